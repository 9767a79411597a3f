// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.nio.ByteBuffer;
import java.util.Arrays;

/**
 * Byte offsets of the C records (pn_types.h) that {@link RecordBuffer}
 * writes and {@link Engine#poll()} decodes, in native byte order. They are
 * pinned by abi/tests/layout_sentinels.c; {@link #verify} checks them against
 * the glue's {@code offsetof} values once, when {@link Engine} loads.
 */
final class RecordLayout {
    private RecordLayout() {}

    /** sizeof(pn_output_t): one poll slot. */
    static final int SLOT_BYTES = 512;
    /** pn_record_header_t. */
    static final int H_SIZE = 0, H_TYPE = 4, H_T_NS = 8, H_SOURCE = 16, H_FLAGS = 20, HEADER_BYTES = 24;
    /** Record type ids (PN_REC_*). */
    static final int REC_IMU = 1, REC_MAG = 2, REC_BARO = 3, REC_GNSS = 4, REC_GAIT_PHASE = 5, REC_STEP = 6,
            REC_ATTITUDE = 7, REC_ATTITUDE_CORRECTION = 8, REC_POSITION = 9, REC_STRIDE = 10;
    /** Input records: sizeof and field offsets. */
    static final int IMU_BYTES = 72, IMU_ACCEL = 24, IMU_GYRO = 48;
    static final int MAG_BYTES = 48, MAG_UT = 24;
    static final int BARO_BYTES = 40, BARO_PRESSURE = 24, BARO_TEMPERATURE = 32;
    static final int GNSS_BYTES = 104, GNSS_LAT = 24, GNSS_LON = 32, GNSS_HEIGHT = 40, GNSS_H_ACC = 48,
            GNSS_V_ACC = 56, GNSS_VEL = 64, GNSS_UTC = 88;
    /** Output records: field offsets. */
    static final int POS_POS = 24, POS_VEL = 48, POS_COV = 72, POS_HEADING = 144, POS_FLOOR = 152, POS_SOURCE = 156,
            POS_PARTICLES = 160, POS_RECOVERIES = 164;
    static final int STRIDE_T_START = 24, STRIDE_DISP = 32, STRIDE_LENGTH = 56, STRIDE_DHEADING = 64, STRIDE_COV = 72,
            STRIDE_CLASS = 144, STRIDE_INDEX = 148;
    static final int STEP_T_START = 24, STEP_P2P = 32, STEP_FREQ = 40, STEP_MAX = 48, STEP_MIN = 56, STEP_MODE = 64;
    static final int ATT_Q = 24, ATT_HEADING = 56, ATT_BIAS = 64, ATT_COV = 88;
    static final int GAIT_STANCE = 24, GAIT_STATISTIC = 32;
    static final int CORR_ROTATION = 24, CORR_BIAS = 48;

    /** The values above in the order of pnj_poll.c's nativeLayout. */
    static final int[] EXPECTED = {SLOT_BYTES, H_SIZE, H_TYPE, H_T_NS, H_SOURCE, H_FLAGS, IMU_BYTES, IMU_ACCEL,
        IMU_GYRO, MAG_BYTES, MAG_UT, BARO_BYTES, BARO_PRESSURE, BARO_TEMPERATURE, GNSS_BYTES, GNSS_LAT, GNSS_LON,
        GNSS_HEIGHT, GNSS_H_ACC, GNSS_V_ACC, GNSS_VEL, GNSS_UTC, POS_POS, POS_VEL, POS_COV, POS_HEADING, POS_FLOOR,
        POS_SOURCE, POS_PARTICLES, POS_RECOVERIES, STRIDE_T_START, STRIDE_DISP, STRIDE_LENGTH, STRIDE_DHEADING,
        STRIDE_COV, STRIDE_CLASS, STRIDE_INDEX, STEP_T_START, STEP_P2P, STEP_FREQ, STEP_MAX, STEP_MIN, STEP_MODE,
        ATT_Q, ATT_HEADING, ATT_BIAS, ATT_COV, GAIT_STANCE, GAIT_STATISTIC, CORR_ROTATION, CORR_BIAS};

    static void verify(int[] nativeLayout) {
        if (!Arrays.equals(EXPECTED, nativeLayout))
            throw new UnsatisfiedLinkError("libpednav_jni's record layout " + Arrays.toString(nativeLayout)
                    + " is not the one org.pednav was built for " + Arrays.toString(EXPECTED));
    }

    /**
     * One polled record in a slot of a poll buffer. Fields past the record's
     * struct_size (a plugin built against an older minor) read as zeros.
     */
    static final class Slot {
        final ByteBuffer b;
        final int at;
        final int size;

        Slot(ByteBuffer b, int at) {
            this.b = b;
            this.at = at;
            this.size = Math.min(b.getInt(at + H_SIZE), SLOT_BYTES);
        }

        int type() {
            return b.getInt(at + H_TYPE);
        }

        long tNs() {
            return b.getLong(at + H_T_NS);
        }

        int sourceId() {
            return b.getInt(at + H_SOURCE);
        }

        int flags() {
            return b.getInt(at + H_FLAGS);
        }

        double f64(int off) {
            return off + 8 <= size ? b.getDouble(at + off) : 0.0;
        }

        long i64(int off) {
            return off + 8 <= size ? b.getLong(at + off) : 0L;
        }

        int i32(int off) {
            return off + 4 <= size ? b.getInt(at + off) : 0;
        }

        double[] f64s(int off, int n) {
            double[] v = new double[n];
            for (int i = 0; i < n; ++i) v[i] = f64(off + 8 * i);
            return v;
        }

        /** The record as its value class, or null for a type this binding does not know. */
        Output decode() {
            switch (type()) {
                case REC_POSITION:
                    return new Position(this);
                case REC_STRIDE:
                    return new Stride(this);
                case REC_STEP:
                    return new Step(this);
                case REC_ATTITUDE:
                    return new Attitude(this);
                case REC_GAIT_PHASE:
                    return new GaitPhase(this);
                case REC_ATTITUDE_CORRECTION:
                    return new AttitudeCorrection(this);
                default:
                    return null;
            }
        }
    }
}

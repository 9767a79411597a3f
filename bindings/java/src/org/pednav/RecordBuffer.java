// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import static org.pednav.RecordLayout.*;

import java.nio.BufferOverflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * Input samples laid out as the engine's own records ({@code pn_imu_t},
 * {@code pn_mag_t}, {@code pn_baro_t}, {@code pn_gnss_t}) in a direct
 * {@link ByteBuffer}, so that {@link Engine#push(RecordBuffer)} hands a whole
 * batch to the engine in one JNI call and without copying: the engine reads
 * the samples where they are. Fill it with the put methods (in time order,
 * as for the single-sample pushes), push it, {@link #clear()} it, and fill it
 * again; one buffer serves a whole stream.
 *
 * <p>Not thread-safe: fill and push from one thread (the producer). Units
 * and frames as in {@link Engine}: SI, body frame FLU, time in ns.
 */
public final class RecordBuffer {
    /** Bytes one {@link #putImu} takes. */
    public static final int IMU_RECORD_BYTES = IMU_BYTES;
    /** Bytes one {@link #putMag} takes. */
    public static final int MAG_RECORD_BYTES = MAG_BYTES;
    /** Bytes one {@link #putBaro} takes. */
    public static final int BARO_RECORD_BYTES = BARO_BYTES;
    /** Bytes one {@link #putGnss} takes. */
    public static final int GNSS_RECORD_BYTES = GNSS_BYTES;

    private final ByteBuffer buffer;
    private int sizeBytes;
    private int count;
    private boolean imuOnly = true;

    /**
     * An empty buffer of {@code capacityBytes} bytes (e.g. 1000 *
     * {@link #IMU_RECORD_BYTES} for 1000 IMU samples), allocated off the Java
     * heap, 8-byte aligned, in native byte order.
     */
    public RecordBuffer(int capacityBytes) {
        if (capacityBytes < 0) throw new IllegalArgumentException("capacityBytes must not be negative: " + capacityBytes);
        int rounded = (capacityBytes + 7) & ~7;
        ByteBuffer raw = ByteBuffer.allocateDirect(rounded + 8);
        buffer = raw.alignedSlice(8).order(ByteOrder.nativeOrder());
        buffer.limit(rounded);
    }

    /** Records in the buffer. */
    public int size() {
        return count;
    }

    /** Bytes the records take. */
    public int sizeBytes() {
        return sizeBytes;
    }

    /** Bytes still free. */
    public int remainingBytes() {
        return buffer.limit() - sizeBytes;
    }

    /** Empties the buffer (the memory stays allocated). */
    public void clear() {
        sizeBytes = 0;
        count = 0;
        imuOnly = true;
    }

    /**
     * Appends an IMU sample: specific force (m/s^2) and angular rate (rad/s),
     * body frame FLU.
     *
     * @throws BufferOverflowException when fewer than {@link #IMU_RECORD_BYTES} bytes are free
     */
    public RecordBuffer putImu(long tNs, double axMps2, double ayMps2, double azMps2, double gxRadps,
            double gyRadps, double gzRadps) {
        int at = header(IMU_BYTES, REC_IMU, tNs);
        buffer.putDouble(at + IMU_ACCEL, axMps2);
        buffer.putDouble(at + IMU_ACCEL + 8, ayMps2);
        buffer.putDouble(at + IMU_ACCEL + 16, azMps2);
        buffer.putDouble(at + IMU_GYRO, gxRadps);
        buffer.putDouble(at + IMU_GYRO + 8, gyRadps);
        buffer.putDouble(at + IMU_GYRO + 16, gzRadps);
        return this;
    }

    /** Appends a magnetometer sample in microtesla, body frame. */
    public RecordBuffer putMag(long tNs, double mxUt, double myUt, double mzUt) {
        int at = header(MAG_BYTES, REC_MAG, tNs);
        buffer.putDouble(at + MAG_UT, mxUt);
        buffer.putDouble(at + MAG_UT + 8, myUt);
        buffer.putDouble(at + MAG_UT + 16, mzUt);
        imuOnly = false;
        return this;
    }

    /** Appends a barometer sample: static pressure (Pa), temperature (deg C, NaN when unknown). */
    public RecordBuffer putBaro(long tNs, double pressurePa, double temperatureC) {
        int at = header(BARO_BYTES, REC_BARO, tNs);
        buffer.putDouble(at + BARO_PRESSURE, pressurePa);
        buffer.putDouble(at + BARO_TEMPERATURE, temperatureC);
        imuOnly = false;
        return this;
    }

    /**
     * Appends a satellite fix (WGS-84; ellipsoidal height; 1-sigma accuracies
     * in m) without velocity or UTC.
     */
    public RecordBuffer putGnss(long tNs, double latDeg, double lonDeg, double heightM, double hAccuracyM,
            double vAccuracyM) {
        int at = header(GNSS_BYTES, REC_GNSS, tNs);
        buffer.putDouble(at + GNSS_LAT, latDeg);
        buffer.putDouble(at + GNSS_LON, lonDeg);
        buffer.putDouble(at + GNSS_HEIGHT, heightM);
        buffer.putDouble(at + GNSS_H_ACC, hAccuracyM);
        buffer.putDouble(at + GNSS_V_ACC, vAccuracyM);
        imuOnly = false;
        return this;
    }

    /** Writes a zeroed record's header; returns its offset. */
    private int header(int bytes, int type, long tNs) {
        if (remainingBytes() < bytes) throw new BufferOverflowException();
        int at = sizeBytes;
        for (int i = 0; i < bytes; i += 8) buffer.putLong(at + i, 0L);
        buffer.putInt(at + H_SIZE, bytes);
        buffer.putInt(at + H_TYPE, type);
        buffer.putLong(at + H_T_NS, tNs);
        sizeBytes += bytes;
        ++count;
        return at;
    }

    ByteBuffer buffer() {
        return buffer;
    }

    boolean imuOnly() {
        return imuOnly;
    }
}

// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * One output record polled from an engine: a {@link Position}, a
 * {@link Stride} or a {@link Step}, and when the output mask asks for them an
 * {@link Attitude}, a {@link GaitPhase} or an {@link AttitudeCorrection}.
 * Immutable.
 */
public abstract class Output {
    /** {@link Engine#setOutputMask} bit of {@link Position} ({@code PN_REC_MASK(PN_REC_POSITION)}). */
    public static final long MASK_POSITION = 1L << RecordLayout.REC_POSITION;
    /** {@link Engine#setOutputMask} bit of {@link Stride}. */
    public static final long MASK_STRIDE = 1L << RecordLayout.REC_STRIDE;
    /** {@link Engine#setOutputMask} bit of {@link Step}. */
    public static final long MASK_STEP = 1L << RecordLayout.REC_STEP;
    /** {@link Engine#setOutputMask} bit of {@link Attitude} (one per IMU sample). */
    public static final long MASK_ATTITUDE = 1L << RecordLayout.REC_ATTITUDE;
    /** {@link Engine#setOutputMask} bit of {@link GaitPhase} (one per IMU sample). */
    public static final long MASK_GAIT_PHASE = 1L << RecordLayout.REC_GAIT_PHASE;
    /** {@link Engine#setOutputMask} bit of {@link AttitudeCorrection}. */
    public static final long MASK_ATTITUDE_CORRECTION = 1L << RecordLayout.REC_ATTITUDE_CORRECTION;
    /** The engine's mask after create: positions, strides and steps. */
    public static final long MASK_DEFAULT = MASK_POSITION | MASK_STRIDE | MASK_STEP;

    private final long tNs;
    private final int sourceId;
    private final int flags;

    Output(RecordLayout.Slot s) {
        this.tNs = s.tNs();
        this.sourceId = s.sourceId();
        this.flags = s.flags();
    }

    /** The time the record describes, on the clock of the pushed samples (ns). */
    public final long tNs() {
        return tNs;
    }

    /** The engine's index of the producing stage + 1 (0 would be an app input). */
    public final int sourceId() {
        return sourceId;
    }

    /** The record's {@code PN_*_FLAG_*} bits. */
    public final int flags() {
        return flags;
    }

    boolean sameHeader(Output o) {
        return tNs == o.tNs && sourceId == o.sourceId && flags == o.flags;
    }

    int headerHash() {
        return (Long.hashCode(tNs) * 31 + sourceId) * 31 + flags;
    }

    /** Bit-exact comparison of doubles (NaN equals NaN, 0.0 differs from -0.0). */
    static boolean same(double a, double b) {
        return Double.doubleToLongBits(a) == Double.doubleToLongBits(b);
    }
}

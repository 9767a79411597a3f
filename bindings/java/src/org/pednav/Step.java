// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * A step found by a step detector ({@code pn_step_t}); {@link #tNs()} is the
 * step's instant (peak or heel strike). Immutable.
 */
public final class Step extends Output {
    private final long tStartNs;
    private final double accelPeakToPeakMps2;
    private final double frequencyHz;

    /** {@code PN_STEP_MODE_*} values of {@link #motionMode()}. */
    public static final int MODE_UNKNOWN = 0, MODE_STRAIGHT = 1, MODE_TURNING = 2, MODE_UPSTAIRS = 3,
            MODE_DOWNSTAIRS = 4, MODE_STATIC = 5;

    private final double accelMaxMps2;
    private final double accelMinMps2;
    private final int motionMode;

    /** From a polled pn_step_t. */
    Step(RecordLayout.Slot s) {
        super(s);
        tStartNs = s.i64(RecordLayout.STEP_T_START);
        accelPeakToPeakMps2 = s.f64(RecordLayout.STEP_P2P);
        frequencyHz = s.f64(RecordLayout.STEP_FREQ);
        accelMaxMps2 = s.f64(RecordLayout.STEP_MAX);
        accelMinMps2 = s.f64(RecordLayout.STEP_MIN);
        motionMode = s.i32(RecordLayout.STEP_MODE);
    }

    /** Start of the step interval (ns). */
    public long tStartNs() {
        return tStartNs;
    }

    /** Filtered vertical acceleration range within the step (m/s^2). */
    public double accelPeakToPeakMps2() {
        return accelPeakToPeakMps2;
    }

    /** 1 / step period (Hz), 0 when unknown. */
    public double frequencyHz() {
        return frequencyHz;
    }

    /** Largest filtered acceleration within the step (m/s^2; 0 from a detector that does not say). */
    public double accelMaxMps2() {
        return accelMaxMps2;
    }

    /** Smallest filtered acceleration within the step (m/s^2). */
    public double accelMinMps2() {
        return accelMinMps2;
    }

    /** One of the MODE_* constants. */
    public int motionMode() {
        return motionMode;
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof Step)) return false;
        Step s = (Step) o;
        return sameHeader(s) && tStartNs == s.tStartNs && same(accelPeakToPeakMps2, s.accelPeakToPeakMps2)
                && same(frequencyHz, s.frequencyHz) && same(accelMaxMps2, s.accelMaxMps2)
                && same(accelMinMps2, s.accelMinMps2) && motionMode == s.motionMode;
    }

    @Override
    public int hashCode() {
        return (headerHash() * 31 + Long.hashCode(tStartNs)) * 31 + Double.hashCode(frequencyHz);
    }

    @Override
    public String toString() {
        return "Step{t_ns=" + tNs() + ", t_start_ns=" + tStartNs + ", accel_p2p_mps2=" + accelPeakToPeakMps2
                + ", frequency_hz=" + frequencyHz + "}";
    }
}

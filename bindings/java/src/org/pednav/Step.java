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

    /** From the JNI scratch layout (see Engine.poll). */
    Step(long[] l, double[] d) {
        super(l[0], (int) l[1], (int) l[2]);
        tStartNs = l[3];
        accelPeakToPeakMps2 = d[0];
        frequencyHz = d[1];
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

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof Step)) return false;
        Step s = (Step) o;
        return sameHeader(s) && tStartNs == s.tStartNs && same(accelPeakToPeakMps2, s.accelPeakToPeakMps2)
                && same(frequencyHz, s.frequencyHz);
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

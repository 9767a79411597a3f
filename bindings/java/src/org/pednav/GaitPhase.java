// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * Per-sample stance or swing decision of a foot stance detector
 * ({@code pn_gait_phase_t}); {@link #tNs()} is the time of the IMU sample it
 * classifies. Polled only when the output mask has
 * {@link Output#MASK_GAIT_PHASE}. Immutable.
 */
public final class GaitPhase extends Output {
    private final boolean stance;
    private final double statistic;

    /** From a polled pn_gait_phase_t. */
    GaitPhase(RecordLayout.Slot s) {
        super(s);
        stance = s.i32(RecordLayout.GAIT_STANCE) != 0;
        statistic = s.f64(RecordLayout.GAIT_STATISTIC);
    }

    /** True when the foot is still on the ground (zero velocity), false when it moves. */
    public boolean stance() {
        return stance;
    }

    /** The detector's test statistic (its own units, for plots and tuning). */
    public double statistic() {
        return statistic;
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof GaitPhase)) return false;
        GaitPhase g = (GaitPhase) o;
        return sameHeader(g) && stance == g.stance && same(statistic, g.statistic);
    }

    @Override
    public int hashCode() {
        return (headerHash() * 31 + Boolean.hashCode(stance)) * 31 + Double.hashCode(statistic);
    }

    @Override
    public String toString() {
        return "GaitPhase{t_ns=" + tNs() + ", stance=" + stance + ", statistic=" + statistic + "}";
    }
}

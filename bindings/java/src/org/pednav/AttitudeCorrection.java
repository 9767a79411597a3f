// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.util.Arrays;

/**
 * Feedback from a position filter to the attitude estimator
 * ({@code pn_attitude_correction_t}): the small ENU rotation and gyroscope
 * bias change applied after {@link #tNs()}. Polled only when the output mask
 * has {@link Output#MASK_ATTITUDE_CORRECTION}. Immutable; array getters
 * return copies.
 */
public final class AttitudeCorrection extends Output {
    private final double[] rotationEnuRad;
    private final double[] gyroBiasDeltaRadps;

    /** From a polled pn_attitude_correction_t. */
    AttitudeCorrection(RecordLayout.Slot s) {
        super(s);
        rotationEnuRad = s.f64s(RecordLayout.CORR_ROTATION, 3);
        gyroBiasDeltaRadps = s.f64s(RecordLayout.CORR_BIAS, 3);
    }

    /** Rotation vector in ENU, radians: q_new = exp(rotation) * q_old (a copy). */
    public double[] rotationEnuRad() {
        return rotationEnuRad.clone();
    }

    /** Change of the gyroscope bias, body frame, rad/s (a copy). */
    public double[] gyroBiasDeltaRadps() {
        return gyroBiasDeltaRadps.clone();
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof AttitudeCorrection)) return false;
        AttitudeCorrection c = (AttitudeCorrection) o;
        return sameHeader(c) && Arrays.equals(rotationEnuRad, c.rotationEnuRad)
                && Arrays.equals(gyroBiasDeltaRadps, c.gyroBiasDeltaRadps);
    }

    @Override
    public int hashCode() {
        return (headerHash() * 31 + Arrays.hashCode(rotationEnuRad)) * 31 + Arrays.hashCode(gyroBiasDeltaRadps);
    }

    @Override
    public String toString() {
        return "AttitudeCorrection{t_ns=" + tNs() + ", rotation_enu_rad=" + Arrays.toString(rotationEnuRad) + "}";
    }
}

// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.util.Arrays;

/**
 * Body attitude from the attitude estimator ({@code pn_attitude_t}), one per
 * IMU sample; polled only when the output mask has {@link Output#MASK_ATTITUDE}.
 * Immutable; array getters return copies.
 */
public final class Attitude extends Output {
    /** {@code PN_ATTITUDE_FLAG_MAG_USED}: the magnetometer corrected this attitude. */
    public static final int FLAG_MAG_USED = 1;

    private final double[] qEnuFromBody;
    private final double headingRad;
    private final double[] gyroBiasRadps;
    private final double[] covAttitudeRad2;

    /** From a polled pn_attitude_t. */
    Attitude(RecordLayout.Slot s) {
        super(s);
        qEnuFromBody = s.f64s(RecordLayout.ATT_Q, 4);
        headingRad = s.f64(RecordLayout.ATT_HEADING);
        gyroBiasRadps = s.f64s(RecordLayout.ATT_BIAS, 3);
        covAttitudeRad2 = s.f64s(RecordLayout.ATT_COV, 9);
    }

    /** Unit quaternion rotating body (FLU) vectors into ENU: w, x, y, z (a copy). */
    public double[] qEnuFromBody() {
        return qEnuFromBody.clone();
    }

    /** Heading of the body x axis projected level, radians clockwise from north. */
    public double headingRad() {
        return headingRad;
    }

    /** Current gyroscope bias estimate, body frame, rad/s (a copy). */
    public double[] gyroBiasRadps() {
        return gyroBiasRadps.clone();
    }

    /** Small-angle attitude error covariance in ENU, rad^2, row-major 3x3 (a copy; zeros when unknown). */
    public double[] covAttitudeRad2() {
        return covAttitudeRad2.clone();
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof Attitude)) return false;
        Attitude a = (Attitude) o;
        return sameHeader(a) && Arrays.equals(qEnuFromBody, a.qEnuFromBody) && same(headingRad, a.headingRad)
                && Arrays.equals(gyroBiasRadps, a.gyroBiasRadps) && Arrays.equals(covAttitudeRad2, a.covAttitudeRad2);
    }

    @Override
    public int hashCode() {
        return (headerHash() * 31 + Arrays.hashCode(qEnuFromBody)) * 31 + Double.hashCode(headingRad);
    }

    @Override
    public String toString() {
        return "Attitude{t_ns=" + tNs() + ", q_enu_from_body=" + Arrays.toString(qEnuFromBody) + ", heading_rad="
                + headingRad + "}";
    }
}

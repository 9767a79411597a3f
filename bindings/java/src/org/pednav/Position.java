// SPDX-License-Identifier: Apache-2.0
package org.pednav;

import java.util.Arrays;

/**
 * A position estimate ({@code pn_position_t}): ENU metres from the start
 * point, its 3x3 covariance (row-major), heading clockwise from north, and
 * the floor when a map matcher or barometer stage knows it. Immutable; array
 * getters return copies.
 */
public final class Position extends Output {
    /** {@code PN_POSITION_FLAG_HAS_VELOCITY}. */
    public static final int FLAG_HAS_VELOCITY = 1;
    /** {@code PN_POSITION_FLAG_HAS_FLOOR}. */
    public static final int FLAG_HAS_FLOOR = 2;
    /** {@code PN_POSITION_FLAG_HAS_PARTICLES}: {@link #liveParticles()} is set. */
    public static final int FLAG_HAS_PARTICLES = 4;
    /** {@code PN_POSITION_FLAG_RECOVERED}: the estimator restarted since its previous output. */
    public static final int FLAG_RECOVERED = 8;
    /** {@code PN_POSITION_SOURCE_*}. */
    public static final int SOURCE_INERTIAL = 0, SOURCE_FUSED = 1, SOURCE_GNSS = 2, SOURCE_MAP = 3;

    private final double[] posEnuM;
    private final double[] velEnuMps;
    private final double[] covEnuM2;
    private final double headingRad;
    private final int floor;
    private final int source;
    private final int liveParticles;
    private final int recoveries;

    /** From a polled pn_position_t. */
    Position(RecordLayout.Slot s) {
        super(s);
        posEnuM = s.f64s(RecordLayout.POS_POS, 3);
        velEnuMps = s.f64s(RecordLayout.POS_VEL, 3);
        covEnuM2 = s.f64s(RecordLayout.POS_COV, 9);
        headingRad = s.f64(RecordLayout.POS_HEADING);
        floor = s.i32(RecordLayout.POS_FLOOR);
        source = s.i32(RecordLayout.POS_SOURCE);
        liveParticles = s.i32(RecordLayout.POS_PARTICLES);
        recoveries = s.i32(RecordLayout.POS_RECOVERIES);
    }

    /** East, north, up in metres from the start point (a copy). */
    public double[] posEnuM() {
        return posEnuM.clone();
    }

    /** East in metres from the start point. */
    public double east() {
        return posEnuM[0];
    }

    /** North in metres from the start point. */
    public double north() {
        return posEnuM[1];
    }

    /** Up in metres from the start point. */
    public double up() {
        return posEnuM[2];
    }

    /** Position covariance in m^2, row-major 3x3 (a copy). */
    public double[] covEnuM2() {
        return covEnuM2.clone();
    }

    /** One covariance entry, row and column in 0..2 (east, north, up). */
    public double cov(int row, int col) {
        if (row < 0 || row > 2 || col < 0 || col > 2) throw new IndexOutOfBoundsException("row and col are 0..2");
        return covEnuM2[3 * row + col];
    }

    /** Velocity ENU in m/s (a copy); zeros unless {@link #hasVelocity()}. */
    public double[] velEnuMps() {
        return velEnuMps.clone();
    }

    /** Whether {@link #velEnuMps()} is set. */
    public boolean hasVelocity() {
        return (flags() & FLAG_HAS_VELOCITY) != 0;
    }

    /** Heading in radians, clockwise from north. */
    public double headingRad() {
        return headingRad;
    }

    /** Whether {@link #floor()} is known. */
    public boolean hasFloor() {
        return (flags() & FLAG_HAS_FLOOR) != 0;
    }

    /** Floor relative to the start floor (0); meaningful when {@link #hasFloor()}. */
    public int floor() {
        return floor;
    }

    /** One of the SOURCE_* constants. */
    public int source() {
        return source;
    }

    /** Particles alive in a particle filter's estimate; meaningful when {@code FLAG_HAS_PARTICLES} is set. */
    public int liveParticles() {
        return liveParticles;
    }

    /** Times the estimator restarted since the last reset. */
    public int recoveries() {
        return recoveries;
    }

    /** Bit-exact equality of every field. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof Position)) return false;
        Position p = (Position) o;
        return sameHeader(p) && Arrays.equals(posEnuM, p.posEnuM) && Arrays.equals(velEnuMps, p.velEnuMps)
                && Arrays.equals(covEnuM2, p.covEnuM2) && same(headingRad, p.headingRad) && floor == p.floor
                && source == p.source && liveParticles == p.liveParticles && recoveries == p.recoveries;
    }

    @Override
    public int hashCode() {
        int h = headerHash();
        h = 31 * h + Arrays.hashCode(posEnuM);
        h = 31 * h + Arrays.hashCode(covEnuM2);
        h = 31 * h + Double.hashCode(headingRad);
        return 31 * h + floor;
    }

    @Override
    public String toString() {
        return "Position{t_ns=" + tNs() + ", pos_enu_m=" + Arrays.toString(posEnuM) + ", cov_enu_m2="
                + Arrays.toString(covEnuM2) + ", heading_rad=" + headingRad
                + (hasFloor() ? ", floor=" + floor : "") + ", source=" + source + "}";
    }
}

// SPDX-License-Identifier: Apache-2.0
package org.pednav;

/**
 * A point on the WGS-84 ellipsoid ({@code pn_geo_point_t}): the engine's
 * geodetic origin is one, the point at ENU (0, 0, 0). Immutable.
 */
public final class GeoPoint {
    private final double latDeg;
    private final double lonDeg;
    private final double heightM;

    /**
     * @param latDeg geodetic latitude in degrees, north positive, [-90, 90]
     * @param lonDeg longitude in degrees, east positive, [-180, 180]
     * @param heightM height above the ellipsoid in metres
     */
    public GeoPoint(double latDeg, double lonDeg, double heightM) {
        this.latDeg = latDeg;
        this.lonDeg = lonDeg;
        this.heightM = heightM;
    }

    /** Geodetic latitude in degrees, north positive. */
    public double latDeg() {
        return latDeg;
    }

    /** Longitude in degrees, east positive. */
    public double lonDeg() {
        return lonDeg;
    }

    /** Height above the WGS-84 ellipsoid in metres. */
    public double heightM() {
        return heightM;
    }

    /** Bit-exact equality of the three values. */
    @Override
    public boolean equals(Object o) {
        if (this == o) return true;
        if (!(o instanceof GeoPoint)) return false;
        GeoPoint g = (GeoPoint) o;
        return Output.same(latDeg, g.latDeg) && Output.same(lonDeg, g.lonDeg) && Output.same(heightM, g.heightM);
    }

    @Override
    public int hashCode() {
        return (Double.hashCode(latDeg) * 31 + Double.hashCode(lonDeg)) * 31 + Double.hashCode(heightM);
    }

    @Override
    public String toString() {
        return "GeoPoint{lat_deg=" + latDeg + ", lon_deg=" + lonDeg + ", height_m=" + heightM + "}";
    }
}

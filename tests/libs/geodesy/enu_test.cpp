// SPDX-License-Identifier: Apache-2.0
// WGS-84 <-> local ENU around an origin.
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_geodesy/enu.hpp>

using namespace pednav::geodesy;

TEST_CASE("geodetic <-> ENU round trip") {
    const GeodeticPoint origin{60.0, 25.0, 30.0};
    const double enu[3] = {1234.5, -987.6, 12.0};
    double lat = 0, lon = 0, h = 0, back[3];
    enu_to_geodetic(origin, enu, &lat, &lon, &h);
    geodetic_to_enu(origin, lat, lon, h, back);
    for (int i = 0; i < 3; ++i) CHECK(back[i] == doctest::Approx(enu[i]).epsilon(1e-9));
    // One degree of latitude is about 111.4 km at 60 degrees.
    geodetic_to_enu(origin, 61.0, 25.0, 30.0, back);
    CHECK(back[1] == doctest::Approx(111412.0).epsilon(0.002));
}

TEST_CASE("ENU across the antimeridian and at the equator") {
    // 0.001 degree east of 179.9995 is -179.9995: 111.3 m east at the equator.
    const GeodeticPoint date_line{0.0, 179.9995, 0.0};
    double enu[3];
    geodetic_to_enu(date_line, 0.0, -179.9995, 0.0, enu);
    CHECK(enu[0] == doctest::Approx(111.319).epsilon(1e-4));  // a = 6378137 m: 111.3195 m per 0.001 deg
    CHECK(std::abs(enu[1]) < 1e-9);
    double lat = 0, lon = 0, h = 0;
    enu_to_geodetic(date_line, enu, &lat, &lon, &h);
    CHECK(lon == doctest::Approx(-179.9995).epsilon(1e-12));
    // Heights are differences from the origin's.
    const GeodeticPoint hill{47.0, 8.0, 400.0};
    geodetic_to_enu(hill, 47.0, 8.0, 412.5, enu);
    CHECK(std::abs(enu[2] - 12.5) < 1e-9);
    CHECK(std::abs(enu[0]) < 1e-9);
    CHECK(std::abs(enu[1]) < 1e-9);
}

TEST_CASE("ENU is the tangent plane at the origin, exactly") {
    // A point 1 km east on the ellipsoid lies below the origin's tangent plane
    // by d^2 / (2 N) with the prime-vertical radius N = 6 388 838 m at 47 N.
    const GeodeticPoint origin{47.0, 8.0, 0.0};
    double lat = 0, lon = 0, h = 0;
    const double east_1km[3] = {1000.0, 0.0, 0.0};
    enu_to_geodetic(origin, east_1km, &lat, &lon, &h);
    CHECK(h == doctest::Approx(1e6 / (2 * 6388838.0)).epsilon(1e-3));  // 7.8 cm above the ellipsoid
    double enu[3];
    geodetic_to_enu(origin, lat, lon, 0.0, enu);
    CHECK(enu[2] == doctest::Approx(-1e6 / (2 * 6388838.0)).epsilon(1e-3));
    // Round trips far from the origin stay exact to the micrometre.
    const double far[3] = {-80000.0, 120000.0, 350.0};
    enu_to_geodetic(origin, far, &lat, &lon, &h);
    geodetic_to_enu(origin, lat, lon, h, enu);
    for (int i = 0; i < 3; ++i) CHECK(std::abs(enu[i] - far[i]) < 1e-6);
}

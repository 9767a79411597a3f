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
    CHECK(enu[2] == 12.5);
    CHECK(enu[0] == 0.0);
    CHECK(enu[1] == 0.0);
}

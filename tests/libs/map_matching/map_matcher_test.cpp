// SPDX-License-Identifier: Apache-2.0
// The map matcher: the output track never crosses a wall, floors from the
// barometer through connectors, altitude zones, and without a map the track
// passes through.
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_geodesy/atmosphere.hpp>
#include <pednav_indoor_map/geometry_2d.hpp>
#include <pednav_map_matching/map_matcher.hpp>

#include "test_maps.hpp"

using namespace pednav;
using namespace pednav::map_matching;

namespace {

TrackPosition track_at(int64_t t_ns, double e, double n, double heading = 0.0) {
    TrackPosition p{};
    p.t_ns = t_ns;
    p.pos_enu_m[0] = e;
    p.pos_enu_m[1] = n;
    p.heading_rad = heading;
    return p;
}

int crossings(const indoor_map::Map& m, const std::vector<indoor_map::Point2>& track, int floor) {
    int n = 0;
    for (size_t i = 1; i < track.size(); ++i)
        for (const auto& w : m.walls)
            if (w.floor == floor && indoor_map::segments_intersect(track[i - 1], track[i], w.a, w.b)) {
                ++n;
                break;
            }
    return n;
}

constexpr int64_t kSecond = 1000000000;

// Pressure at height h above the start (standard atmosphere at sea level).
double pressure_at(double h_m) { return geodesy::standard_pressure_pa(h_m); }

}  // namespace

TEST_CASE("the output track of an L-shaped walk with a 10 deg heading error crosses no wall") {
    const indoor_map::Map m = test::l_corridor_map();
    MapMatcher mm(test::matcher_defaults());
    mm.set_map(m);
    const double bias = -10.0 * M_PI / 180.0;
    double e = 1, n = 1;  // the dead-reckoned track
    std::vector<indoor_map::Point2> raw{{e, n}}, out;
    int64_t t = 0;
    for (int k = 0; k < 50; ++k) {
        const double te = k < 26 ? 0.7 : 0.0, tn = k < 26 ? 0.0 : 0.7;  // the truth's step
        const double de = te * std::cos(bias) + tn * std::sin(bias), dn = tn * std::cos(bias) - te * std::sin(bias);
        for (int j = 1; j <= 10; ++j) {  // positions between steps
            t += kSecond / 20;
            const MatchedPosition p = mm.on_position(track_at(t, e + de * j / 10, n + dn * j / 10));
            out.push_back({p.pos_enu_m[0], p.pos_enu_m[1]});
            CHECK(p.map_matched);
            CHECK(p.live_particles > 0);
        }
        e += de;
        n += dn;
        raw.push_back({e, n});
        mm.on_stride(t, de, dn);
    }
    CHECK(crossings(m, raw, 0) > 0);
    CHECK(crossings(m, out, 0) == 0);
    const indoor_map::Point2 end = out.back();
    CAPTURE(end.e_m);
    CAPTURE(end.n_m);
    CHECK(std::abs(end.e_m - 19.0) < 1.0);  // truth: (19, 17.8)
    CHECK(std::abs(end.n_m - 17.8) < 2.0);
}

TEST_CASE("floors: the barometer climbs a floor on the stairs, the cloud follows; an altitude zone holds the drift") {
    indoor_map::Map m = test::corridor_map(40, 0);
    const indoor_map::Map up = test::corridor_map(40, 1);
    m.walls.insert(m.walls.end(), up.walls.begin(), up.walls.end());
    m.connectors.push_back(test::stairs_area(0, 1, {{30, 0}, {40, 0}, {40, 2}, {30, 2}}));
    m.zones.push_back({indoor_map::ZoneKind::altitude, 1, {{{0, 0}, {10, 0}, {10, 2}, {0, 2}}}, 3.4, 5});
    m.floors = {0, 1};
    m.floor_height_m = 3.4;
    MapMatcherConfig c = test::matcher_defaults();
    MapMatcher mm(c);
    mm.set_map(m);
    int64_t t = 0;
    double e = 1, h = 0;
    std::vector<int> floors;
    auto walk = [&](int steps, double de, double dh_per_step, double drift_m_per_step) {
        for (int k = 0; k < steps; ++k) {
            for (int j = 0; j < 25; ++j) {  // 0.5 s per step, barometer at 50 Hz
                t += kSecond / 50;
                h += dh_per_step / 25;
                mm.on_baro(t, pressure_at(h + drift_m_per_step * k));
                const MatchedPosition p = mm.on_position(track_at(t, e + de * j / 25, 1));
                floors.push_back(p.floor);
            }
            e += de;
            mm.on_stride(t, de, 0);
        }
    };
    walk(20, 0.0, 0.0, 0.0);   // 10 s still: the reference pressure
    walk(40, 0.7, 0.0, 0.0);   // to x = 29 on floor 0
    CHECK(mm.filter().floor() == 0);
    walk(14, 0.7, 3.4 / 14, 0.0);  // up the stairs (x 29 to 39)
    CHECK(mm.filter().floor() == 1);
    CHECK(floors.back() == 1);
    walk(50, -0.7, 0.0, 0.0);  // back west on floor 1 into the altitude zone
    CHECK(mm.filter().floor() == 1);
    // Standing in the zone while the weather moves the pressure by 2 m of
    // altitude: the zone holds the altitude at its height.
    const double before = mm.altimeter().altitude_m();
    walk(40, 0.0, 0.0, 2.0 / 40);
    CHECK(std::abs(before - 3.4) < 0.3);
    CHECK(std::abs(mm.altimeter().altitude_m() - 3.4) < 0.2);
    CHECK(mm.filter().floor() == 1);
    CHECK(mm.filter().recoveries() == 0);
}

TEST_CASE("without a map positions pass through, with the barometer's floor once it has its reference") {
    MapMatcher mm(test::matcher_defaults());
    CHECK_FALSE(mm.has_map());
    int64_t t = 0;
    MatchedPosition p{};
    for (int k = 0; k < 400; ++k) {
        t += kSecond / 50;
        mm.on_baro(t, pressure_at(k < 300 ? 0.0 : 7.0));
        p = mm.on_position(track_at(t, 0.1 * k, -0.05 * k, 1.0));
        if (k == 10) CHECK_FALSE(p.has_floor);
    }
    CHECK(p.has_floor);
    CHECK(p.floor == 2);
    CHECK_FALSE(p.map_matched);
    CHECK(p.pos_enu_m[0] == doctest::Approx(39.9));
    CHECK(p.pos_enu_m[1] == doctest::Approx(-19.95));
    CHECK(p.heading_rad == 1.0);
}

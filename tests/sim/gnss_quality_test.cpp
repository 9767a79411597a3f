// SPDX-License-Identifier: Apache-2.0
// Simulated GNSS reception: quality per segment (good, degraded, none),
// multipath jumps, the gnss_outage route, and the default that keeps the
// existing routes' fixes as they were.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <pednav_geodesy/enu.hpp>
#include <pednav_sim/simulate.hpp>

using namespace pednav::sim;

namespace {

// East-north error of each fix against the truth at its time.
std::vector<double> horizontal_errors(const SimOutput& o, const Route& route) {
    const pednav::geodesy::GeodeticPoint origin{route.origin_lat_deg, route.origin_lon_deg, route.origin_height_m};
    std::vector<double> e;
    for (const pn_gnss_t& g : o.gnss) {
        double enu[3];
        pednav::geodesy::geodetic_to_enu(origin, g.lat_deg, g.lon_deg, g.height_m, enu);
        const size_t k = static_cast<size_t>(std::llround(static_cast<double>(g.header.t_ns) * 1e-9 * o.rate_hz));
        e.push_back(std::hypot(enu[0] - o.truth[k].pos_enu_m[0], enu[1] - o.truth[k].pos_enu_m[1]));
    }
    return e;
}

double rms(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

}  // namespace

TEST_CASE("gnss quality: the default is good outdoors and none indoors, bit for bit") {
    Route explicit_route = builtin_route("outdoor_indoor");
    for (size_t i = 1; i < explicit_route.waypoints.size(); ++i) {
        Waypoint& w = explicit_route.waypoints[i];
        w.gnss = gnss_quality_preset(w.outdoor ? "good" : "none");
        w.gnss_given = true;
    }
    SimOptions o;
    o.mount = "waist";
    const SimOutput a = simulate(builtin_route("outdoor_indoor"), o);
    const SimOutput b = simulate(explicit_route, o);
    REQUIRE(a.gnss.size() == 119);
    REQUIRE(a.gnss.size() == b.gnss.size());
    CHECK(std::memcmp(a.gnss.data(), b.gnss.data(), a.gnss.size() * sizeof(pn_gnss_t)) == 0);
    CHECK(std::memcmp(a.imu.data(), b.imu.data(), a.imu.size() * sizeof(pn_imu_t)) == 0);
    for (const pn_gnss_t& g : a.gnss) {
        CHECK(g.satellites == 12);
        CHECK(g.fix_type == PN_GNSS_FIX_AUTONOMOUS);
    }
}

TEST_CASE("gnss_outage: 440 m outdoors, a 60 s outage in the middle, degraded fixes worse and saying so") {
    const Route route = builtin_route("gnss_outage");
    CHECK(route_length_m(route) == doctest::Approx(440.0));
    for (size_t i = 1; i < route.waypoints.size(); ++i) CHECK(route.waypoints[i].outdoor);
    SimOptions o;
    o.mount = "waist";
    const SimOutput out = simulate(route, o);
    CHECK(out.distance_m == doctest::Approx(440.0).epsilon(0.01));
    REQUIRE(out.gnss.size() > 250);
    // The longest interval between fixes: the outage, 60 s give or take the 1 s fix period.
    double gap = 0, gap_start = 0;
    for (size_t i = 1; i < out.gnss.size(); ++i) {
        const double dt = static_cast<double>(out.gnss[i].header.t_ns - out.gnss[i - 1].header.t_ns) * 1e-9;
        if (dt > gap) gap = dt, gap_start = static_cast<double>(out.gnss[i - 1].header.t_ns) * 1e-9;
    }
    CHECK(gap >= 59.0);
    CHECK(gap <= 62.0);
    const double walk_s = out.truth.back().t_s;
    CHECK(gap_start > 0.3 * walk_s);  // in the middle of the walk
    CHECK(gap_start + gap < 0.8 * walk_s);
    // Good fixes: 12 satellites, 2.24 m reported; degraded: 6 satellites, four times that.
    std::vector<pn_gnss_t> good, degraded;
    for (const pn_gnss_t& g : out.gnss) (g.satellites == 12 ? good : degraded).push_back(g);
    REQUIRE(good.size() > 100);
    REQUIRE(degraded.size() > 80);
    for (const pn_gnss_t& g : degraded) {
        CHECK(g.satellites == 6);
        CHECK(g.h_accuracy_m == doctest::Approx(4.0 * good.front().h_accuracy_m));
    }
    SimOutput only_good = out, only_degraded = out;
    only_good.gnss = good;
    only_degraded.gnss = degraded;
    const double rms_good = rms(horizontal_errors(only_good, route));
    const double rms_degraded = rms(horizontal_errors(only_degraded, route));
    MESSAGE("horizontal rms error: good " << rms_good << " m, degraded " << rms_degraded << " m");
    CHECK(rms_good < good.front().h_accuracy_m * 1.5);
    CHECK(rms_degraded > 2.0 * rms_good);
}

TEST_CASE("multipath: fixes within a jump are off by its offset, the others and the accuracy unchanged") {
    const Route route = builtin_route("outdoor_indoor");
    SimOptions o;
    const SimOutput clean = simulate(route, o);
    GnssJump jump;
    jump.t_s = 30.0;
    jump.duration_s = 3.0;
    jump.offset_enu_m[0] = 50.0;
    o.gnss_jumps.push_back(jump);
    const SimOutput jumped = simulate(route, o);
    REQUIRE(clean.gnss.size() == jumped.gnss.size());
    CHECK(std::memcmp(clean.imu.data(), jumped.imu.data(), clean.imu.size() * sizeof(pn_imu_t)) == 0);
    const pednav::geodesy::GeodeticPoint origin{route.origin_lat_deg, route.origin_lon_deg, route.origin_height_m};
    size_t off = 0;
    for (size_t i = 0; i < clean.gnss.size(); ++i) {
        const pn_gnss_t &a = clean.gnss[i], &b = jumped.gnss[i];
        CHECK(a.h_accuracy_m == b.h_accuracy_m);
        double ea[3], eb[3];
        pednav::geodesy::geodetic_to_enu(origin, a.lat_deg, a.lon_deg, a.height_m, ea);
        pednav::geodesy::geodetic_to_enu(origin, b.lat_deg, b.lon_deg, b.height_m, eb);
        const double t = static_cast<double>(a.header.t_ns) * 1e-9;
        if (t >= 30.0 && t < 33.0) {
            ++off;
            CHECK(eb[0] - ea[0] == doctest::Approx(50.0).epsilon(1e-6));
            CHECK(std::fabs(eb[1] - ea[1]) < 1e-6);
        } else {
            CHECK(std::memcmp(&a, &b, sizeof a) == 0);
        }
    }
    CHECK(off == 3);
}

TEST_CASE("gnss in routes: presets and objects per waypoint, jumps, round trip, errors by pointer") {
    const nlohmann::json doc = {
        {"format", "pednav-route/1"},
        {"waypoints",
         {{0, 0, 0},
          {{"enu_m", {30, 0, 0}}, {"outdoor", true}, {"gnss", "degraded"}},
          {{"enu_m", {30, 30, 0}}, {"gnss", {{"error_scale", 2.5}, {"satellites", 8}}}},
          {{"enu_m", {0, 30, 0}}, {"outdoor", true}, {"gnss", "none"}}}},
        {"gnss_jumps", {{{"t_s", 12}, {"duration_s", 4}, {"offset_enu_m", {0, 40, 0}}}}}};
    const Route r = parse_route(doc);
    CHECK(segment_gnss(r, 0).name == "degraded");
    CHECK(segment_gnss(r, 0).error_scale == 4.0);
    CHECK(segment_gnss(r, 1).name == "custom");
    CHECK(segment_gnss(r, 1).error_scale == 2.5);
    CHECK(segment_gnss(r, 1).satellites == 8);
    CHECK(segment_gnss(r, 1).fixes);  // indoors by `outdoor`, with reception given
    CHECK_FALSE(segment_gnss(r, 2).fixes);
    REQUIRE(r.gnss_jumps.size() == 1);
    CHECK(r.gnss_jumps[0].offset_enu_m[1] == 40.0);
    CHECK(route_to_json(parse_route(route_to_json(r))) == route_to_json(r));
    // A route without GNSS keys writes none (route.json of the existing routes unchanged).
    const nlohmann::json plain = route_to_json(builtin_route("outdoor_indoor"));
    CHECK_FALSE(plain.contains("gnss_jumps"));
    CHECK_FALSE(plain["waypoints"][1].contains("gnss"));

    auto error_of = [](nlohmann::json j) {
        try {
            parse_route(j);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    nlohmann::json bad = doc;
    bad["waypoints"][1]["gnss"] = "foggy";
    CHECK(error_of(bad).find("/waypoints/1/gnss") != std::string::npos);
    bad = doc;
    bad["waypoints"][2]["gnss"]["error_scale"] = 0;
    CHECK(error_of(bad).find("/waypoints/2/gnss/error_scale") != std::string::npos);
    bad = doc;
    bad["gnss_jumps"][0].erase("duration_s");
    CHECK(error_of(bad).find("/gnss_jumps/0/duration_s: missing") != std::string::npos);
}

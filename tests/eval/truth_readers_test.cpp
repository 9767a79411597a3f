// SPDX-License-Identifier: Apache-2.0
// The truth readers on the shared recordings (numbers from each SOURCE.md) and on simulated walks.
#include <filesystem>
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_sim/simulate.hpp>

#include "test_dir.hpp"

using namespace pednav::eval;

namespace {
const std::string kData = PEDNAV_SHARED_DATA_DIR;
}

TEST_CASE("koroglu footprints: stride counts and path lengths of SOURCE.md") {
    struct Walk {
        int n, strides;
        double path_m;
    } walks[] = {{33, 47, 64.2}, {35, 28, 55.5}, {39, 80, 98.3}, {42, 102, 130.9}, {44, 65, 106.2}};
    for (const Walk& w : walks) {
        CAPTURE(w.n);
        const Truth t =
            read_truth(kData + "/koroglu-foot-gcp/SensorConnectData_" + std::to_string(w.n) + "_gcp.csv");
        CHECK(t.kind == TruthKind::footprints);
        CHECK(t.step_count == w.strides);
        CHECK(t.points.size() == static_cast<size_t>(w.strides + 1));
        CHECK(t.distance_m == doctest::Approx(w.path_m).epsilon(0.002));
        CHECK(t.points.front().x_m == 0.0);
    }
    const Truth t33 = read_koroglu_gcp(kData + "/koroglu-foot-gcp/SensorConnectData_33_gcp.csv");
    CHECK(t33.points[1].t_s == doctest::Approx(2.639945));
    CHECK(t33.points[2].x_m == doctest::Approx(2.1970));
}

TEST_CASE("humolire landmarks: counts, reference times, start, map walls") {
    struct Walk {
        const char* dir;
        size_t marks;
        double polyline_m;
    } walks[] = {{"user1_straight", 28, 219.0},
                 {"user1_8_shape", 8, 113.5},
                 {"user1_square_2x", 8, 120.8},
                 {"user3_forward", 16, 238.9}};
    for (const Walk& w : walks) {
        CAPTURE(w.dir);
        const Truth t = read_truth(kData + "/humolire-phone/" + w.dir);
        CHECK(t.kind == TruthKind::landmarks);
        CHECK(t.points.size() == w.marks);
        CHECK(t.walls.size() == 396);
        CHECK(t.distance_m == doctest::Approx(w.polyline_m).epsilon(0.01));
    }
    const Truth t = read_humolire(kData + "/humolire-phone/user1_8_shape");
    CHECK(t.start_x_m == doctest::Approx(7.147));
    CHECK(t.points[0].t_s == doctest::Approx(11.156));
    CHECK(t.points[7].x_m == doctest::Approx(7.147));
    CHECK(t.start_heading_deg == doctest::Approx(90.0));  // along the map's x axis
    CHECK(t.walls[0].points_m[0][0] == doctest::Approx(0.04 * 3.97265625));
    // y up from the image's bottom edge (915 pixels down), as the keypoints.
    CHECK(t.walls[0].points_m[0][1] == doctest::Approx(0.04 * (915.0 - 3.630468750000002)).epsilon(1e-6));
}

TEST_CASE("ipol step annotations: footsteps within the trial and the two 10 m legs") {
    const Truth t = read_truth(kData + "/ipol-gait-waist-feet/1-1.json");
    CHECK(t.kind == TruthKind::step_events);
    CHECK(t.step_count == 35);  // 17 left + 18 right
    REQUIRE(t.legs.size() == 2);
    CHECK(t.legs[0].t0_s == doctest::Approx(4.59));
    CHECK(t.legs[0].t1_s == doctest::Approx(13.16));
    CHECK(t.legs[1].t0_s == doctest::Approx(14.74));
    CHECK(t.legs[1].length_m == 10.0);
    // 10-1 has "Height": NaN (Python's JSON), read all the same.
    CHECK(read_ipol_steps(kData + "/ipol-gait-waist-feet/10-1.json").step_count == 33);
    // 5-2 annotates 21 + 19 footsteps, six of them after the end of the trial.
    CHECK(read_ipol_steps(kData + "/ipol-gait-waist-feet/5-2.json").step_count == 34);
    CHECK(read_ipol_steps(kData + "/ipol-gait-waist-feet/1-1.json", 100.0, 10.0, "left").step_count == 17);
    CHECK(read_ipol_steps(kData + "/ipol-gait-waist-feet/1-1.json", 100.0, 10.0, "right").step_count == 18);
    // The whole recording's footsteps: 5-2's six after the trial counted too, the legs the same.
    const std::string five_two = kData + "/ipol-gait-waist-feet/5-2.json";
    CHECK(read_ipol_steps(five_two, 100.0, 10.0, "left", true).step_count == 21);
    CHECK(read_ipol_steps(five_two, 100.0, 10.0, "right", true).step_count == 19);
    CHECK(read_ipol_steps(five_two, 100.0, 10.0, "both", true).step_count == 40);
    CHECK(read_ipol_steps(five_two, 100.0, 10.0, "left", true).legs[1].t1_s ==
          read_ipol_steps(five_two).legs[1].t1_s);
}

TEST_CASE("IPIN POSI lines: metres from the first point, floors") {
    const std::string path = "eval_test_ipin.txt";
    {
        std::ofstream f(path);
        f << "% comment\nACCE;0.01;0.02;0.1;0.2;9.8;3\n"
             "POSI;1.0;1;40.3135;-3.4838;0;0\n"
             "POSI;11.0;2;40.3136;-3.4838;1;0\n";
    }
    const Truth t = read_truth(path);
    std::remove(path.c_str());
    REQUIRE(t.points.size() == 2);
    CHECK(t.kind == TruthKind::ipin_posi);
    CHECK(t.points[1].y_m == doctest::Approx(11.10).epsilon(0.003));  // 1e-4 deg of latitude
    CHECK(t.points[1].x_m == doctest::Approx(0.0));
    CHECK(t.points[1].floor == 1);
    CHECK(t.points[1].t_s == 11.0);
}

TEST_CASE("simulated truth: read back from pednav sim's files, scores a perfect track at zero") {
    using namespace pednav::sim;
    SimOptions o;
    o.sensor_errors = false;
    const Route route = builtin_route("stairs");
    const SimOutput out = simulate(route, o);
    const std::string dir = pednav::eval_test::test_dir() + "/sim_stairs";
    write_outputs(out, route, dir);
    const Truth t = read_truth(dir);
    CHECK(t.kind == TruthKind::simulated);
    CHECK(t.step_count == static_cast<int>(out.step_times_s.size()));
    CHECK(t.closed_loop);
    CHECK(t.walls.size() == route.walls.size());
    CHECK(t.points.size() == doctest::Approx(out.truth.back().t_s / 0.1).epsilon(0.01));
    // The truth as a track: zero error everywhere, loop closed.
    Track tr;
    for (const TruthSample& s : out.truth) {
        TrackSample ts;
        ts.t_s = s.t_s;
        for (int i = 0; i < 3; ++i) ts.pos_m[i] = s.pos_enu_m[i];
        ts.heading_deg = s.heading_deg;
        ts.floor = s.floor;
        ts.has_floor = true;
        tr.samples.push_back(ts);
    }
    const Metrics m = evaluate(tr, t);
    CHECK(m.horizontal_m.max < 1e-5);
    CHECK(std::fabs(m.height_error_mean_m) < 1e-5);
    CHECK(m.floor_correct_pct == 100.0);
    CHECK(m.loop_closure_m < 1e-5);
    CHECK(m.heading_error_deg.max < 1e-3);
    CHECK(m.truth_distance_m == doctest::Approx(out.distance_m).epsilon(0.02));
    // pednav report builds the truth from the walk in memory: the same points.
    const Truth direct = sim_truth(out, route);
    REQUIRE(direct.points.size() == t.points.size());
    for (size_t i = 0; i < t.points.size(); ++i) {
        const TruthPoint &a = direct.points[i], &b = t.points[i];
        CAPTURE(i);
        CHECK(a.t_s == doctest::Approx(b.t_s).epsilon(1e-9));
        CHECK(std::fabs(a.x_m - b.x_m) < 1e-5);
        CHECK(std::fabs(a.y_m - b.y_m) < 1e-5);
        CHECK(std::fabs(a.z_m - b.z_m) < 1e-5);
        CHECK(std::fabs(a.heading_deg - b.heading_deg) < 1e-3);
        CHECK(a.floor == b.floor);
    }
    CHECK(t.points.back().t_s == doctest::Approx(out.truth.back().t_s));
    REQUIRE(direct.step_times_s.size() == t.step_times_s.size());
    // truth.csv flags the first sample at or after each step: within one sample.
    for (size_t i = 0; i < t.step_times_s.size(); ++i) {
        CHECK(t.step_times_s[i] >= direct.step_times_s[i] - 1e-9);
        CHECK(t.step_times_s[i] - direct.step_times_s[i] < 1.0 / out.rate_hz + 1e-9);
    }
    CHECK(direct.walls.size() == t.walls.size());
    CHECK(direct.closed_loop == t.closed_loop);
    CHECK(direct.loop_length_m == doctest::Approx(t.loop_length_m).epsilon(1e-6));
}

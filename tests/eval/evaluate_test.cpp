// SPDX-License-Identifier: Apache-2.0
// evaluate() on tracks whose errors are known by construction.
#include <doctest/doctest.h>

#include <cstdio>
#include <fstream>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth_readers.hpp>

using namespace pednav::eval;

namespace {

Track line_track(double rot_deg, double ox, double oy, double dy_per_m = 0.0) {
    Track tr;
    const double th = rot_deg * M_PI / 180.0;
    for (int k = 0; k <= 100; ++k) {
        TrackSample s;
        s.t_s = k * 0.1;
        const double x = k * 0.1, y = dy_per_m * x;  // 1 m/s east
        s.pos_m[0] = ox + std::cos(th) * x - std::sin(th) * y;
        s.pos_m[1] = oy + std::sin(th) * x + std::cos(th) * y;
        s.heading_deg = 90.0 - rot_deg;
        tr.samples.push_back(s);
    }
    return tr;
}

Truth line_truth() {
    Truth t;
    t.kind = TruthKind::footprints;
    for (int k = 0; k <= 10; ++k) {
        TruthPoint p;
        p.t_s = k;
        p.x_m = k;
        p.y_m = 0.0;
        p.heading_deg = 90.0;
        t.points.push_back(p);
    }
    return t;
}

}  // namespace

TEST_CASE("evaluate without alignment: a constant offset shows as the error") {
    const Metrics m = evaluate(line_track(0, 0.0, 2.0), line_truth());
    CHECK(m.checkpoints == 11);
    CHECK(m.horizontal_m.mean == doctest::Approx(2.0));
    CHECK(m.dy_m.mean == doctest::Approx(2.0));
    CHECK(m.dy_m.sd == doctest::Approx(0.0));
    CHECK(m.dx_m.max == doctest::Approx(0.0));
    CHECK(m.final_error_m == doctest::Approx(2.0));
    CHECK(m.heading_error_deg.max == doctest::Approx(0.0));
}

TEST_CASE("evaluate: a track drifting sideways 0.1 m per metre") {
    // Errors 0, 0.1, ..., 1.0 m: mean 0.5, median 0.5, p75 0.75, max 1.0.
    const Metrics m = evaluate(line_track(0, 0, 0, 0.1), line_truth());
    CHECK(m.horizontal_m.mean == doctest::Approx(0.5));
    CHECK(m.horizontal_m.median == doctest::Approx(0.5));
    CHECK(m.horizontal_m.p75 == doctest::Approx(0.75));
    CHECK(m.horizontal_m.max == doctest::Approx(1.0));
    CHECK(m.ipin_score_m == doctest::Approx(0.75));
    CHECK(m.dy_m.min == doctest::Approx(0.0));
    CHECK(m.dy_m.max == doctest::Approx(1.0));
}

TEST_CASE("alignment: start point, first segment and fitted rotation undo a rigid motion") {
    const Track tr = line_track(40.0, 5.0, -3.0);
    CHECK(evaluate(tr, line_truth()).horizontal_m.mean > 3.0);
    EvalOptions o;
    o.alignment = Alignment::start_point;
    const Metrics ms = evaluate(tr, line_truth(), o);
    CHECK(ms.horizontal_m.max == doctest::Approx(2 * 10 * std::sin(20.0 * M_PI / 180.0)));  // chord at 10 m
    for (Alignment a : {Alignment::first_segment, Alignment::fitted}) {
        o.alignment = a;
        const Metrics m = evaluate(tr, line_truth(), o);
        CHECK(m.alignment.rotation_deg == doctest::Approx(-40.0));
        CHECK(m.horizontal_m.max < 1e-9);
        CHECK(m.heading_error_deg.max < 1e-9);
    }
}

TEST_CASE("loop closure, legs and steps") {
    Track tr;
    // A square of side 10 walked at 1 m/s that ends 0.4 m east of the start.
    const double xs[] = {0, 10, 10, 0, 0.4}, ys[] = {0, 0, 10, 10, 0};
    for (int k = 0; k < 5; ++k) {
        TrackSample s;
        s.t_s = 10.0 * k;
        s.pos_m[0] = xs[k];
        s.pos_m[1] = ys[k];
        s.pos_m[2] = 0.3 * (k == 4);
        tr.samples.push_back(s);
    }
    tr.has_steps = true;
    tr.step_times_s = {1, 2, 3};
    Truth t = make_loop_truth();
    t.legs.push_back({0.0, 10.0, 10.5});
    t.step_count = 4;
    const Metrics m = evaluate(tr, t);
    CHECK(m.loop_closure_m == doctest::Approx(0.4));
    CHECK(m.loop_closure_3d_m == doctest::Approx(0.5));
    CHECK(m.distance_m == doctest::Approx(30.0 + std::hypot(0.4, 10.0)));
    CHECK(m.loop_closure_pct == doctest::Approx(100.0 * 0.4 / m.distance_m));
    CHECK(m.leg_lengths_m.at(0) == doctest::Approx(10.0));
    CHECK(m.leg_errors_pct.at(0) == doctest::Approx(-100.0 * 0.5 / 10.5));
    CHECK(m.step_count == 3);
    CHECK(m.truth_step_count == 4);
    t.loop_length_m = 40.0;
    CHECK(evaluate(tr, t).loop_closure_pct == doctest::Approx(1.0));
}

TEST_CASE("height error and floors") {
    Truth t = line_truth();
    for (auto& p : t.points) p.z_m = 0.0, p.floor = 0, p.has_floor = true;
    t.points.back().floor = 1;
    Track tr = line_track(0, 0, 0);
    for (auto& s : tr.samples) s.pos_m[2] = 0.2, s.has_floor = true, s.floor = 0;
    const Metrics m = evaluate(tr, t);
    CHECK(m.height_error_mean_m == doctest::Approx(0.2));
    CHECK(m.height_error_sd_m == doctest::Approx(0.0));
    CHECK(m.floor_correct_pct == doctest::Approx(100.0 * 10 / 11));
    // All horizontal errors are 0; the last checkpoint is one floor off: p75 of {0 x 10, 15} = 0.
    CHECK(m.ipin_score_m == doctest::Approx(0.0));
    const nlohmann::json j = to_json(m);
    CHECK(j["height_error_m"]["mean"].get<double>() == doctest::Approx(0.2));
    CHECK(j["loop_closure"]["horizontal_m"].is_null());
    CHECK(format_table(m).find("height error") != std::string::npos);
}

TEST_CASE("step times: the t_end column of pednav run --steps, else t, else the first column") {
    const std::string path = "eval_test_steps.csv";
    {
        std::ofstream f(path);
        f << "index,t_start,t_end,dx\n0,1.5,2.5,0.6\n1,2.5,3.75,1.4\n";
    }
    CHECK(read_step_times_csv(path) == std::vector<double>{2.5, 3.75});
    {
        std::ofstream f(path);
        f << "# steps\n1.25\n2.0\n";
    }
    CHECK(read_step_times_csv(path) == std::vector<double>{1.25, 2.0});
    std::remove(path.c_str());
}

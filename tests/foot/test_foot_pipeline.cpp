// SPDX-License-Identifier: Apache-2.0
// The foot pipeline through the real engine and plugin loader: accuracy on
// the shared recordings and on simulated walks with exact truth (issue 3),
// plus the plugin contract (strict params, determinism, records).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_foot_eval/patches.hpp>
#include <pednav_foot_eval/runs.hpp>
#include <pednav_foot_eval/scores.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_navmath/so3.hpp>
#include <pednav_sim/simulate.hpp>

using namespace pednav;
using namespace pednav::foot_eval;
using eval::SimulatedWalk;

namespace {
const std::string kData = PEDNAV_SHARED_DATA_DIR;
const std::vector<std::string> kPlugins = {PEDNAV_PLUGIN_OUTPUT_DIR};

// configs/foot.json with `patch` merged in.
std::string foot_config(const nlohmann::json& patch) {
    static const std::string preset = [] {
        const std::string path = std::string(PEDNAV_SOURCE_DIR) + "/configs/foot.json";
        std::ifstream f(path);
        if (!f) throw std::runtime_error("cannot open " + path);
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    }();
    return eval::patched_config(preset, patch);
}
// For the koroglu walks: their sensor's gyro range is given to the attitude
// estimator unless the patch sets gyro_range_radps itself.
std::string koroglu_config(const nlohmann::json& patch) {
    return foot_config(with_gyro_range(patch, eval::kKorogluGyroRangeRadps));
}
const std::string& preset() {
    static const std::string cfg = foot_config(nlohmann::json::object());
    return cfg;
}
std::string with_ekf(const nlohmann::json& params) { return foot_config(ekf_patch(params)); }

// The simulated corridor loop through the preset: every stride found and
// classed level, and the loop closed within max_pct of the distance.
void check_loop_closes(const SimulatedWalk& c, double max_pct) {
    const SimScore s = score_sim(c, preset(), kPlugins);
    CAPTURE(c.rate_hz);
    CAPTURE(s.closure_m);
    CAPTURE(s.closure_pct);
    CHECK(s.strides == s.true_strides);
    CHECK(s.level == s.strides);
    CHECK(s.closure_pct < max_pct);
}
}  // namespace

TEST_CASE("issue 3: xio-gait-ngimu loops end near their start (causal)") {
    for (const std::string& walk : eval::xio_walk_names()) {
        const XioScore s = score_xio(eval::xio_walk(kData, walk), preset(), kPlugins);
        CAPTURE(walk);
        CAPTURE(s.closure_m);
        CAPTURE(s.distance_m);
        CHECK(s.distance_m > (walk == "short_walk" ? 20.0 : 52.0));
        CHECK(s.closure_pct < XIO_CLOSURE_PCT_MAX);
    }
}

TEST_CASE("issue 3: koroglu-foot-gcp stride count equals footprints, error at footprints") {
    const std::string cfg = koroglu_config(nlohmann::json::object());
    for (int n : eval::koroglu_walk_numbers()) {
        const KorogluScore s = score_koroglu(eval::koroglu_walk(kData, n), cfg, kPlugins);
        CAPTURE(n);
        CAPTURE(s.err_m.mean);
        CAPTURE(s.err_m.max);
        CAPTURE(s.final_error_m);
        CHECK(s.strides == s.footprints);
        CHECK(s.mean_pct < 1.5);
        // Stride-length scale: the rolling-foot ZUPT keeps the footprint path
        // within 2 % of the measured one (walk 35, with 170 ms gyro clipping
        // in its fast strides: 5 %); the paper's plain ZUPT is 2.7 % short on 44.
        CHECK(std::abs(s.est_path_m / s.path_m - 1.0) < (n == 35 ? 0.05 : 0.02));
    }
}

TEST_CASE("issue 3: ipol foot files, 10 m out and 10 m back") {
    // Two readings of "10 m": start to the farthest point and back (the
    // U-turn's excursion included), and between the annotated walk and U-turn
    // boundaries (the dataset's own, which leaves part of the turn out).
    double sum = 0, sum_annotated = 0;
    int legs = 0;
    for (const std::string& t : eval::ipol_trials())
        for (const char* f : {"lf", "rf"}) {
            const IpolScore s = score_ipol(eval::ipol_walk(kData, t, f), preset(), kPlugins);
            CAPTURE(s.name);
            // Walkers stop past their start (5-2 left foot: 11.0 m from the
            // farthest point, 9.9 m between the annotated boundaries).
            CHECK(std::abs(s.leg_out_m - 10.0) < 1.2);
            CHECK(std::abs(s.leg_back_m - 10.0) < 1.2);
            CHECK(std::abs(static_cast<int>(s.strides) - static_cast<int>(s.footsteps)) <= 2);
            CHECK(std::abs(s.annotated_out_m - 10.0) < 0.9);
            CHECK(std::abs(s.annotated_back_m - 10.0) < 0.9);
            sum += s.leg_out_m + s.leg_back_m;
            sum_annotated += s.annotated_out_m + s.annotated_back_m;
            legs += 2;
        }
    CHECK(std::abs(sum / legs - 10.0) < 0.3);  // within 3 % on average over the 32 legs
    CHECK(std::abs(sum_annotated / legs - 10.0) < 0.3);
}

TEST_CASE("ipol: accelerometers rescaled to read gravity at rest bring the two feet's legs together") {
    // The left-foot sensors read 10.26-10.28 m/s^2 at rest (4.7 % high), the
    // right-foot ones 9.87-9.92 (0.7-1.1 %). With the scale as read the left
    // foot measures 15 of 16 legs longer than the right one (0.3 m apart); rescaled
    // (accel_rescale_above 0: always) the feet agree and most legs come within 3 %.
    const std::string rescaled = with_ekf({{"accel_rescale_above", 0.0}});
    double diff_read = 0, diff_rescaled = 0;
    int within_3pct = 0;
    for (const std::string& t : eval::ipol_trials()) {
        const eval::RecordedWalk left = eval::ipol_walk(kData, t, "lf"), right = eval::ipol_walk(kData, t, "rf");
        const IpolScore lf = score_ipol(left, preset(), kPlugins), rf = score_ipol(right, preset(), kPlugins);
        const IpolScore lf2 = score_ipol(left, rescaled, kPlugins), rf2 = score_ipol(right, rescaled, kPlugins);
        diff_read += std::abs(lf.leg_out_m - rf.leg_out_m) + std::abs(lf.leg_back_m - rf.leg_back_m);
        diff_rescaled += std::abs(lf2.leg_out_m - rf2.leg_out_m) + std::abs(lf2.leg_back_m - rf2.leg_back_m);
        for (double leg : {lf2.leg_out_m, lf2.leg_back_m, rf2.leg_out_m, rf2.leg_back_m})
            within_3pct += std::abs(leg - 10.0) <= 0.3;
    }
    diff_read /= 16;
    diff_rescaled /= 16;
    MESSAGE("ipol, mean |left - right| leg: as read " << diff_read << " m, rescaled " << diff_rescaled
            << " m; rescaled legs within 3 %: " << within_3pct << " of 32");
    CHECK(diff_read > 0.25);      // measured 0.30 m
    CHECK(diff_rescaled < 0.15);  // measured 0.11 m
    CHECK(within_3pct >= 26);     // measured 27 (as read: 18)
}

TEST_CASE("issue 3: simulated 3 x 40 m corridor loop closes within 0.3 %") {
    for (double rate : {100.0, 200.0, 400.0}) {
        SimulatedWalk c;
        c.rate_hz = rate;
        c.mounting_rpy_deg[0] = 20;  // tilted on the shoe
        c.mounting_rpy_deg[1] = -30;
        c.mounting_rpy_deg[2] = 10;
        check_loop_closes(c, 0.3);
    }
}

TEST_CASE("gaits, mountings and rates the preset was not tuned on: every stride found, the loop closes") {
    // A slow walk and a jog (3 m/s, the foot flat for 12 % of a stride, 3 g
    // landings), the sensor upside down or standing on its end, at 100 and
    // 256 Hz. `pednav report --suite sweep` prints the whole grid (288 runs:
    // median 0.19 %, largest 1.05 %, from the gyro scale-factor errors).
    const eval::Gait& slow = eval::sweep_gaits().front();
    const eval::Gait& jog = eval::sweep_gaits().back();
    for (const eval::Gait& g : {slow, jog}) {
        for (const std::array<double, 2> roll_pitch : {std::array<double, 2>{180, 0}, std::array<double, 2>{0, -80}}) {
            for (double rate : {100.0, 256.0}) {
                SimulatedWalk c;
                c.rate_hz = rate;
                c.mounting_rpy_deg[0] = roll_pitch[0];
                c.mounting_rpy_deg[1] = roll_pitch[1];
                c.gait = g;
                CAPTURE(g.name);
                CAPTURE(roll_pitch[1]);
                check_loop_closes(c, 1.5);
            }
        }
    }
}

TEST_CASE("issue 3: clipped gyro: the xio loops clipped at 500 deg/s stay on their unclipped footprints") {
    // The NGIMU reads up to 2000 deg/s; clipped as a +-500 deg/s sensor would
    // read it (200-300 samples per loop), the swings lose rotation. With the
    // range given the attitude estimator restores it; the unclipped run is
    // the truth.
    for (const std::string& walk : eval::xio_walk_names()) {
        const eval::RecordedWalk xio = eval::xio_walk(kData, walk);
        const ClipScore off = score_xio_clipped(xio, preset(), kPlugins, 500.0 * M_PI / 180.0, false);
        const ClipScore on = score_xio_clipped(xio, preset(), kPlugins, 500.0 * M_PI / 180.0, true);
        CAPTURE(walk);
        CAPTURE(off.footprint_rms_m);
        CAPTURE(on.footprint_rms_m);
        CAPTURE(on.heading_rms_deg);
        CHECK(on.clipped_samples > 200);
        CHECK(on.strides == on.strides_unclipped);
        CHECK(off.footprint_rms_m > 0.3);  // unrepaired: 0.45 and 0.88 m
        CHECK(on.footprint_rms_m < 0.2);
        CHECK(on.footprint_rms_m < 0.35 * off.footprint_rms_m);
        CHECK(on.heading_rms_deg < 3.0);
    }
}

TEST_CASE("issue 3: stairs up and down two flights, with and without HUPT") {
    SimulatedWalk c;
    c.route = "stairs";
    c.rate_hz = 200;
    c.mounting_rpy_deg[1] = 25;
    c.error_scale = 5;  // a poor MEMS unit: 0.2 m/s^2 accelerometer and 1 deg/s gyro biases
    const SimScore hupt = score_sim(c, preset(), kPlugins);
    const SimScore zupt = score_sim(c, with_ekf({{"hupt", false}}), kPlugins);
    CAPTURE(hupt.final_err_z_m);
    CAPTURE(zupt.final_err_z_m);
    CAPTURE(hupt.mean_err_z_m);
    CAPTURE(zupt.mean_err_z_m);
    CHECK(hupt.strides == hupt.true_strides);
    CHECK(hupt.stairs == 20);  // 2 x 2 flights of 10 stairs, one foot
    CHECK(hupt.level == hupt.strides - 20);
    CHECK(hupt.final_err_z_m < 0.5 * zupt.final_err_z_m);
    CHECK(hupt.mean_err_z_m < 0.6 * zupt.mean_err_z_m);
    // Back on the start floor within the level memory's reach: its height (the
    // issue asks for a final height error below 0.3 m).
    CHECK(hupt.final_err_z_m < 0.01);
    // Without the memory (the paper's HUPT) the end keeps the stairs' error.
    const SimScore paper = score_sim(c, with_ekf({{"level_match_m", 0.0}}), kPlugins);
    CAPTURE(paper.final_err_z_m);
    CHECK(paper.final_err_z_m > hupt.final_err_z_m);
}

TEST_CASE("issue 3: HUPT on a nine-minute walk over three floors cuts the mean height error by at least 80 %") {
    // The paper's setting (foot-imu-height-update-hupt sec. 3: long walks
    // through several floors and back): the building tour, 40 stair strides,
    // a poor MEMS unit, three noise seeds.
    for (uint64_t seed : {1, 2, 3}) {
        SimulatedWalk c;
        c.route = "building_tour";
        c.error_scale = 5;
        c.seed = seed;
        c.mounting_rpy_deg[1] = 25;
        const SimScore hupt = score_sim(c, preset(), kPlugins);
        const SimScore zupt = score_sim(c, with_ekf({{"hupt", false}}), kPlugins);
        CAPTURE(seed);
        CAPTURE(hupt.mean_err_z_m);
        CAPTURE(zupt.mean_err_z_m);
        CAPTURE(hupt.final_err_z_m);
        CHECK(hupt.strides == hupt.true_strides);
        CHECK(hupt.stairs == 40);
        CHECK(hupt.mean_err_z_m < 0.2 * zupt.mean_err_z_m);
        CHECK(hupt.mean_err_z_m < 0.1);  // the paper: 0.31 m
        CHECK(hupt.final_err_z_m < 0.01);
    }
}

TEST_CASE("issue 3: HUPT cuts the mean height error on level floors by at least 80 %") {
    for (double errors : {1.0, 5.0}) {
        SimulatedWalk c;
        c.error_scale = errors;
        const SimScore hupt = score_sim(c, preset(), kPlugins);
        const SimScore zupt = score_sim(c, with_ekf({{"hupt", false}}), kPlugins);
        CAPTURE(errors);
        CAPTURE(hupt.mean_err_z_m);
        CAPTURE(zupt.mean_err_z_m);
        CHECK(hupt.level == hupt.strides);
        CHECK(hupt.mean_err_z_m < 0.2 * zupt.mean_err_z_m);
    }
}

// Height drift per step of the integration alone, on exact sensor data: each
// swing of the simulated walk is integrated from the true attitude at its
// start with zero velocity, first with end-of-interval rates (first order),
// then the way the plugins do it (mid-interval rates with the coning term for
// the attitude, trapezoidal velocity and position).
namespace {
double step_height_drift(const sim::SimOutput& out, bool mid_interval) {
    using navmath::Quat;
    using navmath::Vec3;
    double sum = 0;
    int steps = 0;
    const double g = 9.80665;
    for (size_t k = 1; k + 1 < out.truth.size(); ++k) {
        if (!(out.truth[k - 1].stance && !out.truth[k].stance)) continue;
        const size_t k0 = k - 1;  // last stance sample
        const auto& t0 = out.truth[k0];
        Quat q(t0.q_enu_from_body[0], t0.q_enu_from_body[1], t0.q_enu_from_body[2], t0.q_enu_from_body[3]);
        Vec3 v = Vec3::Zero(), p = Vec3::Zero();
        auto f_of = [&](size_t i) { return Vec3(out.imu[i].accel_mps2[0], out.imu[i].accel_mps2[1], out.imu[i].accel_mps2[2]); };
        auto w_of = [&](size_t i) { return Vec3(out.imu[i].gyro_radps[0], out.imu[i].gyro_radps[1], out.imu[i].gyro_radps[2]); };
        Vec3 fn_prev = q * f_of(k0);
        size_t i = k0 + 1;
        for (; i < out.truth.size() && !out.truth[i].stance; ++i) {
            const double dt = out.truth[i].t_s - out.truth[i - 1].t_s;
            if (mid_interval) {
                const Vec3 w0 = w_of(i - 1), w1 = w_of(i);
                q = q * navmath::quat_exp(0.5 * (w0 + w1) * dt + dt * dt / 12.0 * w0.cross(w1));
                const Vec3 fn = q * f_of(i);
                const Vec3 v1 = v + (0.5 * (fn_prev + fn) - Vec3(0, 0, g)) * dt;
                p += 0.5 * (v + v1) * dt;
                v = v1;
                fn_prev = fn;
            } else {
                q = q * navmath::quat_exp(w_of(i) * dt);  // foot-imu-zupt-zaru-ekf eq. (8)-(11)
                v += (q * f_of(i) - Vec3(0, 0, g)) * dt;
                p += v * dt;
            }
        }
        if (i >= out.truth.size()) break;
        const double dz_true = out.truth[i].pos_enu_m[2] - t0.pos_enu_m[2];
        sum += std::abs(p.z() - dz_true);
        ++steps;
    }
    return steps ? sum / steps : 1e9;
}
}  // namespace

TEST_CASE("noise-free input: mid-interval integration has no height drift per step at 400 Hz") {
    sim::SimOptions so;
    so.rate_hz = 400;
    so.sensor_errors = false;
    so.with_gnss = so.with_baro = so.with_mag = false;
    so.mounting_rpy_deg[1] = -30;
    const sim::SimOutput out = sim::simulate(sim::builtin_route("corridor_loop"), so);
    const double first = step_height_drift(out, false);
    const double mid = step_height_drift(out, true);
    MESSAGE("height drift per step, 400 Hz, noise-free: first order " << first * 100 << " cm, mid-interval "
                                                                       << mid * 100 << " cm");
    CHECK(first > 0.005);
    CHECK(mid < 0.0005);
    // The whole pipeline, HUPT off, on the same exact data: no height drift.
    SimulatedWalk c;
    c.rate_hz = 400;
    c.sensor_errors = false;
    c.mounting_rpy_deg[1] = -30;
    const SimScore s = score_sim(c, with_ekf({{"hupt", false}}), kPlugins);
    CHECK(s.final_err_z_m < 0.01);
    CHECK(s.closure_pct < 0.01);
}

TEST_CASE("foot plugins reject unknown or bad params, naming the key") {
    const std::string path = eval::xio_walk(kData, "short_walk").input;
    auto expect_error = [&](const nlohmann::json& patch, const std::string& key) {
        try {
            run_recording(path, foot_config(patch), kPlugins);
            FAIL("accepted a bad config");
        } catch (const std::exception& e) {
            CHECK(std::string(e.what()).find(key) != std::string::npos);
        }
    };
    expect_error(ekf_patch({{"zupt_sd", 0.01}}), "/pipelines/foot/position_filter/params/zupt_sd");
    expect_error(ekf_patch({{"zupt_sd_mps", -1.0}}), "zupt_sd_mps");
    expect_error(ekf_patch({{"sensor_height_m", -0.05}}), "sensor_height_m");
    nlohmann::json p;
    p["pipelines"]["foot"]["step_detector"]["params"]["window_samples"] = 31;
    expect_error(p, "window_samples");
    nlohmann::json a;
    a["pipelines"]["foot"]["attitude_estimator"]["params"]["use_magnetometer"] = "yes";
    expect_error(a, "use_magnetometer");
    // A cross-field rule the schema cannot express: an empty trusted magnetometer band.
    nlohmann::json m;
    m["pipelines"]["foot"]["attitude_estimator"]["params"]["mag_min_ut"] = 120.0;
    expect_error(m, "/pipelines/foot/attitude_estimator/params/mag_min_ut");
    expect_error(m, "above mag_max_ut (100 uT)");
}

TEST_CASE("foot pipeline records: one position per sample, deterministic, valid covariances and quaternions") {
    const std::string path = eval::koroglu_walk(kData, 35).input;
    const io::SensorLog log = io::read_sensor_file(path);
    auto doc = nlohmann::json::parse(preset());
    doc["imu_rate_hz"] = 200.0;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = {PEDNAV_PLUGIN_OUTPUT_DIR};
    o.keep_attitudes = true;
    o.keep_gait_phases = true;
    const auto recs = io::merged_records(log);
    const ReplayResult a = replay(o, recs);
    const ReplayResult b = replay(o, recs);
    REQUIRE(a.error.empty());
    CHECK(a.warnings.empty());
    CHECK(a.gait_phases.size() == log.imu.size());
    CHECK(a.positions.size() == a.attitudes.size());
    CHECK(a.positions.size() + 250 > log.imu.size());  // everything after the alignment
    REQUIRE(a.positions.size() == b.positions.size());
    CHECK(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(pn_position_t)) == 0);
    REQUIRE(a.strides.size() == b.strides.size());
    CHECK(std::memcmp(a.strides.data(), b.strides.data(), a.strides.size() * sizeof(pn_stride_t)) == 0);
    for (const auto& q : a.attitudes) {
        const double n = std::sqrt(q.q_enu_from_body[0] * q.q_enu_from_body[0] + q.q_enu_from_body[1] * q.q_enu_from_body[1] +
                                   q.q_enu_from_body[2] * q.q_enu_from_body[2] + q.q_enu_from_body[3] * q.q_enu_from_body[3]);
        REQUIRE(std::abs(n - 1.0) < 1e-12);
    }
    for (size_t i = 0; i < a.positions.size(); i += 97) {
        Eigen::Matrix3d c;
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) c(r, k) = a.positions[i].cov_enu_m2[3 * r + k];
        REQUIRE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c).eigenvalues().minCoeff() > -1e-12);
    }
    // Strides chain: their displacements add up to the track between stances.
    double sum[2] = {0, 0};
    for (const auto& s : a.strides) {
        sum[0] += s.displacement_enu_m[0];
        sum[1] += s.displacement_enu_m[1];
    }
    const auto& p0 = position_at(a, a.strides.front().t_start_ns * 1e-9);
    const auto& p1 = position_at(a, a.strides.back().header.t_ns * 1e-9);
    CHECK(std::hypot(p1.pos_enu_m[0] - p0.pos_enu_m[0] - sum[0], p1.pos_enu_m[1] - p0.pos_enu_m[1] - sum[1]) < 1e-6);
}

TEST_CASE("a start heading given to the engine turns the track (yaw correction at the first sample)") {
    const std::string path = eval::xio_walk(kData, "short_walk").input;
    const io::SensorLog log = io::read_sensor_file(path);
    auto doc = nlohmann::json::parse(preset());
    doc["imu_rate_hz"] = 400.0;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = {PEDNAV_PLUGIN_OUTPUT_DIR};
    const auto recs = io::merged_records(log);
    const ReplayResult base = replay(o, recs);
    o.heading_deg = 90.0;
    o.start_enu_m[0] = 5.0;
    const ReplayResult turned = replay(o, recs);
    REQUIRE(base.strides.size() == turned.strides.size());
    REQUIRE(!turned.positions.empty());
    CHECK(turned.positions.front().heading_rad == doctest::Approx(M_PI / 2).epsilon(1e-9));
    CHECK(turned.positions.front().pos_enu_m[0] == doctest::Approx(5.0));
    // Every stride is the base one turned by the heading difference.
    const double d = turned.positions.front().heading_rad - base.positions.front().heading_rad;
    for (size_t i = 0; i < base.strides.size(); ++i) {
        const double* b = base.strides[i].displacement_enu_m;
        const double* t = turned.strides[i].displacement_enu_m;
        // Heading is clockwise: a heading change d rotates ENU vectors by -d.
        const double ex = std::cos(-d) * b[0] - std::sin(-d) * b[1], ey = std::sin(-d) * b[0] + std::cos(-d) * b[1];
        CHECK(std::hypot(t[0] - ex, t[1] - ey) < 1e-6 + 1e-6 * i);
    }
}

TEST_CASE("ZARU that holds the position: no walk's mean error grows by more than 0.005 %, and the swaying last stances of koroglu 33 and 42 end nearer their footprints") {
    // At the end of koroglu 33 and 42 the foot stands while turning at
    // 0.03-0.1 rad/s, under the ZARU gate: ZARU reads the turn as gyro bias and,
    // through the bias-position correlation, moves the standing foot.
    // Walk 39's final error grows (0.35 -> 1.65 m), the trade-off that keeps
    // the option off in the preset (docs/foot-pipeline.md, "Weak points").
    const std::string preset_cfg = koroglu_config(nlohmann::json::object());
    const std::string hold_cfg = koroglu_config(ekf_patch({{"zaru_moves_position", false}}));
    for (int n : eval::koroglu_walk_numbers()) {
        const eval::RecordedWalk walk = eval::koroglu_walk(kData, n);
        const KorogluScore def = score_koroglu(walk, preset_cfg, kPlugins);
        const KorogluScore hold = score_koroglu(walk, hold_cfg, kPlugins);
        CAPTURE(n);
        CAPTURE(def.final_error_m);
        CAPTURE(hold.final_error_m);
        CAPTURE(hold.mean_pct);
        CHECK(hold.strides == hold.footprints);
        CHECK(hold.mean_pct < 1.5);
        CHECK(hold.mean_pct <= def.mean_pct + 0.005);  // measured: equal or lower on every walk
        if (n == 33 || n == 42) CHECK(hold.final_error_m < def.final_error_m - 0.5);  // 3.08 -> 1.32, 3.41 -> 2.34 m
    }
}

TEST_CASE("the dense textbook EKF plugin gives the same track as the hand-written kernels, to round-off") {
    // org.pednav.foot.ekf15.dense: 15 x 15 Phi P Phi^T and a dense-H Joseph
    // update. A real walk with clipping repair, brisk stances and ZARU
    // (koroglu 35) and a simulated stairs walk with HUPT.
    nlohmann::json dense;
    dense["pipelines"]["foot"]["position_filter"]["plugin"] = "org.pednav.foot.ekf15.dense";
    const std::string koroglu = eval::koroglu_walk(kData, 35).input;
    const ReplayResult fast_run = run_recording(koroglu, koroglu_config(nlohmann::json::object()), kPlugins);
    const ReplayResult dense_run = run_recording(koroglu, koroglu_config(dense), kPlugins);
    REQUIRE(fast_run.positions.size() == dense_run.positions.size());
    CHECK(fast_run.strides.size() == dense_run.strides.size());
    double max_diff_m = 0, max_cov_rel = 0;
    for (size_t i = 0; i < fast_run.positions.size(); ++i) {
        const pn_position_t &a = fast_run.positions[i], &b = dense_run.positions[i];
        max_diff_m = std::max(max_diff_m, std::hypot(a.pos_enu_m[0] - b.pos_enu_m[0], a.pos_enu_m[1] - b.pos_enu_m[1],
                                                     a.pos_enu_m[2] - b.pos_enu_m[2]));
        max_cov_rel = std::max(max_cov_rel, std::abs(a.cov_enu_m2[0] - b.cov_enu_m2[0]) / a.cov_enu_m2[0]);
    }
    MESSAGE("koroglu 35, fast vs dense: largest position difference " << max_diff_m
            << " m, largest relative difference of the east variance " << max_cov_rel);
    CHECK(max_diff_m < 1e-9);
    CHECK(max_cov_rel < 1e-9);
    // The preset, the other covariance form (P - K H P), propagation at every
    // filter step, and the filter at 100 Hz on 200 Hz input (its steps span
    // two samples, in the swing deferred and in stance propagated).
    const nlohmann::json variants[] = {nlohmann::json::object(),
                                       {{"joseph_form", false}},
                                       {{"swing_propagation_s", 0}},
                                       {{"filter_rate_hz", 100}}};
    SimScore preset_sim{};
    for (const nlohmann::json& params : variants) {
        nlohmann::json form = ekf_patch(params);
        nlohmann::json dense_form = form;
        dense_form.merge_patch(dense);
        SimulatedWalk c;
        c.route = "stairs";
        const SimScore fast_sim = score_sim(c, foot_config(form), kPlugins);
        const SimScore dense_sim = score_sim(c, foot_config(dense_form), kPlugins);
        CAPTURE(params.dump());
        CHECK(fast_sim.strides == dense_sim.strides);
        CHECK(std::abs(fast_sim.closure_m - dense_sim.closure_m) < 1e-9);
        CHECK(std::abs(fast_sim.mean_err_z_m - dense_sim.mean_err_z_m) < 1e-9);
        if (params.empty()) preset_sim = fast_sim;
        if (params.contains("swing_propagation_s")) {
            // Deferring the swing's propagation changes the track only through
            // where the swing's process noise enters the next stance's gains.
            MESSAGE("stairs, swing_propagation_s 0 vs the preset: closure " << fast_sim.closure_m << " vs "
                    << preset_sim.closure_m << " m, mean height error " << fast_sim.mean_err_z_m << " vs "
                    << preset_sim.mean_err_z_m << " m");
            CHECK(fast_sim.strides == preset_sim.strides);
            CHECK(fast_sim.closure_m != preset_sim.closure_m);  // the parameter takes effect
            CHECK(std::abs(fast_sim.closure_m - preset_sim.closure_m) < 0.002);  // measured: 7e-5 m
            CHECK(std::abs(fast_sim.mean_err_z_m - preset_sim.mean_err_z_m) < 0.002);  // 1.3e-4 m
        }
    }
}

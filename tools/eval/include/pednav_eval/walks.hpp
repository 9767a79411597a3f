// SPDX-License-Identifier: Apache-2.0
// The walks the pipelines are scored on, in one place: the shared recordings
// that have a ground truth (which exist, where each one's input and truth are,
// how its track is aligned) and the simulated walks (which built-in routes with
// which simulator settings). pednav report, its suites and the accuracy tests
// all take their walks from here.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth.hpp>

namespace pednav::sim {
struct SimOptions;
struct Route;
}  // namespace pednav::sim

namespace pednav::eval {

// ------------------------------------------------ shared recordings
// Each folder under the data directory (../shared/data) has a SOURCE.md.

// A shared recording with its ground truth.
struct RecordedWalk {
    std::string name;         // as reported: "koroglu-33", "xio-short_walk", "ipol-1-1-lf", "humolire-user1_straight"
    std::string mount;        // the pipeline that runs it: "foot", "waist", "chest" or "handheld"
    std::string input;        // the recording: a file, or a folder (humolire)
    TruthKind truth_kind = TruthKind::loop;
    std::string truth_path;   // the truth's file or folder; empty for a loop
    std::string feet;         // step events: whose steps the sensor sees ("left", "right" or "both")
    Alignment alignment = Alignment::none;
    bool give_start = false;  // the engine starts at the truth's start point and heading
    double gyro_range_radps = 0.0;  // the sensor's gyro range where it clips in these walks, else 0
    double user_height_m = 0.0;     // the walker's height where the recording gives it (with_user_height), else 0
};

// koroglu-foot-gcp: SensorConnectData_<n>.csv, a foot at 200 Hz, and the
// footprints in SensorConnectData_<n>_gcp.csv; scored after one rotation fitted
// on the first 5 strides. The 3DM-GX5-25 is set to +-500 deg/s and clips in
// brisk swings.
const std::vector<int>& koroglu_walk_numbers();  // 33, 35, 39, 42, 44
constexpr double kKorogluGyroRangeRadps = 500.0 * M_PI / 180.0;
RecordedWalk koroglu_walk(const std::string& data_dir, int number);

// xio-gait-ngimu: <name>.csv, a foot at 400 Hz on a loop that ends where it started.
const std::vector<std::string>& xio_walk_names();  // short_walk, long_walk
RecordedWalk xio_walk(const std::string& data_dir, const std::string& name);

// ipol-gait-waist-feet: <trial>_<part>.txt at 100 Hz, part lf or rf (a foot)
// or lb (the lower back), annotated in <trial>.json: footsteps and two 10 m legs.
const std::vector<std::string>& ipol_trials();  // 1-1, 1-2, 5-1, 5-2, 10-1, 10-2, 15-1, 19-1
const std::vector<std::string>& ipol_parts();   // lf, rf, lb
constexpr double kIpolRateHz = 100.0;           // of the annotations' sample indices
constexpr double kIpolLegM = 10.0;
RecordedWalk ipol_walk(const std::string& data_dir, const std::string& trial, const std::string& part);

// humolire-phone: <name>/, a handheld phone (handheld pipeline), landmarks on a
// map; the engine is started at the known start point and heading, and told
// the walker's height (participant.txt).
const std::vector<std::string>& humolire_walk_names();
RecordedWalk humolire_walk(const std::string& data_dir, const std::string& name);
// The height of walk "user<N>_..."'s walker, m: participant N of
// humolire-phone/participant.txt (number, height in cm, gender, age); 0 when
// the file or the participant is not there.
double humolire_user_height_m(const std::string& data_dir, const std::string& name);

// Every walk above, in the report's order: koroglu, xio, ipol (lf, rf, lb per
// trial), humolire. Whether its files exist is not checked here.
std::vector<RecordedWalk> recorded_walks(const std::string& data_dir);

// The walk's truth through the reader of its kind (truth_readers.hpp); throws
// std::runtime_error naming the file.
Truth read_walk_truth(const RecordedWalk& walk);

// ------------------------------------------------- simulated walks

// A gait on level floors: speed, step length (half a stride), the share of a
// stride the foot is flat and still, and the landing transient in g (0: none).
// Zeros keep the route's own values.
struct Gait {
    const char* name;
    double speed_mps, step_length_m, stance_fraction, heel_strike_g;
};

// A walk of the simulator (pednav_sim): a built-in route, at its own gait or
// another, and the simulator's settings.
struct SimulatedWalk {
    std::string route = "corridor_loop";
    std::string mount = "foot";
    double rate_hz = 200.0;
    uint64_t seed = 1;
    bool sensor_errors = true;  // false: an exact sensor
    double mounting_rpy_deg[3] = {0.0, 0.0, 0.0};
    double error_scale = 1.0;            // multiplies every IMU error of the simulator's default model
    double accel_bias_walk_scale = 1.0;  // and this the accelerometer bias random walk once more
    bool gyro_scale_errors = true;       // false: the gyro has no scale-factor error
    bool with_baro = false, with_gnss = false;  // IMU and magnetometer only unless set
    double surge_m = NAN;        // the trunk's forward oscillation (SimOptions::surge_m); NaN = the mount's own
    double time_jitter_s = 0.0;  // irregular sample times (SimOptions::time_jitter_s)
    Gait gait{"route", 0.0, 0.0, 0.0, 0.0};
};
sim::SimOptions sim_options(const SimulatedWalk& walk);
sim::Route sim_route(const SimulatedWalk& walk);  // throws for an unknown route

// pednav report: the built-in routes corridor_loop, stairs, figure_eight,
// building_tour and outdoor_indoor with `mount`, the simulator's defaults
// (consumer-grade errors, barometer and GNSS) and `seed`; the chest walks with
// the trunk surge of the handheld mount (kChestSurgeM), which the step vector
// measures.
constexpr double kChestSurgeM = 0.02;
std::vector<SimulatedWalk> builtin_sim_walks(const std::string& mount, uint64_t seed);

// The foot suites' walks (pednav report --suite, docs/foot-pipeline.md), each
// with the sensor tilted 20/-30/10 deg on the shoe:
// the corridor loop and the stairs with an exact sensor, the default MEMS
// errors x1 and x5, and the accelerometer bias random walk x100 and x300.
std::vector<SimulatedWalk> imu_error_walks(double rate_hz);
// The stairs and the building tour, MEMS errors x1 and x5, seeds 1 to 4, 200 Hz.
std::vector<SimulatedWalk> hupt_walks();
// The corridor loop over the gaits, rates and mountings the preset was not
// tuned on, three seeds each: gait by gait, rate by rate (100, 200, 256,
// 400 Hz), mounting by mounting, seed by seed.
std::vector<SimulatedWalk> sweep_walks(bool gyro_scale_errors);
const std::vector<Gait>& sweep_gaits();  // slow, normal, brisk, jog
const std::vector<double>& sweep_rates_hz();
const std::vector<std::array<double, 3>>& sweep_mountings_rpy_deg();

}  // namespace pednav::eval

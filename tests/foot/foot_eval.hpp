// Accuracy evaluation of the foot pipeline on the shared recordings and on
// simulated walks, through the real engine and plugin loader (pednav::replay).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav_engine/replay.hpp>

namespace pednav::foot_eval {

// configs/foot.json with `patch` merged in (RFC 7386 merge patch); the replay
// helpers below set imu_rate_hz to the recording's or simulation's rate.
std::string foot_config(const nlohmann::json& patch);
// foot_config() for the koroglu-foot-gcp walks: their sensor's +-500 deg/s gyro
// range is given to the attitude estimator unless the patch sets
// gyro_range_radps itself (0 = the clipping repair off).
std::string koroglu_config(const nlohmann::json& patch);
// The patch that selects a stance detector ("shoe" or "multicondition"; throws on any other name).
nlohmann::json detector_patch(const std::string& which);
// Merge patch for the position filter's params.
nlohmann::json ekf_patch(const nlohmann::json& params);

std::string data_dir();

// Reads a recording and replays it through the engine.
ReplayResult run_file(const std::string& path, const std::string& config_json, double* rate_hz = nullptr);

struct Stats {
    double mean = 0, max = 0, final = 0, sd = 0, min = 0;
    size_t n = 0;
};
Stats stats_of(const std::vector<double>& v);

// Position at time t (the last output at or before t).
const pn_position_t& position_at(const ReplayResult& r, double t_s);
// Horizontal length of the path through the stride end points.
double stride_path_m(const ReplayResult& r);

struct XioScore {
    std::string name;
    double distance_m = 0;     // walked (sum of stride lengths)
    double closure_m = 0;      // 3-D distance between start and end
    double closure_h_m = 0;    // horizontal
    double closure_pct = 0;    // closure_m / distance_m * 100
    size_t strides = 0;
};
XioScore score_xio(const std::string& name, const std::string& config_json);

// An xio loop with its gyro clipped at `clip_radps` (as a sensor set to that
// range would read it), against the same loop unclipped: how far the
// footprints and the stride headings move. The unclipped run is the truth.
struct ClipScore {
    size_t clipped_samples = 0;
    size_t strides = 0, strides_unclipped = 0;
    double footprint_rms_m = 0;   // rms over strides of |cumulative displacement - unclipped's|
    double heading_rms_deg = 0;   // rms over strides of the cumulative heading change's difference
};
ClipScore score_xio_clipped(const std::string& name, const std::string& config_json, double clip_radps,
                            bool tell_range);

struct KorogluScore {
    std::string name;
    size_t strides = 0;
    size_t footprints = 0;     // GCP rows - 1 (strides of the ground truth)
    double path_m = 0;         // GCP path length
    double est_path_m = 0;     // the same path through the estimated footprints (stride-length scale)
    Stats err_m;               // horizontal error at each footprint (after the 5-stride rotation fit)
    double mean_pct = 0;       // err.mean / path * 100
    std::vector<double> dx, dy;  // signed errors per footprint (for the paper's tables)
};
// Takes config_json as it is: build it with koroglu_config() to give the walks' gyro range.
KorogluScore score_koroglu(int n, const std::string& config_json);

struct IpolScore {
    std::string name;
    double leg_out_m = 0, leg_back_m = 0;  // start to the farthest point, and from there to the end
    double annotated_out_m = 0, annotated_back_m = 0;  // between the annotated walk and U-turn boundaries
    size_t strides = 0, footsteps = 0;
};
IpolScore score_ipol(const std::string& trial, const std::string& foot, const std::string& config_json);

struct SimScore {
    double distance_m = 0;       // horizontal distance walked (truth)
    double closure_m = 0;        // horizontal distance between estimated start and end
    double closure_pct = 0;
    double max_err_h_m = 0;      // horizontal error against the truth, largest
    double mean_err_z_m = 0;     // |height error| against the truth, mean over the stance samples
    double final_err_z_m = 0;    // height error at the end
    size_t strides = 0, true_strides = 0;
    size_t level = 0, stairs = 0;  // strides by class
};
// A gait on level floors: speed, step length (half a stride), the share of
// a stride the foot is flat and still, and the landing transient in g (0:
// none). Zeros keep the route's own values.
struct Gait {
    const char* name;
    double speed_mps, step_length_m, stance_fraction, heel_strike_g;
};
struct SimCase {
    std::string route = "corridor_loop";
    double rate_hz = 200.0;
    bool sensor_errors = true;
    uint64_t seed = 1;
    double mounting_rpy_deg[3] = {0.0, 0.0, 0.0};
    double error_scale = 1.0;  // multiplies every IMU error of the simulator's default model
    double accel_bias_walk_scale = 1.0;  // and this the accelerometer bias random walk once more
    bool gyro_scale_errors = true;       // false: the gyro has no scale-factor error
    Gait gait{"route", 0.0, 0.0, 0.0, 0.0};
};
SimScore score_sim(const SimCase& c, const std::string& config_json);

// Gaits of the sweep over gaits, mountings and rates (foot_report sweep and
// its test): slow, normal, brisk, jog.
const std::vector<Gait>& sweep_gaits();

}  // namespace pednav::foot_eval

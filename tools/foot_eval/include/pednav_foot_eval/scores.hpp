// SPDX-License-Identifier: Apache-2.0
// The foot pipeline's scores on the walks of the walk list (pednav_eval/walks.hpp),
// through the real engine and plugin loader: the figures of the foot issue and
// docs/foot-pipeline.md. Each takes the whole engine config (eval::patched_config)
// and the plugin directories, and throws std::runtime_error naming the walk
// when a run fails.
#pragma once

#include <string>
#include <vector>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/walks.hpp>

namespace pednav::foot_eval {

// xio-gait-ngimu: a loop that ends where it started.
struct XioScore {
    std::string name;
    double distance_m = 0;   // walked (sum of stride lengths)
    double closure_m = 0;    // 3-D distance between start and end
    double closure_h_m = 0;  // horizontal
    double closure_pct = 0;  // closure_m / distance_m * 100
    size_t strides = 0;
};
XioScore score_xio(const eval::RecordedWalk& walk, const std::string& config_json,
                   const std::vector<std::string>& plugin_dirs);

// An xio loop with its gyro clipped at `clip_radps` (as a sensor set to that
// range would read it), against the same loop unclipped: how far the
// footprints and the stride headings move. The unclipped run is the truth.
// tell_range: the attitude estimator is given the range (its clipping repair).
struct ClipScore {
    size_t clipped_samples = 0;
    size_t strides = 0, strides_unclipped = 0;
    double footprint_rms_m = 0;  // rms over strides of |cumulative displacement - unclipped's|
    double heading_rms_deg = 0;  // rms over strides of the cumulative heading change's difference
};
ClipScore score_xio_clipped(const eval::RecordedWalk& walk, const std::string& config_json,
                            const std::vector<std::string>& plugin_dirs, double clip_radps, bool tell_range);

// koroglu-foot-gcp: the estimated footprint (the position at the end of each
// annotated stance) against the measured one, after one rotation about the
// start fitted on the first 5 strides.
struct KorogluScore {
    std::string name;
    size_t strides = 0;
    size_t footprints = 0;     // strides of the ground truth
    double path_m = 0;         // the footprints' path length
    double est_path_m = 0;     // the same path through the estimated footprints (stride-length scale)
    eval::ErrorStats err_m;    // horizontal error at each footprint
    double final_error_m = 0;  // at the last footprint
    double mean_pct = 0;       // err_m.mean / path_m * 100
    std::vector<double> dx, dy;  // signed errors per footprint (for the paper's tables)
};
// Takes config_json as it is: give the walk's gyro range with with_gyro_range().
KorogluScore score_koroglu(const eval::RecordedWalk& walk, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs);

// ipol-gait-waist-feet foot file: the two 10 m legs.
struct IpolScore {
    std::string name;
    double leg_out_m = 0, leg_back_m = 0;  // start to the farthest point, and from there to the end
    double annotated_out_m = 0, annotated_back_m = 0;  // between the annotated walk and U-turn boundaries
    size_t strides = 0;
    size_t footsteps = 0;  // every annotated footstep of the walk's foot, in the trial or not
};
IpolScore score_ipol(const eval::RecordedWalk& walk, const std::string& config_json,
                     const std::vector<std::string>& plugin_dirs);

// A simulated walk against its exact truth, started at the truth's start point.
struct SimScore {
    double distance_m = 0;     // horizontal distance walked (truth)
    double closure_m = 0;      // horizontal distance between estimated start and end
    double closure_pct = 0;
    double max_err_h_m = 0;    // horizontal error against the truth, largest (after fitting the start heading)
    double mean_err_z_m = 0;   // |height error| against the truth, mean over the stance samples
    double final_err_z_m = 0;  // height error at the end
    size_t strides = 0, true_strides = 0;
    size_t level = 0, stairs = 0;  // strides by class
};
SimScore score_sim(const eval::SimulatedWalk& walk, const std::string& config_json,
                   const std::vector<std::string>& plugin_dirs);

}  // namespace pednav::foot_eval

// SPDX-License-Identifier: Apache-2.0
// A recording through the engine and the real plugins (pednav::replay) at the
// recording's own IMU rate, and what the foot scores read from the result.
#pragma once

#include <string>
#include <vector>

#include <pednav_engine/replay.hpp>

namespace pednav::io {
struct SensorLog;
}  // namespace pednav::io

namespace pednav::foot_eval {

// Replays `log` through `config_json` with imu_rate_hz set to the log's
// accelerometer rate. Throws std::runtime_error "<what>: <engine error>" when
// the run stops early.
ReplayResult run_log(const io::SensorLog& log, const std::string& config_json,
                     const std::vector<std::string>& plugin_dirs, const std::string& what);
// The same for a recording file (any format the readers detect).
ReplayResult run_recording(const std::string& path, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs);

// Position at time t: the last output at or before t (the first one before
// the track starts). Throws std::runtime_error when there is none.
const pn_position_t& position_at(const ReplayResult& r, double t_s);
// Distance walked: the sum of the stride lengths.
double stride_path_m(const ReplayResult& r);

}  // namespace pednav::foot_eval

// SPDX-License-Identifier: Apache-2.0
// The presets and the walks the chest tests share.
#pragma once

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/walks.hpp>

namespace pednav::test {

inline const std::string kData = PEDNAV_SHARED_DATA_DIR;
inline const std::vector<std::string> kPlugins = {PEDNAV_PLUGIN_OUTPUT_DIR};

// configs/<mount>.json with `patch` merged in (the position filter's params by name).
inline std::string preset(const std::string& mount, const nlohmann::json& filter_params = nlohmann::json::object()) {
    const std::string path = std::string(PEDNAV_SOURCE_DIR) + "/configs/" + mount + ".json";
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    if (filter_params.empty()) return ss.str();
    return eval::patched_config(ss.str(), {{"pipelines", {{mount, {{"position_filter", {{"params", filter_params}}}}}}}});
}

// The built-in route `route` as pednav report simulates it for `mount`.
inline eval::SimulatedWalk sim_walk(const std::string& mount, const std::string& route, uint64_t seed = 1) {
    for (const eval::SimulatedWalk& w : eval::builtin_sim_walks(mount, seed))
        if (w.route == route) return w;
    throw std::runtime_error("no built-in route " + route);
}

}  // namespace pednav::test

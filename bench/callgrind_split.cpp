// SPDX-License-Identifier: Apache-2.0
#include "callgrind_split.hpp"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace pednav::bench {

namespace {

enum class Part { bench, engine, plugin, system };

Part part_of(const std::string& object) {
    const size_t slash = object.rfind('/');
    const std::string base = slash == std::string::npos ? object : object.substr(slash + 1);
    if (base.rfind("libpnp_", 0) == 0) return Part::plugin;
    if (base.rfind("libpednav.so", 0) == 0) return Part::engine;
    if (base.find(".so") != std::string::npos) return Part::system;
    return Part::bench;  // the executable
}

// "(12) /path/name", "(12)" or "/path/name": the name, remembered by its id.
std::string resolve(const std::string& value, std::map<std::string, std::string>& names) {
    if (value.empty() || value[0] != '(') return value;
    const size_t close = value.find(')');
    if (close == std::string::npos) return value;
    const std::string id = value.substr(0, close + 1);
    size_t name_at = close + 1;
    while (name_at < value.size() && value[name_at] == ' ') ++name_at;
    if (name_at < value.size()) names[id] = value.substr(name_at);
    return names[id];
}

}  // namespace

InstructionSplit split_callgrind_profile(const std::string& path) {
    InstructionSplit s;
    std::ifstream in(path);
    if (!in) {
        s.error = "cannot read " + path;
        return s;
    }
    std::map<std::string, std::string> objects;
    size_t positions = 1;  // fields before the costs on a cost line
    Part current = Part::bench, callee = Part::bench;
    bool callee_set = false, call_cost_next = false;
    uint64_t bench_to_engine = 0, engine_to_plugin = 0, plugin_to_engine = 0;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (call_cost_next) {  // the line after calls=: the call's position and inclusive cost
            call_cost_next = false;
            std::istringstream fields(line);
            std::string field;
            for (size_t i = 0; i < positions && fields >> field; ++i) {
            }
            uint64_t cost = 0;
            fields >> cost;
            const Part to = callee_set ? callee : current;
            if (current == Part::bench && to == Part::engine) bench_to_engine += cost;
            if (current == Part::engine && to == Part::plugin) engine_to_plugin += cost;
            if (current == Part::plugin && to == Part::engine) plugin_to_engine += cost;
            callee_set = false;
            continue;
        }
        if (line.rfind("positions:", 0) == 0) {
            std::istringstream fields(line.substr(10));
            std::string f;
            positions = 0;
            while (fields >> f) ++positions;
        } else if (line.rfind("summary:", 0) == 0 || line.rfind("totals:", 0) == 0) {
            s.total = std::strtoull(line.c_str() + line.find(':') + 1, nullptr, 10);
        } else if (line.rfind("ob=", 0) == 0) {
            current = part_of(resolve(line.substr(3), objects));
        } else if (line.rfind("cob=", 0) == 0) {
            callee = part_of(resolve(line.substr(4), objects));
            callee_set = true;
        } else if (line.rfind("calls=", 0) == 0) {
            call_cost_next = true;
        }
    }
    if (!s.total) {
        s.error = path + " has no summary line";
        return s;
    }
    s.plugins = engine_to_plugin - plugin_to_engine;
    s.engine = bench_to_engine - s.plugins;
    s.ok = true;
    return s;
}

}  // namespace pednav::bench

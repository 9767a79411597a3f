// SPDX-License-Identifier: Apache-2.0
// The particle filter's settings; no defaults here: they live in the map
// matcher plugin's parameter schema.
#pragma once

#include <cstdint>
#include <string>

namespace pednav::map_matching {

struct ParticleFilterConfig {
    int particles;                    // N, the cloud's size (paper: 256 in corridors, 512 in halls)
    uint64_t seed;                    // same seed, same run
    double scale_min, scale_max;      // step scale s_i drawn uniform in [min, max] (paper: 0.9, 1.1)
    double init_position_sd_m;        // the first cloud around the start point, per axis
    double init_heading_sd_rad;       // heading offsets of the first cloud
    double heading_walk_sd_rad;       // heading offset random walk, per step
    double step_length_sd;            // relative noise on each particle's step length, per step
    double scale_walk_sd;             // relative random walk of each particle's step scale, per step
    double position_sd_m;             // position noise per step, per axis
    double regen_radius_m;            // Algorithm 1's Radius: new particles within it of a survivor
    int regen_tries;                  // Algorithm 1's TryTimeMax
    double regen_heading_sd_rad;      // a new particle's heading offset around the circular mean (eq. 3)
    int backtrack_steps;              // steps the backtracking test walks back
    double recovery_radius_m;         // all particles died: reseed within this of the last estimate
    double recovery_growth;           // times this per consecutive recovery
    double recovery_heading_sd_rad;   // heading offsets of a reseeded cloud around the last one
    double recovery_max_radius_m;     // the radius grows up to this
    double stall_progress;            // lost when, over the backtracking window, the cloud went less than
                                      // this share of the track's way (0 = never)
};

// Fills a config from a params view (any type with number(key) and
// integer(key)) under the keys of the struct's fields, prefixed.
template <class Params>
ParticleFilterConfig particle_filter_config(Params& v, const char* prefix = "") {
    const auto key = [prefix](const char* name) { return std::string(prefix) + name; };
    ParticleFilterConfig c;
    c.particles = static_cast<int>(v.integer(key("particles")));
    c.seed = static_cast<uint64_t>(v.integer(key("seed")));
    c.scale_min = v.number(key("scale_min"));
    c.scale_max = v.number(key("scale_max"));
    c.init_position_sd_m = v.number(key("init_position_sd_m"));
    c.init_heading_sd_rad = v.number(key("init_heading_sd_rad"));
    c.heading_walk_sd_rad = v.number(key("heading_walk_sd_rad"));
    c.step_length_sd = v.number(key("step_length_sd"));
    c.scale_walk_sd = v.number(key("scale_walk_sd"));
    c.position_sd_m = v.number(key("position_sd_m"));
    c.regen_radius_m = v.number(key("regen_radius_m"));
    c.regen_tries = static_cast<int>(v.integer(key("regen_tries")));
    c.regen_heading_sd_rad = v.number(key("regen_heading_sd_rad"));
    c.backtrack_steps = static_cast<int>(v.integer(key("backtrack_steps")));
    c.recovery_radius_m = v.number(key("recovery_radius_m"));
    c.recovery_growth = v.number(key("recovery_growth"));
    c.recovery_heading_sd_rad = v.number(key("recovery_heading_sd_rad"));
    c.recovery_max_radius_m = v.number(key("recovery_max_radius_m"));
    c.stall_progress = v.number(key("stall_progress"));
    return c;
}

}  // namespace pednav::map_matching

// SPDX-License-Identifier: Apache-2.0
#include "cmd_demo.hpp"

#include <sys/stat.h>

#include <cmath>
#include <cstdio>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/track.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_io/writers.hpp>
#include <pednav_plot/eval_plot.hpp>
#include <pednav_plot/svg.hpp>
#include <pednav_sim/simulate.hpp>

#include "cli_common.hpp"
#include "run_pipeline.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav demo [--out DIR] [--route NAME] [--seed N] [--rate HZ] [--plugin-dir DIR]\n"
    "  simulates a built-in route (default corridor_loop) with a foot-mounted IMU (default 200 Hz,\n"
    "  seed 1), runs the foot preset on it from the true start point and heading, prints the error\n"
    "  and writes DIR/{input.csv,truth.csv,track.csv,steps.csv,demo.svg} (default DIR: out/demo)\n";

}  // namespace

const char* const pednav_cmd_demo_usage = kUsage;

int pednav_cmd_demo(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    std::string out_dir = "out/demo", route_name = "corridor_loop";
    sim::SimOptions so;
    so.mount = "foot";
    so.rate_hz = 200;
    so.seed = 1;
    ReplayOptions options;
    options.plugin_dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--out") out_dir = args.value(a);
        else if (a == "--route") route_name = args.value(a);
        else if (a == "--seed") so.seed = cli::parse_count(args.value(a), a);
        else if (a == "--rate") so.rate_hz = cli::parse_numbers(args.value(a), 1, a)[0];
        else if (a == "--plugin-dir") options.plugin_dirs.push_back(args.value(a));
        else throw cli::UsageError("unknown option " + a + " for demo");
    }
    const sim::Route route = sim::builtin_route(route_name);
    std::printf("simulating %s with a foot-mounted IMU at %.0f Hz (seed %llu, consumer-grade sensor errors);\n"
                "start point and heading given\n",
                route_name.c_str(), so.rate_hz, static_cast<unsigned long long>(so.seed));
    const sim::SimOutput walk = sim::simulate(route, so);
    sim::write_outputs(walk, route, out_dir);

    options.config_json = cli::load_config("", "foot");
    options.mount = "foot";
    // Start point and heading given, as a user does with --start and --heading
    // (without them the heading comes from the magnetometer).
    for (int i = 0; i < 3; ++i) options.start_enu_m[i] = walk.truth.front().pos_enu_m[i];
    options.heading_deg = walk.truth.front().heading_deg;
    const ReplayResult r = cli::run_with_progress(options, walk.records());
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!r.error.empty()) {
        std::fprintf(stderr, "pednav demo: %s\n", r.error.c_str());
        return 1;
    }
    io::write_track_csv(out_dir + "/track.csv", r.positions);
    io::write_steps_csv(out_dir + "/steps.csv", r.strides);

    const eval::Truth truth = eval::read_sim_truth(out_dir + "/truth.csv");
    eval::Track track = eval::track_from_positions(r.positions);
    track.step_times_s = eval::step_times_from_strides(r.strides);
    track.has_steps = true;
    const eval::Metrics m = eval::evaluate(track, truth);
    std::printf("%s", eval::format_table(m).c_str());
    plot::write_text_file(out_dir + "/demo.svg",
                          plot::render_walk(plot::walk_plot("pednav demo: " + route_name + ", foot pipeline", track,
                                                            &truth, &m)));
    std::printf("walked %.1f m in %.0f s, %zu strides (truth %zu); loop closes %.2f m off (%.2f %% of distance)\n",
                walk.distance_m, walk.truth.back().t_s - walk.truth.front().t_s, r.strides.size(),
                walk.step_times_s.size(), m.loop_closure_m, m.loop_closure_pct);
    std::printf("wrote %s/{input.csv,truth.csv,track.csv,steps.csv,demo.svg}\n", out_dir.c_str());
    return 0;
}

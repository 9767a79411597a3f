// SPDX-License-Identifier: Apache-2.0
#include "cmd_report.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_foot_eval/patches.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_plot/eval_plot.hpp>
#include <pednav_plot/svg.hpp>
#include <pednav_sim/simulate.hpp>

#include "cli_common.hpp"
#include "report_suite_chest.hpp"
#include "report_suites.hpp"
#include "waist_report_suite.hpp"

namespace {

using namespace pednav;

constexpr const char* kUsage =
    "usage: pednav report --out DIR [--data DIR] [--mounts foot,chest,handheld,waist] [--only TEXT] [--seed N]\n"
    "                     [--no-recordings] [--no-sim] [--plugin-dir DIR] [--patch JSON] [--detector NAME]\n"
    "       pednav report --suite full|quick|sim|sweep|tables|hupt|clip|chest [--data DIR] [--plugin-dir DIR]\n"
    "                     [--patch JSON] [--detector NAME]\n"
    "       pednav report --suite waist [--data DIR] [--plugin-dir DIR] [--seeds N] [--only TEXT] [--patch JSON]\n"
    "                     (the waist pipeline's tables; the simulated walks of seeds 1 to N, 8 by default)\n"
    "  --data      the shared recordings (default: $PEDNAV_SHARED_DATA_DIR, ../shared/data, or next to the "
    "build)\n"
    "  --only      run only the walks whose name contains TEXT\n"
    "  --patch     a JSON merge patch applied to each mount's preset (configs/<mount>.json)\n"
    "  --detector  the foot pipeline's stance detector: shoe (the preset's) or multicondition\n"
    "  --suite     accuracy (the default) writes DIR/accuracy.md, DIR/accuracy.json and\n"
    "              DIR/plots/<mount>-<walk>.svg; the foot suites print the foot pipeline's own tables:\n"
    "              full (simulated walks at 400 Hz, then every foot recording), quick (xio and koroglu),\n"
    "              sim (simulated walks at 100, 200, 400 Hz), sweep (gaits, mountings, rates), tables\n"
    "              (koroglu, ZUPT only and with ZARU), hupt (HUPT against ZUPT only), clip (clipped gyro);\n"
    "              chest prints the chest and handheld pipelines' tables (humolire, biba, simulated walks)\n";

bool exists(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0;
}

void make_dirs(const std::string& p) {
    std::error_code ec;
    std::filesystem::create_directories(p, ec);
    if (ec) throw std::runtime_error("cannot create " + p + ": " + ec.message());
}

// One walk to run: a shared recording with its truth, or a simulated route.
struct Walk {
    std::string name, mount;
    std::string input;               // recording path (empty: simulated)
    eval::SimulatedWalk simulated;   // when input is empty
    eval::Truth truth;
    eval::Alignment alignment = eval::Alignment::start_point;
    bool give_start = false;  // start the engine at the truth's start point and heading
    double user_height_m = 0.0;  // the walker's height when the recording gives it (eval::with_user_height)
};

struct Result {
    Walk walk;
    eval::Metrics metrics;
    double duration_s = NAN;
    std::string error, plot;
};

// The walk list's recordings that are in `data`; a walk whose truth cannot be
// read is reported through `skip` and left out.
template <typename Skip>
std::vector<Walk> recording_walks(const std::string& data, Skip skip) {
    std::vector<Walk> w;
    for (const eval::RecordedWalk& recorded : eval::recorded_walks(data)) {
        if (!exists(recorded.input)) continue;
        Walk walk{recorded.name,      recorded.mount,      recorded.input,       {}, {}, recorded.alignment,
                  recorded.give_start, recorded.user_height_m};
        try {
            walk.truth = eval::read_walk_truth(recorded);
            w.push_back(std::move(walk));
        } catch (const std::exception& e) {
            skip(walk.name, e);
        }
    }
    return w;
}

Result run_walk(const Walk& walk, const std::string& config, const std::vector<std::string>& plugin_dirs) {
    Result r;
    r.walk = walk;
    ReplayOptions o;
    o.config_json = eval::with_user_height(config, walk.user_height_m);
    o.plugin_dirs = plugin_dirs;
    o.mount = walk.mount;
    std::vector<const pn_record_header_t*> records;
    io::SensorLog log;
    sim::SimOutput simulated;
    if (walk.input.empty()) {
        const sim::Route route = eval::sim_route(walk.simulated);
        simulated = sim::simulate(route, eval::sim_options(walk.simulated));
        records = simulated.records();
        r.walk.truth = eval::sim_truth(simulated, route);
        // The walker is told where it starts and which way it faces, as in an app.
        o.heading_deg = simulated.truth.front().heading_deg;
    } else {
        log = io::read_sensor_file(walk.input);
        records = io::merged_records(log);
    }
    if (walk.give_start) {
        o.start_enu_m[0] = walk.truth.start_x_m;
        o.start_enu_m[1] = walk.truth.start_y_m;
        o.heading_deg = walk.truth.start_heading_deg;
    }
    if (!records.empty())
        r.duration_s = static_cast<double>(records.back()->t_ns - records.front()->t_ns) * 1e-9;
    const ReplayResult rr = replay(o, records);
    if (!rr.error.empty()) r.error = rr.error;
    if (rr.positions.empty()) {
        if (r.error.empty()) r.error = "no positions";
        return r;
    }
    eval::Track track = eval::track_from_positions(rr.positions);
    track.step_times_s = walk.mount == "foot" && !rr.strides.empty()
                             ? eval::step_times_from_strides(rr.strides)
                             : eval::step_times_from_steps(rr.steps);
    track.has_steps = true;
    eval::EvalOptions eo;
    eo.alignment = walk.alignment;
    eo.fit_points = 5;
    r.metrics = eval::evaluate(track, r.walk.truth, eo);
    r.plot =
        plot::render_walk(plot::walk_plot(walk.mount + " / " + walk.name, track, &r.walk.truth, &r.metrics));
    return r;
}

std::string f(double v, int decimals = 2) {
    if (!std::isfinite(v)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

std::string markdown(const std::vector<Result>& results, uint64_t seed) {
    std::string md =
        "# Accuracy\n\nGenerated by `pednav report`. Every walk runs through the mount's preset "
        "(`configs/<mount>.json`) with the real plugins. Horizontal errors in metres at the truth's "
        "checkpoints (simulated walks: every 0.1 s; koroglu: every footprint, after one rotation fitted on "
        "the first 5 strides; humolire: every landmark, started at the known start point and heading). "
        "Simulated walks: `pednav sim` built-in routes, seed " +
        std::to_string(seed) +
        ", consumer-grade sensor errors, start heading given. Definitions: docs/metrics.md.\n\n";
    md +=
        "| mount | walk | truth | time (s) | distance (m) | checkpoints | mean | median | p75 | max | final "
        "| loop closure (%) | "
        "height error (m) | steps (est / truth) | legs (%) |\n";
    md += "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for (const Result& r : results) {
        const eval::Metrics& m = r.metrics;
        if (!r.error.empty() && m.checkpoints == 0 && !std::isfinite(m.loop_closure_pct) &&
            m.leg_lengths_m.empty()) {
            md += "| " + r.walk.mount + " | " + r.walk.name + " | " +
                  eval::truth_kind_name(r.walk.truth.kind) + " | " + f(r.duration_s, 0) +
                  " | failed: " + r.error + " |||||||||||\n";
            continue;
        }
        std::string legs;
        for (double e : m.leg_errors_pct) legs += (legs.empty() ? "" : ", ") + f(e, 1);
        md += "| " + r.walk.mount + " | " + r.walk.name + " | " + eval::truth_kind_name(r.walk.truth.kind) +
              " | " + f(r.duration_s, 0) + " | " + f(m.distance_m, 1) + " | " +
              std::to_string(m.checkpoints) + " | " + f(m.horizontal_m.mean) + " | " +
              f(m.horizontal_m.median) + " | " + f(m.horizontal_m.p75) + " | " + f(m.horizontal_m.max) +
              " | " + f(m.final_error_m) + " | " + f(m.loop_closure_pct, 3) + " | " +
              f(m.height_error_mean_m) + " | " + (m.step_count >= 0 ? std::to_string(m.step_count) : "-") +
              " / " + (m.truth_step_count >= 0 ? std::to_string(m.truth_step_count) : "-") + " | " +
              (legs.empty() ? "-" : legs) + " |\n";
    }
    // The papers' per-axis table and the remaining metrics, for the walks with checkpoints.
    md +=
        "\n## Per-axis differences, IPIN score, heading, height, floors\n\n"
        "| mount | walk | dx min | dx max | dx mean | dx SD | dy min | dy max | dy mean | dy SD | IPIN score "
        "(m) | "
        "heading error mean / max (deg) | height error SD (m) | floor correct (%) |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Result& r : results) {
        const eval::Metrics& m = r.metrics;
        if (m.checkpoints == 0) continue;
        md += "| " + r.walk.mount + " | " + r.walk.name + " | " + f(m.dx_m.min) + " | " + f(m.dx_m.max) +
              " | " + f(m.dx_m.mean) + " | " + f(m.dx_m.sd) + " | " + f(m.dy_m.min) + " | " + f(m.dy_m.max) +
              " | " + f(m.dy_m.mean) + " | " + f(m.dy_m.sd) + " | " + f(m.ipin_score_m) + " | " +
              (m.heading_error_deg.n ? f(m.heading_error_deg.mean, 1) + " / " + f(m.heading_error_deg.max, 1)
                                     : "-") +
              " | " + f(m.height_error_sd_m) + " | " + f(m.floor_correct_pct, 1) + " |\n";
    }
    // Percentiles across walks, per mount.
    std::map<std::string, std::map<std::string, std::vector<double>>> by_mount;
    for (const Result& r : results) {
        auto& v = by_mount[r.walk.mount];
        const eval::Metrics& m = r.metrics;
        if (std::isfinite(m.horizontal_m.mean)) v["mean horizontal error (m)"].push_back(m.horizontal_m.mean);
        if (std::isfinite(m.horizontal_m.p75)) v["p75 horizontal error (m)"].push_back(m.horizontal_m.p75);
        if (std::isfinite(m.final_error_m)) v["final error (m)"].push_back(m.final_error_m);
        if (std::isfinite(m.ipin_score_m)) v["IPIN score (m)"].push_back(m.ipin_score_m);
        if (std::isfinite(m.heading_error_deg.mean))
            v["mean heading error (deg)"].push_back(m.heading_error_deg.mean);
        if (std::isfinite(m.height_error_mean_m))
            v["height error (abs mean, m)"].push_back(std::fabs(m.height_error_mean_m));
        if (std::isfinite(m.loop_closure_pct))
            v["loop closure (% of distance)"].push_back(m.loop_closure_pct);
        for (double e : m.leg_errors_pct) v["leg length error (abs %)"].push_back(std::fabs(e));
        if (m.step_count >= 0 && m.truth_step_count > 0)
            v["step count error (abs %)"].push_back(100.0 * std::abs(m.step_count - m.truth_step_count) /
                                                    m.truth_step_count);
    }
    md +=
        "\n## Across walks\n\n| mount | metric | walks | median | p75 | p95 | max "
        "|\n|---|---|---:|---:|---:|---:|---:|\n";
    for (const auto& [mount, metrics] : by_mount)
        for (const auto& [name, v] : metrics)
            md += "| " + mount + " | " + name + " | " + std::to_string(v.size()) + " | " +
                  f(eval::percentile(v, 50), 3) + " | " + f(eval::percentile(v, 75), 3) + " | " +
                  f(eval::percentile(v, 95), 3) + " | " + f(eval::percentile(v, 100), 3) + " |\n";
    return md;
}

// One line per walk on stderr while the report runs.
std::string summary(const eval::Metrics& m) {
    std::string s;
    if (m.checkpoints > 0)
        s += "mean error " + f(m.horizontal_m.mean) + " m, p75 " + f(m.horizontal_m.p75) + " m; ";
    if (std::isfinite(m.loop_closure_pct)) s += "loop closure " + f(m.loop_closure_pct, 3) + " %; ";
    for (size_t i = 0; i < m.leg_errors_pct.size(); ++i)
        s += "leg " + std::to_string(i + 1) + " " + f(m.leg_errors_pct[i], 1) + " %; ";
    if (m.step_count >= 0)
        s += "steps " + std::to_string(m.step_count) + " / " +
             (m.truth_step_count >= 0 ? std::to_string(m.truth_step_count) : "-");
    return s;
}

std::string default_data_dir() {
    if (const char* env = std::getenv("PEDNAV_SHARED_DATA_DIR")) return env;
    if (exists("../shared/data")) return "../shared/data";
    return cli::executable_dir() + "/../../shared/data";
}

nlohmann::json parse_patch(const std::string& text) {
    nlohmann::json patch;
    try {
        patch = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw pednav::cli::UsageError(std::string("--patch: not JSON: ") + e.what());
    }
    if (!patch.is_object()) throw pednav::cli::UsageError("--patch: expected a JSON object, got " + patch.dump());
    return patch;
}

// The stance detector's patch with the user's patch merged in.
nlohmann::json foot_patch(const std::string& detector, const nlohmann::json& patch) {
    nlohmann::json p;
    try {
        p = foot_eval::detector_patch(detector);
    } catch (const std::exception& e) {
        throw pednav::cli::UsageError(std::string("--detector: ") + e.what());
    }
    p.merge_patch(patch);
    return p;
}

// pednav report --suite NAME (a foot suite): printed on stdout.
int run_suite(const std::string& suite, pednav::cli::FootSuiteSetup setup) {
    try {
        if (setup.data_dir.empty()) setup.data_dir = default_data_dir();
        if (pednav::cli::foot_suite_reads_recordings(suite) && !exists(setup.data_dir))
            throw std::runtime_error("no shared recordings at " + setup.data_dir + " (--data)");
        setup.preset_json = cli::read_text_file(cli::default_config_dir() + "/foot.json");
        pednav::cli::run_foot_suite(suite, setup);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav report: %s\n", e.what());
        return 1;
    }
}

int run_chest_suite(std::string data, const std::vector<std::string>& plugin_dirs) {
    try {
        pednav::cli::ChestSuiteSetup setup;
        setup.data_dir = data.empty() ? default_data_dir() : data;
        if (!exists(setup.data_dir)) throw std::runtime_error("no shared recordings at " + setup.data_dir + " (--data)");
        setup.chest_preset_json = cli::read_text_file(cli::default_config_dir() + "/chest.json");
        setup.handheld_preset_json = cli::read_text_file(cli::default_config_dir() + "/handheld.json");
        setup.plugin_dirs = plugin_dirs;
        pednav::cli::run_chest_suite(setup);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav report: %s\n", e.what());
        return 1;
    }
}

}  // namespace

const char* const pednav_cmd_report_usage = kUsage;

int pednav_cmd_report(const std::vector<std::string>& args) {
    std::string out, data, only, suite = "accuracy", detector, accuracy_option, not_waist_option;
    std::vector<std::string> mounts{"foot", "chest", "handheld", "waist"}, plugin_dirs{cli::default_plugin_dir()};
    uint64_t seed = 1, seeds = 0;
    bool recordings = true, simulated = true, patched = false;
    nlohmann::json patch = nlohmann::json::object();
    pednav::cli::Args in(args, kUsage);
    while (!in.done()) {
        const std::string a = in.next();
        auto value = [&] { return in.value(a); };
        if (a == "--out" || a == "--only" || a == "--seed" || a == "--no-recordings" || a == "--no-sim" ||
            a == "--mounts")
            accuracy_option = a;
        if (accuracy_option == a && a != "--only") not_waist_option = a;
        if (a == "--out")
            out = value();
        else if (a == "--data")
            data = value();
        else if (a == "--only")
            only = value();
        else if (a == "--seed")
            seed = pednav::cli::parse_count(value(), a);
        else if (a == "--seeds")
            seeds = pednav::cli::parse_count(value(), a);
        else if (a == "--plugin-dir")
            plugin_dirs.push_back(value());
        else if (a == "--no-recordings")
            recordings = false;
        else if (a == "--no-sim")
            simulated = false;
        else if (a == "--mounts") {
            mounts.clear();
            std::string list = value() + ",";
            for (size_t p = 0, q; (q = list.find(',', p)) != std::string::npos; p = q + 1)
                if (q > p) mounts.push_back(list.substr(p, q - p));
        } else if (a == "--suite")
            suite = value();
        else if (a == "--patch") {
            patch = parse_patch(value());
            patched = true;
        } else if (a == "--detector") {
            detector = value();
            patched = true;
        } else
            throw pednav::cli::UsageError("unknown option " + a);
    }
    const nlohmann::json detector_and_patch = foot_patch(detector.empty() ? "shoe" : detector, patch);
    if (seeds > 0 && suite != "waist") throw pednav::cli::UsageError("--seeds is an option of --suite waist");
    if (suite == "chest") {
        if (!accuracy_option.empty() || patched)
            throw pednav::cli::UsageError((accuracy_option.empty() ? std::string("--patch/--detector") : accuracy_option) +
                                          " is not an option of --suite chest");
        return run_chest_suite(data, plugin_dirs);
    }
    if (suite == "waist") {
        if (!not_waist_option.empty() || !detector.empty())
            throw pednav::cli::UsageError((detector.empty() ? not_waist_option : std::string("--detector")) +
                                          " is not an option of --suite waist");
        try {
            if (data.empty()) data = default_data_dir();
            if (!exists(data)) throw std::runtime_error("no shared recordings at " + data + " (--data)");
            nlohmann::json waist = nlohmann::json::parse(cli::read_text_file(cli::default_config_dir() + "/waist.json"));
            waist.merge_patch(patch);
            pednav::cli::run_waist_suite(waist.dump(), cli::read_text_file(cli::default_config_dir() + "/foot.json"),
                                         data, plugin_dirs, seeds > 0 ? seeds : 8, only);
            return 0;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "pednav report: %s\n", e.what());
            return 1;
        }
    }
    if (suite != "accuracy") {
        const auto& names = pednav::cli::foot_suite_names();
        if (std::find(names.begin(), names.end(), suite) == names.end())
            throw pednav::cli::UsageError("unknown suite '" + suite + "' (accuracy, full, quick, sim, sweep, tables, hupt, clip, chest, waist)");
        if (!accuracy_option.empty())
            throw pednav::cli::UsageError(accuracy_option + " is an option of the accuracy suite, not of --suite " + suite);
        return run_suite(suite, {"", detector.empty() ? "shoe" : detector, detector_and_patch, data, plugin_dirs});
    }
    if (out.empty()) throw pednav::cli::UsageError("--out is required");
    try {
        if (data.empty()) data = default_data_dir();
        make_dirs(out + "/plots");
        std::map<std::string, std::string> configs;
        for (const std::string& m : mounts) {
            const std::string preset = cli::default_config_dir() + "/" + m + ".json";
            if (exists(preset))
                configs[m] = patched ? eval::patched_config(cli::read_text_file(preset),
                                                            m == "foot" ? detector_and_patch : patch)
                                     : cli::read_text_file(preset);
            else
                std::fprintf(stderr, "pednav report: no preset for mount %s (%s): skipped\n", m.c_str(),
                             preset.c_str());
        }
        std::vector<Walk> walks;
        size_t failed = 0;  // walks that could not be read or run: the report is written, the exit says so
        if (recordings) {
            if (!exists(data))
                throw std::runtime_error("no shared recordings at " + data +
                                         " (--data DIR, or --no-recordings for the simulated walks only)");
            walks = recording_walks(data, [&failed](const std::string& what, const std::exception& e) {
                std::fprintf(stderr, "pednav report: %s: %s (skipped)\n", what.c_str(), e.what());
                ++failed;
            });
        }
        if (simulated)
            for (const std::string& m : mounts)
                for (const eval::SimulatedWalk& sw : eval::builtin_sim_walks(m, seed))
                    walks.push_back({"sim-" + sw.route, m, "", sw, {}, eval::Alignment::start_point, false});
        std::vector<Result> results;
        nlohmann::json js = nlohmann::json::array();
        for (const Walk& w : walks) {
            if (!configs.count(w.mount) || (!only.empty() && w.name.find(only) == std::string::npos))
                continue;
            std::fprintf(stderr, "%-6s %-28s ", w.mount.c_str(), w.name.c_str());
            Result r;
            try {
                r = run_walk(w, configs[w.mount], plugin_dirs);
            } catch (const std::exception& e) {
                r.walk = w;
                r.error = e.what();
            }
            if (!r.plot.empty()) {
                const std::string file = "plots/" + w.mount + "-" + w.name + ".svg";
                plot::write_text_file(out + "/" + file, r.plot);
                r.plot = file;
            }
            std::fprintf(stderr, "%s\n",
                         r.error.empty() ? summary(r.metrics).c_str() : ("error: " + r.error).c_str());
            nlohmann::json j = eval::to_json(r.metrics);
            j["walk"] = w.name;
            j["mount"] = w.mount;
            j["duration_s"] =
                std::isfinite(r.duration_s) ? nlohmann::json(r.duration_s) : nlohmann::json(nullptr);
            j["plot"] = r.plot;
            j["error"] = r.error;
            if (!r.error.empty()) ++failed;
            js.push_back(j);
            results.push_back(std::move(r));
        }
        plot::write_text_file(out + "/accuracy.md", markdown(results, seed));
        plot::write_text_file(out + "/accuracy.json", js.dump(2) + "\n");
        std::printf("%zu walks -> %s/accuracy.md\n", results.size(), out.c_str());
        if (failed) std::fprintf(stderr, "pednav report: %zu walk%s failed (named above)\n", failed, failed == 1 ? "" : "s");
        return failed ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav report: %s\n", e.what());
        return 1;
    }
}

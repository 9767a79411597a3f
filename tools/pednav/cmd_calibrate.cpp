// SPDX-License-Identifier: Apache-2.0
#include "cmd_calibrate.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_chest_eval/calibrated_config.hpp>
#include <pednav_eval/calibration.hpp>
#include <pednav_io/sensor_log.hpp>

#include "cli_common.hpp"
#include "run_pipeline.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav calibrate --mount chest|handheld|waist [--config CFG] --input WALK (--distance-m D | --landmarks FILE)\n"
    "                        [--input WALK (--distance-m D | --landmarks FILE) ...] --out NEW_CFG\n"
    "                        [--fit-beta] [--fit-root] [--start x,y,z] [--heading DEG] [--plugin-dir DIR]\n"
    "  --config      the config to calibrate (default: the mount's preset)\n"
    "  --input       a walk (any format pednav run reads); each is followed by its --distance-m or --landmarks\n"
    "  --distance-m  the length walked, m\n"
    "  --landmarks   a file of t,x,y (s, m, m): timed landmarks; each pair of consecutive ones is a leg of\n"
    "                known length (the straight line between them); or a humolire-phone walk folder\n"
    "  --out         the calibrated copy of the config\n"
    "  --fit-beta    step model: fit beta as well as k (walks at different paces)\n"
    "  --fit-root    step model: fit the root b too\n"
    "The position filter is calibrated by its parameter names: step_vector_k (scaled by true / estimated\n"
    "distance) or step_model_k, step_model_b, step_model_beta_m (pdr::fit_step_length over the legs).\n"
    "exit status: 0 written, 1 the walks cannot be run or fitted (the reason is printed), 2 a usage mistake\n";

struct WalkArg {
    std::string input;
    double distance_m = NAN;
    std::string landmarks;
};

}  // namespace

const char* const pednav_cmd_calibrate_usage = kUsage;

int pednav_cmd_calibrate(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    std::string mount, config_path, out;
    std::vector<WalkArg> walks;
    eval::CalibrationOptions fit;
    ReplayOptions options;
    options.plugin_dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--mount") mount = args.value(a);
        else if (a == "--config") config_path = args.value(a);
        else if (a == "--out") out = args.value(a);
        else if (a == "--input") walks.push_back({args.value(a), NAN, ""});
        else if (a == "--distance-m" || a == "--landmarks") {
            if (walks.empty()) throw cli::UsageError(a + " must follow the --input it belongs to");
            WalkArg& w = walks.back();
            if (std::isfinite(w.distance_m) || !w.landmarks.empty())
                throw cli::UsageError(w.input + " has a --distance-m or --landmarks already");
            if (a == "--distance-m") {
                w.distance_m = cli::parse_numbers(args.value(a), 1, a)[0];
                if (!(w.distance_m > 0)) throw cli::UsageError("--distance-m must be positive");
            } else {
                w.landmarks = args.value(a);
            }
        } else if (a == "--fit-beta") fit.fit_beta = true;
        else if (a == "--fit-root") fit.fit_root = true;
        else if (a == "--plugin-dir") options.plugin_dirs.push_back(args.value(a));
        else if (a == "--start") {
            const auto v = cli::parse_numbers(args.value(a), 3, a);
            for (int i = 0; i < 3; ++i) options.start_enu_m[i] = v[i];
        } else if (a == "--heading") options.heading_deg = cli::parse_numbers(args.value(a), 1, a)[0];
        else throw cli::UsageError("unknown option " + a + " for calibrate");
    }
    if (mount != "chest" && mount != "handheld" && mount != "waist")
        throw cli::UsageError("calibrate needs --mount chest, handheld or waist");
    if (walks.empty()) throw cli::UsageError("calibrate needs at least one --input");
    if (out.empty()) throw cli::UsageError("calibrate needs --out NEW_CFG");
    for (const WalkArg& w : walks)
        if (!std::isfinite(w.distance_m) && w.landmarks.empty())
            throw cli::UsageError(w.input + " needs its --distance-m or --landmarks");
    try {
        options.config_json = cli::load_config(config_path, mount);
        options.mount = mount;
        nlohmann::json config = nlohmann::json::parse(options.config_json, nullptr, false);
        if (config.is_discarded() || !config.is_object())
            throw std::runtime_error((config_path.empty() ? mount + " preset" : config_path) + ": not a JSON object");
        if (const std::string problem = config_problem(options); !problem.empty())
            throw std::runtime_error("config: " + problem);
        const nlohmann::json::json_pointer where("/pipelines/" + mount + "/position_filter/params");
        const nlohmann::json params = chest_eval::position_filter_params(config, mount, options.plugin_dirs);
        std::vector<eval::CalibrationRun> runs;
        for (const WalkArg& w : walks) {
            eval::CalibrationRun run;
            run.name = w.input;
            run.legs = w.landmarks.empty() ? std::vector<eval::CalibrationLeg>{eval::whole_walk_leg(w.distance_m)}
                                           : eval::landmark_legs(w.landmarks);
            const io::SensorLog log = io::read_sensor_file(w.input);
            const ReplayResult r = cli::run_with_progress(options, io::merged_records(log));
            if (!r.error.empty()) throw std::runtime_error(w.input + ": " + r.error);
            run.strides = r.strides;
            run.steps = r.steps;
            std::fprintf(stderr, "%s: %zu steps, %zu strides\n", w.input.c_str(), r.steps.size(), r.strides.size());
            runs.push_back(std::move(run));
        }
        const eval::CalibrationResult result = eval::calibrate_position_filter(params, runs, fit);
        for (const auto& [key, value] : result.params.items()) config[where][key] = value;
        std::ofstream file(out);
        file << config.dump(2) << "\n";
        if (!file) throw std::runtime_error("cannot write " + out);
        std::printf("%s\n", result.summary.c_str());
        for (size_t i = 0; i < result.relative_errors_after.size(); ++i)
            std::printf("leg %zu: distance error %+.1f %% -> %+.1f %%\n", i + 1, 100 * result.relative_errors_before[i],
                        100 * result.relative_errors_after[i]);
        std::printf("-> %s\n", out.c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav calibrate: %s\n", e.what());
        return 1;
    }
}

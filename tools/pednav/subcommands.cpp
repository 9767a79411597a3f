// SPDX-License-Identifier: Apache-2.0
#include "subcommands.hpp"

#include "cmd_calibrate.hpp"
#include "cmd_demo.hpp"
#include "cmd_eval.hpp"
#include "cmd_inspect.hpp"
#include "cmd_map.hpp"
#include "cmd_plugins.hpp"
#include "cmd_report.hpp"
#include "cmd_run.hpp"
#include "cmd_sim.hpp"
#include "cmd_validate.hpp"

const std::vector<PednavSubcommand>& pednav_subcommands() {
    static const std::vector<PednavSubcommand> table = {
        {"demo", &pednav_cmd_demo, pednav_cmd_demo_usage,
         "simulate a foot walk, run the foot pipeline, print its error, plot it"},
        {"run", &pednav_cmd_run, pednav_cmd_run_usage, "run a recording through a mount's pipeline"},
        {"plugins", &pednav_cmd_plugins, pednav_cmd_plugins_usage, "plugins loaded and files rejected"},
        {"inspect", &pednav_cmd_inspect, pednav_cmd_inspect_usage, "what the engine sees in a recording"},
        {"sim", &pednav_cmd_sim, pednav_cmd_sim_usage, "simulate a walk: engine input, truth, GNSS, map"},
        {"eval", &pednav_cmd_eval, pednav_cmd_eval_usage, "score a track against a ground truth"},
        {"map", &pednav_cmd_map, pednav_cmd_map_usage, "check a map, convert floor plans to one"},
        {"report", &pednav_cmd_report, pednav_cmd_report_usage,
         "accuracy of every recording and simulated walk"},
        {"calibrate", &pednav_cmd_calibrate, pednav_cmd_calibrate_usage,
         "fit a step position filter's constants to walks of known length"},
        {"validate", &pednav_cmd_validate, pednav_cmd_validate_usage,
         "the conformance checks every plugin library must pass"},
    };
    return table;
}

// SPDX-License-Identifier: Apache-2.0
#include "cmd_eval.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth_readers.hpp>

#include "cli_common.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav eval --track FILE --truth PATH [--kind KIND] [--align MODE] [--fit-points N]\n"
    "                   [--steps FILE] [--json]\n"
    "  --track   the track CSV written by pednav run (t,x,y,z,heading_deg,floor,...)\n"
    "  --truth   truth file or folder; --kind auto (default), sim, koroglu, humolire, ipin, ipol,\n"
    "            loop or loop:LENGTH_M (closed loop: --truth is then ignored)\n"
    "  --align   none, start, first-segment or fitted (default: fitted for koroglu, none for ipin,\n"
    "            start otherwise); --fit-points N checkpoints for fitted (default 5, 0 = all)\n"
    "  --steps   step events CSV (time in the first column) to compare step counts\n";

}  // namespace

const char* const pednav_cmd_eval_usage = kUsage;

int pednav_cmd_eval(const std::vector<std::string>& args) {
    using namespace pednav::eval;
    std::string track_path, truth_path, kind = "auto", align_name, steps_path;
    bool json = false;
    EvalOptions options;
    pednav::cli::Args in(args, kUsage);
    while (!in.done()) {
        const std::string a = in.next();
        auto value = [&] { return in.value(a); };
        if (a == "--track")
            track_path = value();
        else if (a == "--truth")
            truth_path = value();
        else if (a == "--kind")
            kind = value();
        else if (a == "--align")
            align_name = value();
        else if (a == "--fit-points")
            options.fit_points = static_cast<size_t>(pednav::cli::parse_count(value(), a));
        else if (a == "--steps")
            steps_path = value();
        else if (a == "--json")
            json = true;
        else
            throw pednav::cli::UsageError("unknown option " + a);
    }
    if (track_path.empty()) throw pednav::cli::UsageError("--track is required");
    if (truth_path.empty() && kind.rfind("loop", 0) != 0)
        throw pednav::cli::UsageError("--truth is required");
    try {
        Track track = read_track_csv(track_path);
        if (!steps_path.empty()) {
            track.step_times_s = read_step_times_csv(steps_path);
            track.has_steps = true;
        }
        const Truth truth = read_truth(truth_path, kind);
        if (!align_name.empty())
            options.alignment = parse_alignment(align_name);
        else if (truth.kind == TruthKind::footprints)
            options.alignment = Alignment::fitted;
        else if (truth.kind == TruthKind::ipin_posi)
            options.alignment = Alignment::none;
        else
            options.alignment = Alignment::start_point;
        const Metrics m = evaluate(track, truth, options);
        if (json)
            std::printf("%s\n", to_json(m).dump(2).c_str());
        else
            std::fputs(format_table(m).c_str(), stdout);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav eval: %s\n", e.what());
        return 1;
    }
}

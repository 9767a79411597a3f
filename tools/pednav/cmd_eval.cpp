// SPDX-License-Identifier: Apache-2.0
#include "cmd_eval.hpp"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/wall_crossings.hpp>
#include <pednav_plot/eval_plot.hpp>

#include "cli_common.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav eval --track FILE --truth PATH [--kind KIND] [--align MODE] [--fit-points N]\n"
    "                   [--steps FILE] [--json] [--map FILE.geojson] [--origin lat,lon,height]\n"
    "                   [--plot FILE.svg]\n"
    "  --track   the track CSV written by pednav run (t,x,y,z,heading_deg,floor,...)\n"
    "  --truth   truth file or folder; --kind auto (default), sim, koroglu, humolire, ipin, ipol,\n"
    "            loop or loop:LENGTH_M (closed loop: --truth is then ignored)\n"
    "  --align   none, start, first-segment or fitted (default: fitted for koroglu, none for ipin,\n"
    "            start otherwise); --fit-points N checkpoints for fitted (default 5, 0 = all)\n"
    "  --steps   step events CSV (time in the first column) to compare step counts\n"
    "  --map     a map (pednav.map/1): counts the steps of the aligned track through its walls;\n"
    "            --origin for a WGS-84 map (default: the map's own)\n"
    "  --plot    the track over the truth and the walls, and its error against time, as SVG; with\n"
    "            --map, over the map instead, one panel per floor, with its stairs and landmarks\n";

}  // namespace

const char* const pednav_cmd_eval_usage = kUsage;

int pednav_cmd_eval(const std::vector<std::string>& args) {
    using namespace pednav::eval;
    std::string track_path, truth_path, kind = "auto", align_name, steps_path, plot_path, map_path;
    std::optional<pednav::geodesy::GeodeticPoint> origin;
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
        else if (a == "--plot")
            plot_path = value();
        else if (a == "--map")
            map_path = value();
        else if (a == "--origin") {
            const std::vector<double> v = pednav::cli::parse_numbers(value(), 3, a);
            origin = pednav::geodesy::GeodeticPoint{v[0], v[1], v[2]};
        }
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
        // With a map: the aligned track's steps through its walls.
        std::string map_doc;
        pednav::indoor_map::Map map;
        size_t crossings = 0;
        if (!map_path.empty()) {
            map_doc = pednav::cli::read_text_file(map_path);
            map = pednav::indoor_map::read_geojson_map(map_doc, origin);
            const Track aligned = apply_alignment(track, m.alignment);
            std::vector<pednav::indoor_map::Point2> points;
            std::vector<int> floors;
            for (const TrackSample& t : aligned.samples) {
                points.push_back({t.pos_m[0], t.pos_m[1]});
                floors.push_back(t.has_floor ? t.floor : 0);
            }
            crossings = pednav::indoor_map::wall_crossings(map, points, floors).size();
        }
        if (json) {
            nlohmann::json j = to_json(m);
            if (!map_path.empty()) j["wall_crossings"] = crossings;
            std::printf("%s\n", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
        } else {
            std::fputs(format_table(m).c_str(), stdout);
            if (!map_path.empty()) std::printf("  wall crossings of the track        %zu\n", crossings);
        }
        if (!plot_path.empty()) {
            const std::string title = track_path;
            if (map_path.empty())
                pednav::plot::write_text_file(plot_path, pednav::plot::render_walk(pednav::plot::walk_plot(title, track, &truth, &m)));
            else
                pednav::plot::write_text_file(
                    plot_path, pednav::plot::render_map_panels(
                                   title, pednav::plot::walk_floor_panels(track, &truth, &m, map,
                                                                          pednav::plot::landmark_names(map_doc, map))));
        }
        return 0;
    } catch (const pednav::indoor_map::MapError& e) {
        std::fprintf(stderr, "pednav eval: %s:%s: %s\n", map_path.c_str(), e.pointer.c_str(), e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav eval: %s\n", e.what());
        return 1;
    }
}

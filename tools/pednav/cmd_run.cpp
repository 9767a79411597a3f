// SPDX-License-Identifier: Apache-2.0
#include "cmd_run.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>
#include <pednav_io/origin.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_io/writers.hpp>

#include "cli_common.hpp"
#include "run_pipeline.hpp"
#include "run_plot.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav run --mount foot|chest|waist --input FILE [--config FILE] [--format NAME]\n"
    "                  [--output track.csv] [--steps FILE] [--start x,y,z] [--heading DEG]\n"
    "                  [--geojson FILE] [--gpx FILE] [--summary FILE] [--plot FILE.svg]\n"
    "                  [--column-map FILE.json] [--origin lat,lon,height] [--map FILE.geojson]\n"
    "                  [--plugin-dir DIR]\n"
    "  --config  a pednav-config/1 file instead of the mount's preset (configs/<mount>.json)\n"
    "  --format  the input format (default auto: detected); --column-map for any other CSV\n"
    "  --start, --heading  the start point (m) and heading (deg clockwise from north), when known\n"
    "  --origin  the geodetic origin (WGS-84 of ENU 0,0,0, the start point by default): given to the\n"
    "            engine and used by --geojson and --gpx\n"
    "  --map     a map (GeoJSON, docs/maps.md) for the pipeline's map matcher; --plot then draws the\n"
    "            track over it, one panel per floor\n"
    "exit status: 0 done, 1 an error (or plugin failures: outputs still written), 2 a usage mistake\n";

}  // namespace

const char* const pednav_cmd_run_usage = kUsage;

int pednav_cmd_run(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    std::string mount, config_path, input, format = "auto", output, steps, geojson, gpx, summary, plot, column_map_path,
        map_path;
    io::Origin origin;
    ReplayOptions options;
    options.plugin_dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--mount") mount = args.value(a);
        else if (a == "--config") config_path = args.value(a);
        else if (a == "--input") input = args.value(a);
        else if (a == "--format") format = args.value(a);
        else if (a == "--output") output = args.value(a);
        else if (a == "--steps") steps = args.value(a);
        else if (a == "--geojson") geojson = args.value(a);
        else if (a == "--gpx") gpx = args.value(a);
        else if (a == "--summary") summary = args.value(a);
        else if (a == "--plot") plot = args.value(a);
        else if (a == "--column-map") column_map_path = args.value(a);
        else if (a == "--map") map_path = args.value(a);
        else if (a == "--origin") {
            const auto v = cli::parse_numbers(args.value(a), 3, a);
            if (std::fabs(v[0]) > 90 || std::fabs(v[1]) > 180)
                throw cli::UsageError("--origin latitude must be within 90 deg and longitude within 180 deg");
            origin.lat_deg = v[0];
            origin.lon_deg = v[1];
            origin.height_m = v[2];
            origin.known = true;
        }
        else if (a == "--plugin-dir") options.plugin_dirs.push_back(args.value(a));
        else if (a == "--start") {
            const auto v = cli::parse_numbers(args.value(a), 3, a);
            for (int i = 0; i < 3; ++i) options.start_enu_m[i] = v[i];
        } else if (a == "--heading") {
            options.heading_deg = cli::parse_numbers(args.value(a), 1, a)[0];
        } else {
            throw cli::UsageError("unknown option " + a + " for run");
        }
    }
    if (input.empty()) throw cli::UsageError("run needs --input FILE");
    if (mount.empty() && config_path.empty())
        throw cli::UsageError("run needs --mount foot|chest|handheld|waist or --config FILE");
    if (!mount.empty() && mount != "foot" && mount != "chest" && mount != "handheld" && mount != "waist")
        throw cli::UsageError("--mount must be foot, chest, handheld or waist, not " + mount);

    options.config_json = cli::load_config(config_path, mount.empty() ? "foot" : mount);
    options.mount = mount;
    if (origin.known || !map_path.empty()) {  // the options win over the config's own
        nlohmann::json doc = nlohmann::json::parse(options.config_json, nullptr, false);
        if (doc.is_discarded() || !doc.is_object()) throw std::runtime_error("config: not a JSON object");
        if (origin.known)
            doc["origin"] = {{"lat_deg", origin.lat_deg}, {"lon_deg", origin.lon_deg}, {"height_m", origin.height_m}};
        if (!map_path.empty()) doc["map"] = {{"path", map_path}};
        options.config_json = doc.dump();
    }

    // The config is checked (and its plugins created) before the input is read.
    if (const std::string problem = config_problem(options); !problem.empty())
        throw std::runtime_error("config: " + problem);

    // Reader settings: the config's "input" object ({"format": ..., "column_map": {...}},
    // checked by the engine with the rest of the config), overridden by --format and --column-map.
    io::ReadOptions ro;
    nlohmann::json column_map;
    const nlohmann::json config_doc = nlohmann::json::parse(options.config_json);
    if (const auto in = config_doc.find("input"); in != config_doc.end()) {
        ro.format = in->value("format", std::string());
        if (in->contains("column_map")) {
            column_map = (*in)["column_map"];
            ro.column_map = &column_map;
        }
    }
    if (format != "auto") ro.format = format;
    if (!column_map_path.empty()) {
        column_map = nlohmann::json::parse(cli::read_text_file(column_map_path), nullptr, false);
        if (column_map.is_discarded()) throw std::runtime_error(column_map_path + " is not valid JSON");
        ro.column_map = &column_map;
        if (format == "auto") ro.format = "column-map";
    }
    const io::SensorLog log = io::read_sensor_file(input, ro);
    if (!origin.known && log.truth_origin.known) origin = log.truth_origin;
    for (const auto& n : log.notes) std::fprintf(stderr, "input: %s\n", n.c_str());
    size_t shown = 0;
    for (const auto& i : log.issues)
        if (shown++ < 20) std::fprintf(stderr, "input: line %zu: %s\n", i.line, i.message.c_str());
    const size_t issue_count = log.issues.size() + log.issues_not_listed;
    if (issue_count > 20) std::fprintf(stderr, "input: ... %zu issues in all\n", issue_count);

    const ReplayResult r = cli::run_with_progress(options, io::merged_records(log));
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!r.error.empty()) {
        std::fprintf(stderr, "pednav run: %s\n", r.error.c_str());
        return 1;
    }
    if (!output.empty()) io::write_track_csv(output, r.positions);
    if (!steps.empty()) io::write_steps_csv(steps, r.strides);
    if (!geojson.empty()) io::write_geojson(geojson, r.positions, r.strides, origin);
    if (!gpx.empty()) io::write_gpx(gpx, r.positions, origin);
    if (!summary.empty()) {
        std::ofstream out(summary);
        out << io::run_summary_json(log, r.describe_json, r.positions, r.strides, r.warnings).dump(2) << "\n";
        if (!out) throw std::runtime_error("cannot write " + summary);
    }
    if (!plot.empty()) {
        std::optional<geodesy::GeodeticPoint> map_origin;
        if (origin.known) map_origin = geodesy::GeodeticPoint{origin.lat_deg, origin.lon_deg, origin.height_m};
        cli::write_run_plot(plot, input, r, map_path, map_origin);
    }
    if (r.plugin_failures > 0) {
        // The outputs are written, but the run did not do its job cleanly.
        std::fprintf(stderr, "pednav run: %llu plugin failure%s (see the warnings above); outputs written\n",
                     static_cast<unsigned long long>(r.plugin_failures), r.plugin_failures == 1 ? "" : "s");
    }
    const pn_position_t* last = r.positions.empty() ? nullptr : &r.positions.back();
    std::printf("samples %zu, positions %zu, steps %zu, distance %.2f m, latency %.3f s\n", log.imu.size(),
                r.positions.size(), r.strides.size() ? r.strides.size() : r.steps.size(),
                io::track_length_m(r.positions), static_cast<double>(r.latency_ns) * 1e-9);
    if (last)
        std::printf("final position x %.3f m, y %.3f m, z %.3f m, heading %.1f deg\n", last->pos_enu_m[0],
                    last->pos_enu_m[1], last->pos_enu_m[2], last->heading_rad * 180.0 / M_PI);
    return r.plugin_failures > 0 ? 1 : 0;
}

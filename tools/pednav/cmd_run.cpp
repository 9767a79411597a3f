// SPDX-License-Identifier: Apache-2.0
#include "cmd_run.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>
#include <pednav_io/gnss_log.hpp>
#include <pednav_io/origin.hpp>
#include <pednav_io/record_stream.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_io/writers.hpp>

#include "cli_common.hpp"
#include "run_outputs.hpp"
#include "run_pipeline.hpp"
#include "run_plot.hpp"
#include "pednav_strict_json/strict_json.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav run --mount foot|chest|waist --input FILE [--config FILE] [--format NAME]\n"
    "                  [--output track.csv] [--steps FILE] [--start x,y,z] [--heading DEG]\n"
    "                  [--geojson FILE [--geojson-points]] [--gpx FILE] [--geo-csv FILE]\n"
    "                  [--summary FILE] [--plot FILE.svg]\n"
    "                  [--column-map FILE.json] [--rate HZ] [--origin lat,lon,height] [--map FILE.geojson]\n"
    "                  [--plugin-dir DIR] [--gnss FILE [--gnss-format auto|nmea|csv] [--gnss-t0 S]\n"
    "                  [--gnss-utc0 UTC] [--gnss-uere M]]\n"
    "  --config  a pednav-config/1 file instead of the mount's preset (configs/<mount>.json)\n"
    "  --format  the input format (default auto: detected); --column-map for any other CSV\n"
    "  --rate    the sample rate (Hz) of a packet-counter time column (Xsens PacketCounter without\n"
    "            SampleTimeFine); wins over a rate in the file's preamble\n"
    "  --gnss    GNSS fixes (NMEA 0183 or a t,lat,lon,... CSV) merged with the input in time order,\n"
    "            in place of the input's own; NMEA times go on the input's clock by --gnss-utc0 (the\n"
    "            UTC of t = 0: Unix seconds or 2024-05-01T10:00:00Z) or --gnss-t0 (the t of the\n"
    "            file's first epoch; default the input's first sample: the logs started together)\n"
    "  --gnss-uere  range error (m, 1 sigma) scaling HDOP/VDOP when the NMEA has no GST (default 5)\n"
    "  --start, --heading  the start point (m) and heading (deg clockwise from north), when known\n"
    "  --origin  the geodetic origin (WGS-84 of ENU 0,0,0, the start point by default): given to the\n"
    "            engine and used by --geojson, --gpx and --geo-csv (default: the engine's own, e.g.\n"
    "            from the first good GNSS fix)\n"
    "  --geo-csv the track in latitude/longitude: t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m\n"
    "  --geojson-points  a Point per position (0.1 s apart) with its source, floor, heading and sigma\n"
    "  --map     a map (GeoJSON, docs/maps.md) for the pipeline's map matcher; --plot then draws the\n"
    "            track over it, one panel per floor\n"
    "exit status: 0 done, 1 an error (or plugin failures: outputs still written), 2 a usage mistake\n";

// A reader's notes and its first issues on stderr, each line prefixed by `what`.
void print_read_messages(const char* what, const pednav::io::SensorLog& log) {
    for (const auto& n : log.notes) std::fprintf(stderr, "%s: %s\n", what, n.c_str());
    size_t shown = 0;
    for (const auto& i : log.issues)
        if (shown++ < 20) std::fprintf(stderr, "%s: line %zu: %s\n", what, i.line, i.message.c_str());
    const size_t issue_count = log.issues.size() + log.issues_not_listed;
    if (issue_count > 20) std::fprintf(stderr, "%s: ... %zu issues in all\n", what, issue_count);
}

namespace io = pednav::io;
using pednav::ReplaySession;

// What was pushed of the input.
struct InputRun {
    size_t records_pushed = 0;
    std::vector<pn_gnss_t> input_gnss;  // the input's own GNSS fixes (for the GeoJSON and the summary)
    std::string read_error;             // the input went bad here; what was read before is run
};

void show_progress(const io::RecordStream& stream, bool done) {
    const uint64_t total = stream.bytes_total();
    pednav::cli::progress_bar(static_cast<size_t>(done ? total : stream.bytes_read()), static_cast<size_t>(total),
                              nullptr);
}

// Reads the input a block at a time and pushes it, merged in time order with
// `fixes` (given with --gnss, in place of the input's own GNSS records).
InputRun push_input(io::RecordStream& stream, const std::vector<pn_gnss_t>* fixes, ReplaySession& session) {
    constexpr size_t kBlockRecords = 4096;
    // A bar for files that take a while to read, when stderr is a terminal.
    const bool progress = isatty(2) && stream.bytes_total() > (uint64_t{16} << 20);
    InputRun run;
    std::vector<io::InputRecord> block;
    std::vector<const pn_record_header_t*> records;
    size_t next_fix = 0;
    try {
        while (stream.read(block, kBlockRecords) > 0) {
            records.clear();
            for (const io::InputRecord& r : block) {
                if (r.header.type == PN_REC_GNSS) {
                    if (fixes != nullptr) continue;
                    run.input_gnss.push_back(r.gnss);
                }
                // At equal times the input's records come first (IMU, MAG, BARO, then GNSS).
                while (fixes != nullptr && next_fix < fixes->size() && (*fixes)[next_fix].header.t_ns < r.header.t_ns)
                    records.push_back(&(*fixes)[next_fix++].header);
                records.push_back(&r.header);
            }
            session.push(records.data(), records.size());
            run.records_pushed += records.size();
            block.clear();
            if (progress) show_progress(stream, false);
        }
    } catch (const io::ReadError& e) {
        run.read_error = e.what();
    }
    records.clear();
    while (fixes != nullptr && next_fix < fixes->size()) records.push_back(&(*fixes)[next_fix++].header);
    session.push(records.data(), records.size());
    run.records_pushed += records.size();
    if (progress) show_progress(stream, true);
    return run;
}

}  // namespace

const char* const pednav_cmd_run_usage = kUsage;

int pednav_cmd_run(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    std::string mount, config_path, input, format = "auto", output, steps, geojson, gpx, geo_csv, summary, plot,
        column_map_path,
        map_path, gnss_path;
    io::GnssReadOptions gnss_options;
    bool gnss_t0_given = false, geojson_points = false;
    double counter_rate_hz = 0.0;
    io::Origin origin;
    ReplayOptions options;
    options.plugin_dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--mount") mount = args.value(a);
        else if (a == "--config") config_path = args.value(a);
        else if (a == "--input") input = args.value(a);
        else if (a == "--format") format = args.value(a);
        else if (a == "--rate") counter_rate_hz = cli::parse_positive_rate(args.value(a), a);
        else if (a == "--output") output = args.value(a);
        else if (a == "--steps") steps = args.value(a);
        else if (a == "--geojson") geojson = args.value(a);
        else if (a == "--gpx") gpx = args.value(a);
        else if (a == "--geo-csv") geo_csv = args.value(a);
        else if (a == "--geojson-points") geojson_points = true;
        else if (a == "--summary") summary = args.value(a);
        else if (a == "--plot") plot = args.value(a);
        else if (a == "--column-map") column_map_path = args.value(a);
        else if (a == "--map") map_path = args.value(a);
        else if (a == "--gnss") gnss_path = args.value(a);
        else if (a == "--gnss-format") gnss_options.format = args.value(a);
        else if (a == "--gnss-t0") {
            gnss_options.time.first_epoch_t_s = cli::parse_numbers(args.value(a), 1, a)[0];
            gnss_t0_given = true;
        } else if (a == "--gnss-utc0") {
            const std::string v = args.value(a);
            if (!io::parse_utc(v, &gnss_options.time.utc_ns_at_zero))
                throw cli::UsageError("--gnss-utc0 takes Unix seconds or an ISO 8601 UTC time such as "
                                      "2024-05-01T10:00:00Z, not " + v);
        } else if (a == "--gnss-uere") {
            gnss_options.uere_m = cli::parse_numbers(args.value(a), 1, a)[0];
            if (!(gnss_options.uere_m > 0.0 && gnss_options.uere_m < 1000.0))
                throw cli::UsageError("--gnss-uere must be within 0 .. 1000 m");
        }
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
    if (geojson_points && geojson.empty()) throw cli::UsageError("--geojson-points goes with --geojson FILE");
    if (gnss_path.empty() && (gnss_options.format != "auto" || gnss_t0_given || gnss_options.time.utc_ns_at_zero))
        throw cli::UsageError("--gnss-format, --gnss-t0 and --gnss-utc0 go with --gnss FILE");
    if (gnss_options.format != "auto" && gnss_options.format != "nmea" && gnss_options.format != "csv")
        throw cli::UsageError("--gnss-format must be auto, nmea or csv, not " + gnss_options.format);
    if (mount.empty() && config_path.empty())
        throw cli::UsageError("run needs --mount foot|chest|handheld|waist or --config FILE");
    if (!mount.empty() && mount != "foot" && mount != "chest" && mount != "handheld" && mount != "waist")
        throw cli::UsageError("--mount must be foot, chest, handheld or waist, not " + mount);

    options.config_json = cli::load_config(config_path, mount.empty() ? "foot" : mount);
    options.mount = mount;
    if (origin.known || !map_path.empty()) {  // the options win over the config's own
        nlohmann::json doc = strict_json::parse(options.config_json);  // checked by load_config
        if (!doc.is_object()) throw std::runtime_error("config: not a JSON object");
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
    ro.counter_rate_hz = counter_rate_hz;
    if (!column_map_path.empty()) {
        column_map = nlohmann::json::parse(cli::read_text_file(column_map_path), nullptr, false);
        if (column_map.is_discarded()) throw std::runtime_error(column_map_path + " is not valid JSON");
        ro.column_map = &column_map;
        if (format == "auto") ro.format = "column-map";
    }
    io::RecordStream stream(input, ro);
    io::SensorLog gnss_log;
    if (!gnss_path.empty()) {
        int64_t t0_ns = 0;
        if (!gnss_t0_given && stream.first_imu_t_ns(&t0_ns))
            gnss_options.time.first_epoch_t_s = static_cast<double>(t0_ns) * 1e-9;
        gnss_log = io::read_gnss_file(gnss_path, gnss_options);
        print_read_messages("gnss", gnss_log);
    }

    // What the outputs written at the end need is kept; the CSVs are written as the run goes.
    cli::RunOutputPlan plan;
    plan.track_csv = output;
    plan.steps_csv = steps;
    plan.geo_csv = geo_csv;
    if (origin.known) plan.geo_origin = origin;
    plan.log_positions = !geojson.empty() || !gpx.empty() || (!geo_csv.empty() && !origin.known);
    plan.keep_positions = !plot.empty();
    plan.keep_strides = !geojson.empty() || !plot.empty();
    cli::RunOutputs outputs(plan);
    ReplaySession session(options, &outputs);
    if (!session.ok()) {
        std::fprintf(stderr, "pednav run: %s\n", session.result().error.c_str());
        return 1;
    }
    const InputRun in = push_input(stream, gnss_path.empty() ? nullptr : &gnss_log.gnss, session);
    ReplayResult& r = session.finish();
    const bool computed = in.records_pushed > 0;
    outputs.close(in.read_error.empty());

    io::SensorLog log = stream.log();
    log.gnss = in.input_gnss;
    print_read_messages("input", log);
    if (!gnss_path.empty()) {
        io::use_gnss(log, gnss_log);
        std::fprintf(stderr, "input: %s\n", log.notes.back().c_str());
    }
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!in.read_error.empty()) {
        std::fprintf(stderr, "pednav run: %s\n", in.read_error.c_str());
        if (!computed) return 1;
        std::fprintf(stderr, "pednav run: the outputs of the %zu records read before it are written\n",
                     in.records_pushed);
    }
    // Latitude and longitude: the --origin given, else the engine's own (the
    // config's, a map's or its first good GNSS fix), else the truth points' frame.
    if (!origin.known && r.has_origin) {
        origin.lat_deg = r.origin.lat_deg;
        origin.lon_deg = r.origin.lon_deg;
        origin.height_m = r.origin.height_m;
        origin.known = true;
    }
    if (!origin.known && log.truth_origin.known) origin = log.truth_origin;
    if (origin.utc_ns_at_zero == 0) origin.utc_ns_at_zero = log.utc_ns_at_zero;
    r.positions = std::move(outputs.positions());
    r.strides = std::move(outputs.strides());
    if (!geojson.empty()) {
        io::GeoJsonExtras extras;
        extras.position_points = geojson_points;
        if (!log.gnss.empty()) extras.gnss_fixes = &log.gnss;
        io::write_geojson(geojson, outputs.position_log(), r.strides, origin, extras);
    }
    if (!gpx.empty()) io::write_gpx(gpx, outputs.position_log(), origin);
    if (!geo_csv.empty() && !plan.geo_origin.known) io::write_geo_track_csv(geo_csv, outputs.position_log(), origin);
    if (!summary.empty()) {
        std::ofstream out(summary);
        nlohmann::json j = io::run_summary_json(log, r.describe_json, outputs.totals(), r.warnings);
        if (!gnss_path.empty()) j["gnss_input"] = io::sensor_log_json(gnss_log);
        out << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
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
    const io::RunTotals& totals = outputs.totals();
    std::printf("samples %zu, positions %zu, steps %zu, distance %.2f m, latency %.3f s\n", log.records.imu,
                totals.positions, totals.strides ? totals.strides : outputs.steps(), totals.distance_m,
                static_cast<double>(r.latency_ns) * 1e-9);
    if (totals.positions > 0) {
        const pn_position_t& last = totals.last;
        std::printf("final position x %.3f m, y %.3f m, z %.3f m, heading %.1f deg\n", last.pos_enu_m[0],
                    last.pos_enu_m[1], last.pos_enu_m[2], last.heading_rad * 180.0 / M_PI);
    }
    return r.plugin_failures > 0 || !in.read_error.empty() ? 1 : 0;
}

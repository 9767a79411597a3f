// SPDX-License-Identifier: Apache-2.0
#include "cmd_inspect.hpp"

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>
#include <pednav_io/gnss_log.hpp>
#include <pednav_io/record_stream.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_io/writers.hpp>

#include "cli_common.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav inspect FILE [--json] [--format NAME] [--column-map FILE.json] [--gap S] [--rate HZ]\n"
    "                      [--gnss FILE [--gnss-format auto|nmea|csv]]\n"
    "  what the engine sees in a recording: format, axes, streams and rates, units, gaps, issues;\n"
    "  FILE may also be a GNSS file (NMEA 0183 or a t,lat,lon,... CSV), detected when no other\n"
    "  format matches\n"
    "  --format  the input format (default auto: detected); --column-map for any other CSV\n"
    "  --gap     intervals longer than S seconds are reported as gaps (default 1)\n"
    "  --rate    the sample rate (Hz) of a packet-counter time column (Xsens PacketCounter without\n"
    "            SampleTimeFine); wins over a rate in the file's preamble\n"
    "  --gnss    a GNSS file read as `pednav run --gnss` reads it (NMEA's first epoch at the\n"
    "            input's first sample), shown after the input\n";

void print_text(const pednav::io::SensorLog& log, bool forced) {
    std::printf("file    %s\n", log.path.c_str());
    std::printf("format  %s (%s)\n", log.format.c_str(), forced ? "as requested" : "detected");
    std::printf("axes    %s\n", log.axes.c_str());
    std::printf("\n%-9s %9s %10s %10s %11s %10s  %-34s %5s %8s\n", "stream", "count", "rate_hz", "median_hz",
                "duration_s", "start_s", "units (file -> engine)", "gaps", "bad_rows");
    for (const auto& s : log.streams) {
        const std::string units = s.units_found.empty() ? "-" : s.units_found + " -> " + s.units_converted;
        std::printf("%-9s %9zu %10.3f %10.3f %11.3f %10.3f  %-34s %5zu %8zu\n", s.name.c_str(), s.count,
                    s.rate_hz, s.median_rate_hz, s.duration_s, s.t_first_s, units.c_str(), s.gaps,
                    s.bad_rows);
    }
    std::printf("\nrecords: %zu IMU, %zu magnetometer, %zu barometer, %zu GNSS, %zu ground truth\n",
                log.records.imu, log.records.mag, log.records.baro, log.records.gnss, log.truth.size());
    if (!log.notes.empty()) {
        std::printf("\nnotes:\n");
        for (const auto& n : log.notes) std::printf("  %s\n", n.c_str());
    }
    std::printf("\nissues: %zu\n", log.issues.size() + log.issues_not_listed);
    for (const auto& i : log.issues) {
        if (i.line > 0)
            std::printf("  line %zu: %s\n", i.line, i.message.c_str());
        else
            std::printf("  %s\n", i.message.c_str());
    }
    if (log.issues_not_listed > 0) std::printf("  ... %zu more issues not listed\n", log.issues_not_listed);
    if (!log.gnss.empty()) {
        const nlohmann::json g = pednav::io::gnss_fixes_json(log.gnss);
        std::printf("\ngnss fixes: %zu, %zu with velocity; fix types %s\n", log.gnss.size(),
                    g["with_velocity"].get<size_t>(), g["fix_types"].dump().c_str());
        std::printf("  satellites min/median/max %s, horizontal accuracy median %.2f m, max %.2f m\n",
                    g["satellites"].dump().c_str(), g["h_accuracy_m"]["median"].get<double>(),
                    g["h_accuracy_m"]["max"].get<double>());
        if (!g["utc_first"].is_null())
            std::printf("  UTC of the first fix: %s\n", g["utc_first"].get<std::string>().c_str());
    }
}

// FILE as a recording, or as a GNSS file when it is one and no recording format matches.
pednav::io::SensorLog read_any(const std::string& path, const pednav::io::ReadOptions& options) {
    using namespace pednav::io;
    if ((options.format == "auto" || options.format.empty()) && options.column_map == nullptr) {
        bool recording = true;
        try {
            detect_format(path);
        } catch (const ReadError&) {
            recording = false;
        }
        if (!recording) {
            try {
                detect_gnss_format(path);
            } catch (const ReadError&) {
                return scan_sensor_file(path, options);  // throws the recording readers' error
            }
            GnssReadOptions go;
            go.max_issues = options.max_issues;
            return read_gnss_file(path, go);
        }
    }
    return scan_sensor_file(path, options);
}

}  // namespace

const char* const pednav_cmd_inspect_usage = kUsage;

int pednav_cmd_inspect(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    bool json = false;
    std::string path, column_map_path, gnss_path;
    io::ReadOptions options;
    io::GnssReadOptions gnss_options;
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--json")
            json = true;
        else if (a == "--format")
            options.format = args.value(a);
        else if (a == "--column-map")
            column_map_path = args.value(a);
        else if (a == "--gnss")
            gnss_path = args.value(a);
        else if (a == "--gnss-format")
            gnss_options.format = args.value(a);
        else if (a == "--gap")
            options.gap_s = cli::parse_numbers(args.value(a), 1, a)[0];
        else if (a == "--rate")
            options.counter_rate_hz = cli::parse_positive_rate(args.value(a), a);
        else if (!a.empty() && a[0] == '-')
            throw cli::UsageError("unknown option " + a + " for inspect");
        else if (path.empty())
            path = a;
        else
            throw cli::UsageError(std::string("inspect takes one FILE, not also ").append(a));
    }
    if (path.empty()) throw cli::UsageError("inspect needs a FILE");
    if (gnss_path.empty() && gnss_options.format != "auto")
        throw cli::UsageError("--gnss-format goes with --gnss FILE");
    if (gnss_options.format != "auto" && gnss_options.format != "nmea" && gnss_options.format != "csv")
        throw cli::UsageError("--gnss-format must be auto, nmea or csv, not " + gnss_options.format);
    nlohmann::json column_map;
    if (!column_map_path.empty()) {
        column_map = nlohmann::json::parse(cli::read_text_file(column_map_path), nullptr, false);
        if (column_map.is_discarded()) throw std::runtime_error(column_map_path + ": not valid JSON");
        options.column_map = &column_map;
    }
    try {
        const io::SensorLog log = read_any(path, options);
        io::SensorLog gnss;
        if (!gnss_path.empty()) {
            if (log.records.imu > 0)
                gnss_options.time.first_epoch_t_s = static_cast<double>(log.records.imu_first_t_ns) * 1e-9;
            gnss = io::read_gnss_file(gnss_path, gnss_options);
        }
        if (json) {
            nlohmann::json j = io::sensor_log_json(log);
            j["format_detected"] = options.format == "auto" && options.column_map == nullptr;
            if (!gnss_path.empty()) {
                j["gnss_input"] = io::sensor_log_json(gnss);
                j["gnss_input"]["format_detected"] = gnss_options.format == "auto";
            }
            std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        } else {
            print_text(log, options.format != "auto" || options.column_map != nullptr);
            if (!gnss_path.empty()) {
                std::printf("\n--- GNSS input\n");
                print_text(gnss, gnss_options.format != "auto");
            }
        }
        return 0;
    } catch (const io::ReadError& e) {
        if (json) {
            const nlohmann::json j = {
                {"path", path}, {"error", {{"file", e.path()}, {"line", e.line()}, {"reason", e.reason()}}}};
            std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        }
        std::fprintf(stderr, "pednav inspect: %s\n", e.what());
        return 1;
    }
}

// SPDX-License-Identifier: Apache-2.0
// Xsens exports: MTw/Awinda tab-separated text and MT Manager CSV. A few
// preamble lines ("Acquisition frequency: 100 Hz", "// Update Rate: 100.0Hz",
// "// Start Time: ..."), then a header naming PacketCounter, SampleTimeFine,
// Acc_X.., Gyr_X.., Mag_X.., Pressure, Roll/Pitch/Yaw, Quat_*.
// Time: SampleTimeFine (100 us ticks, wraps at 2^32) when present, else
// PacketCounter / rate (wraps at 65536) with the rate from the preamble.
// Units: Acc m/s^2, Gyr rad/s, Mag normalised to the field at calibration
// (scaled by kXsensMagFieldUt), Pressure Pa. Axes: the Xsens sensor frame
// (x, y, z on the case, right-handed), kept as the body axes.
#include <cstdio>
#include <cstdlib>

#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

// Xsens normalises the magnetometer so that the field where it was calibrated
// reads 1. The engine wants microtesla; the field magnitude is not in the file,
// so a nominal mid-latitude field is assumed. Heading uses only the direction.
constexpr double kXsensMagFieldUt = 50.0;

struct XsensHeader {
    size_t index = 0;
    char delim = ',';
    std::vector<std::string> names;
    double rate_hz = 0.0;
};

bool find_header(const TextFile& file, XsensHeader* out) {
    const size_t limit = std::min<size_t>(file.lines.size(), 30);
    double rate = 0.0;
    for (size_t i = 0; i < limit; ++i) {
        const std::string_view line = trim(file.lines[i]);
        const std::string lower = to_lower(line);
        // "Acquisition frequency: 100 Hz" or "// Update Rate: 100.0Hz"
        for (const char* key : {"acquisition frequency:", "update rate:", "sample rate:"}) {
            const size_t at = lower.find(key);
            if (at != std::string::npos) rate = std::atof(lower.c_str() + at + std::string(key).size());
        }
        if (line.find("Acc_X") != std::string_view::npos &&
            (line.find("PacketCounter") != std::string_view::npos ||
             line.find("SampleTimeFine") != std::string_view::npos)) {
            out->index = i;
            out->delim = guess_delimiter(line);
            out->names.clear();
            for (auto f : split(line, out->delim)) out->names.emplace_back(trim(f));
            out->rate_hz = rate;
            return true;
        }
    }
    return false;
}

}  // namespace

bool detect_xsens_mtw_tsv(const TextFile& file) {
    XsensHeader h;
    return find_header(file, &h) && h.delim == '\t';
}

bool detect_xsens_mtmanager_csv(const TextFile& file) {
    XsensHeader h;
    return find_header(file, &h) && h.delim != '\t';
}

std::unique_ptr<RowReader> open_xsens(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                      SensorLog& log) {
    const TextFile& file = input.head();
    XsensHeader h;
    if (!find_header(file, &h))
        throw ReadError(file.path, 0, "no Xsens header (PacketCounter, Acc_X, ...) found");
    TableSpec spec;
    spec.delim = h.delim;
    spec.names = h.names;
    spec.column_count = h.names.size();
    spec.first_data_index = h.index + 1;
    spec.comment_prefixes = {"//", "#"};
    const int fine = find_column(h.names, "SampleTimeFine");
    const int counter = find_column(h.names, "PacketCounter");
    char text[200];
    if (fine >= 0) {
        spec.time_col = fine;
        spec.time_scale = 1e-4;
        spec.counter_wrap = 4294967296.0;
        builder.note("time from SampleTimeFine (100 us ticks)");
    } else if (counter >= 0 && (h.rate_hz > 0 || options.counter_rate_hz > 0)) {
        const bool given = options.counter_rate_hz > 0;
        spec.time_kind = TableSpec::TimeKind::counter;
        spec.time_col = counter;
        spec.counter_rate_hz = given ? options.counter_rate_hz : h.rate_hz;
        spec.counter_wrap = 65536.0;
        std::snprintf(text, sizeof text, "time from PacketCounter / %.6g Hz (rate %s)", spec.counter_rate_hz,
                      given ? "given by the user (--rate)" : "from the file's preamble");
        builder.note(text);
        if (given && h.rate_hz > 0 && h.rate_hz != options.counter_rate_hz) {
            std::snprintf(text, sizeof text, "the file's preamble says %.6g Hz; the rate given, %.6g Hz, is used",
                          h.rate_hz, options.counter_rate_hz);
            builder.issue(h.index + 1, text);
        }
    } else {
        throw ReadError(file.path, h.index + 1,
                        "Xsens export without SampleTimeFine and without a sample rate line: time unknown "
                        "(give the rate of PacketCounter with --rate HZ)");
    }
    const char* xyz[3] = {"_X", "_Y", "_Z"};
    for (int i = 0; i < 3; ++i) {
        spec.accel.col[i] = find_column(h.names, std::string("Acc") + xyz[i]);
        spec.gyro.col[i] = find_column(h.names, std::string("Gyr") + xyz[i]);
        spec.mag.col[i] = find_column(h.names, std::string("Mag") + xyz[i]);
    }
    if (!spec.accel.present() || !spec.gyro.present()) {
        throw ReadError(file.path, h.index + 1, "no complete Acc_X/Y/Z and Gyr_X/Y/Z columns");
    }
    builder.set_units(stream_accel, "m/s^2", "m/s^2");
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    if (spec.mag.present()) {
        spec.mag.scale = kXsensMagFieldUt;
        builder.set_units(stream_mag, "normalised a.u.", "uT");
        std::snprintf(
            text, sizeof text,
            "magnetometer in Xsens normalised units (1 = field at calibration) scaled by a nominal %.0f uT",
            kXsensMagFieldUt);
        builder.note(text);
    } else {
        spec.mag = Vec3Spec{};
    }
    spec.pressure_col = find_column(h.names, "Pressure");
    if (spec.pressure_col >= 0) builder.set_units(stream_pressure, "Pa", "Pa");
    spec.temperature_col = find_column(h.names, "Temperature");
    log.axes = "Xsens sensor frame x, y, z (right-handed, as on the case), not levelled";
    return std::make_unique<TableReader>(input, spec, builder);
}

}  // namespace pednav::io::detail

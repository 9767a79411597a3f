// SPDX-License-Identifier: Apache-2.0
// NMEA 0183: sentences grouped into epochs by their UTC time, one fix per
// epoch, put on the IMU log's clock by the time base (docs/formats.md).
#include <cstdio>
#include <map>

#include "formats.hpp"
#include "gnss_formats.hpp"
#include "nmea_epoch.hpp"

namespace pednav::io::detail {

namespace {

std::string seconds_text(double t_s) {
    char text[40];
    std::snprintf(text, sizeof text, "%.3f s", t_s);
    return text;
}

std::string clock_text(int64_t time_of_day_ns) {
    const int64_t ms = (time_of_day_ns % kDay_ns) / 1000000;
    char text[32];
    std::snprintf(text, sizeof text, "%02d:%02d:%02d.%03d", static_cast<int>(ms / 3600000),
                  static_cast<int>(ms / 60000 % 60), static_cast<int>(ms / 1000 % 60), static_cast<int>(ms % 1000));
    return text;
}

// The epochs of the file in order; bad sentences reported and skipped.
std::vector<NmeaEpoch> read_epochs(const TextFile& file, LogBuilder& builder, std::map<std::string, size_t>& ignored,
                                   size_t& prefixed_lines) {
    const unsigned gnss_bit = stream_bit(stream_gnss);
    std::vector<NmeaEpoch> epochs;
    NmeaEpoch current;
    bool open = false;
    NmeaSentence s;
    std::string problem;
    for (size_t i = 0; i < file.lines.size(); ++i) {
        const size_t line = i + 1;
        const std::string_view text = trim(file.lines[i]);
        if (text.empty() || text[0] == '#') continue;
        if (!parse_nmea_sentence(text, &s, &problem)) {
            builder.bad_row(line, problem, gnss_bit, "sentence");
            continue;
        }
        if (s.text_before) ++prefixed_lines;
        int64_t tod = 0;
        const bool timed = nmea_sentence_time(s, &tod);
        // A sentence with another time starts the next epoch; sentences
        // without a time (GSA, VTG) belong to the epoch they follow.
        if (timed && open && current.has_time && current.time_of_day_ns != tod) {
            epochs.push_back(current);
            open = false;
        }
        if (!open) {
            current = NmeaEpoch{};
            current.line = line;
            open = true;
        }
        NmeaEpoch applied = current;
        if (!apply_nmea_sentence(s, &applied, &problem)) {
            builder.bad_row(line, problem, gnss_bit, "sentence");
            continue;
        }
        if (timed && !applied.has_time) {
            applied.has_time = true;
            applied.time_of_day_ns = tod;
        }
        current = std::move(applied);
        const std::string type(s.type);
        if (s.talker == "P" || (type != "GGA" && type != "RMC" && type != "GSA" && type != "GST" && type != "VTG" &&
                                type != "ZDA"))
            ++ignored[s.talker == "P" ? "proprietary" : type];
    }
    if (open) epochs.push_back(current);
    return epochs;
}

}  // namespace

bool detect_nmea(const TextFile& file) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) return false;
    const std::string_view line = trim(file.lines[index]);
    return line.size() > 7 && line[0] == '$' && line.find(',') == 6;
}

void read_nmea(const TextFile& file, const GnssReadOptions& options, LogBuilder& builder, SensorLog& log) {
    const unsigned gnss_bit = stream_bit(stream_gnss);
    builder.set_units(stream_gnss, "ddmm.mmmm, knots|km/h, deg, m MSL + geoid", "deg, m/s ENU, m ellipsoidal");
    log.axes = "WGS-84 fixes; velocity east-north-up";
    std::map<std::string, size_t> ignored;
    size_t prefixed = 0;
    const std::vector<NmeaEpoch> epochs = read_epochs(file, builder, ignored, prefixed);

    // Time since the first epoch, across midnight; the first dated epoch anchors UTC.
    std::vector<int64_t> since_first(epochs.size(), 0);
    bool have_first = false, anchored = false;
    int64_t first_tod = 0, previous_tod = 0, days_passed = 0, utc_of_first = 0;
    size_t untimed = 0;
    for (size_t k = 0; k < epochs.size(); ++k) {
        const NmeaEpoch& e = epochs[k];
        if (!e.has_time) {
            ++untimed;
            continue;
        }
        if (!have_first) {
            first_tod = previous_tod = e.time_of_day_ns;
            have_first = true;
        }
        if (e.time_of_day_ns < previous_tod - kDay_ns / 2) ++days_passed;  // past midnight
        previous_tod = e.time_of_day_ns;
        since_first[k] = e.time_of_day_ns + days_passed * kDay_ns - first_tod;
        if (e.has_date && !anchored) {
            utc_of_first = e.date_days * kDay_ns + e.time_of_day_ns - since_first[k];
            anchored = true;
        }
    }
    if (!have_first) throw ReadError(file.path, 0, "no NMEA sentence with a time (GGA, RMC, GST or ZDA)");

    // The time base: an explicit UTC of t = 0, or the first epoch at a given t.
    const int64_t utc0 = options.time.utc_ns_at_zero;
    int64_t t_first_ns = seconds_to_ns(options.time.first_epoch_t_s);
    if (utc0 != 0) {
        if (!anchored) {
            // No date in the file: the day of utc0, the nearer of it and the next.
            utc_of_first = (utc0 / kDay_ns) * kDay_ns + first_tod;
            if (utc_of_first < utc0 - kDay_ns / 2) utc_of_first += kDay_ns;
            builder.note("no date in the file (no RMC or ZDA): the day of the given UTC of t = 0 is taken");
            anchored = true;
        }
        t_first_ns = utc_of_first - utc0;
        builder.note("time base: UTC " + iso_utc(utc0) + " at t = 0, so the first epoch (" +
                     clock_text(first_tod) + ") is at t = " + seconds_text(static_cast<double>(t_first_ns) * 1e-9));
    } else {
        builder.note("time base: the first epoch (UTC " + clock_text(first_tod) + ") at t = " +
                     seconds_text(options.time.first_epoch_t_s) + " on the IMU clock");
    }
    if (anchored) log.utc_ns_at_zero = utc_of_first - t_first_ns;

    Clock clock("gnss");
    size_t counts[3] = {0, 0, 0};
    std::map<NoFix, size_t> no_fix;
    std::string problem;
    for (size_t k = 0; k < epochs.size(); ++k) {
        const NmeaEpoch& e = epochs[k];
        if (!e.has_time) continue;
        NoFix why = NoFix::none;
        FixFields f = nmea_epoch_fix(e, &why);
        if (why != NoFix::none) {
            ++no_fix[why];
            continue;
        }
        if (anchored) f.utc_ns = utc_of_first + since_first[k];
        AccuracySource source = AccuracySource::sigma;
        const pn_gnss_t g = make_gnss_fix(f, options.uere_m, &problem, &source);
        if (!problem.empty()) {
            builder.bad_row(e.line, problem, gnss_bit, "epoch");
            continue;
        }
        const int64_t t_ns = t_first_ns + since_first[k];
        const double t_s = static_cast<double>(t_ns) * 1e-9;
        if (!builder.accept_time(clock, e.line, t_s, gnss_bit)) continue;
        ++counts[static_cast<int>(source)];
        builder.add_gnss(e.line, t_s, g);
    }
    builder.note(std::to_string(epochs.size() - untimed) + " epochs" +
                 (anchored ? ", UTC dates from RMC/ZDA" : ", no date (utc_ns 0)"));
    builder.note(accuracy_note(counts, options.uere_m));
    const char* reasons[] = {"", "GGA fix quality 0", "RMC status V", "no position", "GGA quality 7/8 (manual or simulated)"};
    for (const auto& [why, n] : no_fix)
        builder.note(std::to_string(n) + " epochs without a fix (" + reasons[static_cast<int>(why)] + ")");
    if (untimed > 0) builder.note(std::to_string(untimed) + " sentence groups without a time ignored");
    if (prefixed > 0) builder.note(std::to_string(prefixed) + " lines with text before the '$' (read from the '$')");
    if (!ignored.empty()) {
        std::string text = "sentences not used:";
        for (const auto& [type, n] : ignored) text += " " + type + " " + std::to_string(n);
        builder.note(text);
    }
}

}  // namespace pednav::io::detail

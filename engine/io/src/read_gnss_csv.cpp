// SPDX-License-Identifier: Apache-2.0
// GNSS CSV: header t,lat,lon[,alt][,hacc][,vacc][,speed][,course][,sats][,fix]
// by name (case-insensitive, any order, other columns ignored); s, deg, deg, m
// (ellipsoidal), m, m, m/s, deg clockwise from north, count, GGA quality code.
// Only t, lat and lon are required; an empty optional cell = not given.
#include <cmath>

#include "formats.hpp"
#include "gnss_fix.hpp"
#include "gnss_formats.hpp"

namespace pednav::io::detail {

namespace {

std::vector<std::string> header_names(std::string_view line) {
    std::vector<std::string> names;
    for (auto field : split(line, ',')) names.push_back(to_lower(trim(field)));
    return names;
}

const char* const kOptional[] = {"alt", "hacc", "vacc", "speed", "course", "sats", "fix"};

}  // namespace

bool detect_gnss_csv(const TextFile& file) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) return false;
    const auto names = header_names(file.lines[index]);
    return find_column(names, "t") >= 0 && find_column(names, "lat") >= 0 && find_column(names, "lon") >= 0;
}

void read_gnss_csv(const TextFile& file, const GnssReadOptions& options, LogBuilder& builder, SensorLog& log) {
    const size_t header = first_content_line(file);
    if (header >= file.lines.size()) throw ReadError(file.path, 0, "no header line");
    const std::vector<std::string> names = header_names(file.lines[header]);
    const int col_t = find_column(names, "t"), col_lat = find_column(names, "lat"),
              col_lon = find_column(names, "lon");
    if (col_t < 0 || col_lat < 0 || col_lon < 0)
        throw ReadError(file.path, header + 1, "a GNSS CSV header needs the columns t, lat and lon");
    int col[7];
    std::string found = "t,lat,lon";
    for (int k = 0; k < 7; ++k) {
        col[k] = find_column(names, kOptional[k]);
        if (col[k] >= 0) found += std::string(",") + kOptional[k];
    }
    builder.note("columns used: " + found);
    builder.set_units(stream_gnss, "deg, m, m/s, deg", "deg, m, m/s ENU");
    log.axes = "WGS-84 fixes; velocity east-north-up";

    const unsigned gnss_bit = stream_bit(stream_gnss);
    Clock clock("gnss");
    size_t counts[3] = {0, 0, 0};
    size_t no_fix_rows = 0, zero_sat_rows = 0, zero_sat_first = 0;
    std::vector<std::string_view> fields;
    std::string problem;
    for (size_t i = header + 1; i < file.lines.size(); ++i) {
        const size_t line = i + 1;
        const std::string_view text = trim(file.lines[i]);
        if (text.empty() || text[0] == '#') continue;
        split_into(text, ',', fields);
        if (fields.size() != names.size()) {
            builder.bad_row(line,
                            "truncated line: " + std::to_string(fields.size()) + " fields, the header has " +
                                std::to_string(names.size()),
                            gnss_bit);
            continue;
        }
        // Optional numbers first (empty = not given): a row without a fix
        // (fix = 0) usually has no position either.
        bool bad = false;
        double v[7];
        for (int k = 0; k < 7 && !bad; ++k) {
            v[k] = NAN;
            if (col[k] < 0) continue;
            const std::string_view field = fields[static_cast<size_t>(col[k])];
            const NumberStatus st = parse_number(field, &v[k]);
            if (st == NumberStatus::empty) {
                v[k] = NAN;
            } else if (st != NumberStatus::ok) {
                builder.bad_row(line, describe_bad_number(st, field, kOptional[k]), gnss_bit);
                bad = true;
            }
        }
        if (bad) continue;
        const double sats = v[5], fix = v[6];
        if (std::isfinite(sats) && (sats < 0 || sats != std::floor(sats) || sats > 1000)) {
            builder.bad_row(line, "sats must be a count, not '" + std::string(fields[col[5]]) + "'", gnss_bit);
            continue;
        }
        if (std::isfinite(fix) && (fix < 0 || fix > 6 || fix != std::floor(fix))) {
            builder.bad_row(line, "fix must be a GGA quality code 0..6, not '" + std::string(fields[col[6]]) + "'",
                            gnss_bit);
            continue;
        }
        if (fix == 0.0) {  // the receiver had no fix at this time
            ++no_fix_rows;
            continue;
        }
        if (sats == 0.0) {  // a position from no satellite is no fix, whatever `fix` says
            if (zero_sat_rows++ == 0) zero_sat_first = line;
            continue;
        }
        double t = 0, lat = 0, lon = 0;
        for (auto [c, out] : {std::pair<int, double*>{col_t, &t}, {col_lat, &lat}, {col_lon, &lon}}) {
            const NumberStatus st = parse_number(fields[static_cast<size_t>(c)], out);
            if (st != NumberStatus::ok) {
                builder.bad_row(line, describe_bad_number(st, fields[static_cast<size_t>(c)], names[c]),
                                gnss_bit);
                bad = true;
                break;
            }
        }
        if (bad) continue;
        FixFields f;
        f.lat_deg = lat;
        f.lon_deg = lon;
        f.height_m = v[0];
        f.h_sigma_m = v[1];
        f.v_sigma_m = v[2];
        f.speed_mps = v[3];
        f.course_deg = v[4];
        f.satellites = std::isfinite(sats) ? static_cast<int32_t>(sats) : 0;
        f.fix_type = std::isfinite(fix) ? static_cast<int32_t>(fix) : PN_GNSS_FIX_UNKNOWN;
        AccuracySource source = AccuracySource::sigma;
        const pn_gnss_t g = make_gnss_fix(f, options.uere_m, &problem, &source);
        if (!problem.empty()) {
            builder.bad_row(line, problem, gnss_bit);
            continue;
        }
        if (!builder.accept_time(clock, line, t, gnss_bit)) continue;
        ++counts[static_cast<int>(source)];
        builder.add_gnss(line, t, g);
    }
    builder.note("time: the column t, in seconds on the IMU log's clock");
    builder.note(accuracy_note(counts, options.uere_m));
    if (no_fix_rows > 0) builder.note(std::to_string(no_fix_rows) + " rows without a fix (fix = 0) skipped");
    if (zero_sat_rows > 0)
        builder.issue(zero_sat_first, std::to_string(zero_sat_rows) + " fixes with 0 satellites skipped (first at line " +
                                          std::to_string(zero_sat_first) + ")");
}

}  // namespace pednav::io::detail

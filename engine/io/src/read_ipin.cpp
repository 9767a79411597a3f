// SPDX-License-Identifier: Apache-2.0
// IPIN competition logfiles (smartphone track): one ';'-separated line per
// sample, '%' comments.
//   ACCE;AppTimestamp(s);SensorTimestamp(s);Acc_X;Acc_Y;Acc_Z;Accuracy      m/s^2
//   GYRO;...;Gyr_X;Gyr_Y;Gyr_Z;Accuracy                                      rad/s
//   MAGN;...;Mag_X;Mag_Y;Mag_Z;Accuracy                                      uT
//   PRES;AppTimestamp;SensorTimestamp;Pres(mbar);Accuracy                    hPa
//   GNSS;AppTimestamp;SensorTimestamp;Lat;Lon;Alt;Bearing;Accuracy;Speed;[UTCTime(ms);]SatInView;SatInUse
//   POSI;Timestamp;Counter;Latitude;Longitude;FloorID;BuildingID            ground truth
// Other tags (AHRS, WIFI, BLUE, LIGH, ...) are counted and ignored.
// Time: the app clock, common to every line. For ACCE/GYRO/MAGN/PRES the
// sensor clock is used for spacing (it is the accurate one) and placed on the
// app clock by the smallest app - sensor difference of that stream (the
// least-delayed delivery). GNSS and POSI use the app timestamp.
#include <cmath>
#include <cstdio>
#include <map>

#include "android_axes.hpp"
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

// "POSI <counter>": the counter as the file gives it, whole; a counter no
// integer type holds (a corrupt line) is printed as a number, not converted.
std::string posi_name(double counter) {
    char name[64];
    std::snprintf(name, sizeof name, "POSI %.0f", std::trunc(counter) + 0.0);
    return name;
}

struct RawLine {
    size_t line;
    double app_s, sensor_s;
    double v[9];
    size_t n;  // values after the two timestamps
};

bool is_tag(std::string_view s) {
    if (s.size() < 5 || s[4] != ';') return false;
    for (int i = 0; i < 4; ++i) {
        if (!((s[i] >= 'A' && s[i] <= 'Z') || (s[i] >= '0' && s[i] <= '9'))) return false;
    }
    return true;
}

}  // namespace

bool detect_ipin(const TextFile& file) {
    size_t seen = 0;
    for (size_t i = 0; i < file.lines.size() && seen < 50; ++i) {
        const std::string_view line = trim(file.lines[i]);
        if (line.empty() || line[0] == '%') continue;
        ++seen;
        if (!is_tag(line)) return false;
        const std::string_view tag = line.substr(0, 4);
        if (tag == "ACCE" || tag == "GYRO" || tag == "MAGN" || tag == "PRES" || tag == "POSI" ||
            tag == "GNSS") {
            return true;
        }
    }
    return false;
}

namespace {

void read_ipin(const TextFile& file, const ReadOptions&, LogBuilder& builder, SensorLog& log) {
    std::map<std::string, std::vector<RawLine>> streams;  // ACCE, GYRO, MAGN, PRES, GNSS
    std::map<std::string, size_t> ignored;
    std::vector<std::string_view> fields;
    struct Posi {
        size_t line;
        double t_s, counter, lat, lon, floor;
    };
    std::vector<Posi> posi;

    // Values expected after the tag: timestamps included.
    const std::map<std::string, size_t> min_fields = {{"ACCE", 6}, {"GYRO", 6}, {"MAGN", 6},
                                                      {"PRES", 4}, {"GNSS", 9}, {"POSI", 6}};
    const unsigned all_bits =
        kImuBits | stream_bit(stream_mag) | stream_bit(stream_pressure) | stream_bit(stream_gnss);
    for (size_t index = 0; index < file.lines.size(); ++index) {
        const size_t line_no = index + 1;
        const std::string_view line = trim(file.lines[index]);
        if (line.empty() || line[0] == '%') continue;
        if (!is_tag(line)) {
            builder.bad_row(line_no, "not a 'TAG;...' line: '" + std::string(line.substr(0, 40)) + "'",
                            all_bits);
            continue;
        }
        const std::string tag(line.substr(0, 4));
        auto need = min_fields.find(tag);
        if (need == min_fields.end()) {
            ++ignored[tag];
            continue;
        }
        split_into(line.substr(5), ';', fields);
        while (!fields.empty() && fields.back().empty()) fields.pop_back();  // trailing ';'
        const unsigned bits = tag == "ACCE"   ? stream_bit(stream_accel)
                              : tag == "GYRO" ? stream_bit(stream_gyro)
                              : tag == "MAGN" ? stream_bit(stream_mag)
                              : tag == "PRES" ? stream_bit(stream_pressure)
                              : tag == "GNSS" ? stream_bit(stream_gnss)
                                              : stream_bit(stream_truth);
        if (fields.size() < need->second) {
            builder.bad_row(line_no,
                            tag + " line truncated: " + std::to_string(fields.size()) + " fields, " +
                                std::to_string(need->second) + " expected",
                            bits);
            continue;
        }
        double v[12] = {};
        const size_t used = std::min<size_t>(fields.size(), 12);
        bool ok = true;
        for (size_t k = 0; k < used && ok; ++k) {
            // The trailing accuracy / satellite counts may be absent or text; only the needed ones must
            // parse.
            const NumberStatus status = parse_number(fields[k], &v[k]);
            if (status != NumberStatus::ok && k < need->second) {
                builder.bad_row(
                    line_no,
                    tag + " " + describe_bad_number(status, fields[k], "field " + std::to_string(k + 2)),
                    bits);
                ok = false;
            }
        }
        if (!ok) continue;
        if (tag == "POSI") {
            posi.push_back({line_no, v[0], v[1], v[2], v[3], v[4]});
            continue;
        }
        RawLine raw{line_no, v[0], v[1], {}, used - 2};
        for (size_t k = 2; k < used && k < 11; ++k) raw.v[k - 2] = v[k];
        streams[tag].push_back(raw);
    }

    // Place each sensor clock on the app clock.
    auto offset_of = [](const std::vector<RawLine>& s) {
        double best = INFINITY;
        for (const auto& r : s) best = std::min(best, r.app_s - r.sensor_s);
        return std::isfinite(best) ? best : 0.0;
    };
    char text[256];
    struct Inertial {
        const char* tag;
        StreamId id;
    };
    for (const Inertial in :
         {Inertial{"ACCE", stream_accel}, Inertial{"GYRO", stream_gyro}, Inertial{"MAGN", stream_mag}}) {
        const auto& s = streams[in.tag];
        if (s.empty()) continue;
        const double offset = offset_of(s);
        std::snprintf(text, sizeof text, "%s: sensor clock + %.6f s = app clock (smallest delivery delay)",
                      in.tag, offset);
        builder.note(text);
        Clock clock(in.tag);
        for (const auto& r : s) {
            const double t = r.sensor_s + offset;
            if (!builder.accept_time(clock, r.line, t, stream_bit(in.id))) continue;
            double body[3];
            android_to_flu(r.v, body);
            if (in.id == stream_accel)
                builder.add_accel(r.line, t, body);
            else if (in.id == stream_gyro)
                builder.add_gyro(r.line, t, body);
            else
                builder.add_mag(r.line, t, body);
        }
    }
    builder.set_units(stream_accel, "m/s^2", "m/s^2");
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    if (!streams["MAGN"].empty()) builder.set_units(stream_mag, "uT", "uT");
    if (!streams["PRES"].empty()) {
        const auto& s = streams["PRES"];
        const double offset = offset_of(s);
        Clock clock("PRES");
        for (const auto& r : s) {
            const double t = r.sensor_s + offset;
            if (builder.accept_time(clock, r.line, t, stream_bit(stream_pressure)))
                builder.add_baro(r.line, t, r.v[0] * 100.0, NAN);
        }
        builder.set_units(stream_pressure, "hPa", "Pa");
    }
    if (!streams["GNSS"].empty()) {
        Clock clock("GNSS");
        for (const auto& r : streams["GNSS"]) {
            pn_gnss_t fix{};
            fix.lat_deg = r.v[0];
            fix.lon_deg = r.v[1];
            fix.height_m = r.v[2];
            const double bearing_rad = r.v[3] * kDegToRad;
            fix.h_accuracy_m = r.v[4];
            // Android gives no vertical accuracy here: 1.5 x horizontal is assumed (docs/formats.md).
            fix.v_accuracy_m = 1.5 * r.v[4];
            const double speed = r.v[5];
            fix.vel_enu_mps[0] = speed * std::sin(bearing_rad);
            fix.vel_enu_mps[1] = speed * std::cos(bearing_rad);
            fix.vel_enu_mps[2] = 0.0;
            // With 9 values the 7th is UTCTime(ms); else the sensor timestamp is Unix seconds when it looks
            // like one.
            if (r.n >= 9)
                fix.utc_ns = static_cast<int64_t>(std::llround(r.v[6] * 1e6));
            else if (r.sensor_s > 1e9)
                fix.utc_ns = static_cast<int64_t>(std::llround(r.sensor_s * 1e9));
            if (std::fabs(fix.lat_deg) > 90 || std::fabs(fix.lon_deg) > 180) {
                builder.bad_row(r.line, "GNSS latitude/longitude out of range", stream_bit(stream_gnss));
                continue;
            }
            if (!builder.accept_time(clock, r.line, r.app_s, stream_bit(stream_gnss))) continue;
            fix.header.flags = speed > 0 || bearing_rad != 0 ? PN_GNSS_FLAG_HAS_VELOCITY : 0u;
            builder.add_gnss(r.line, r.app_s, fix);
        }
        builder.set_units(stream_gnss, "deg, m", "deg, m");
    }
    if (!posi.empty()) {
        log.truth_origin = {posi.front().lat, posi.front().lon, 0.0, true};
        for (const auto& p : posi) {
            double enu[3];
            geodesy::geodetic_to_enu(log.truth_origin, p.lat, p.lon, 0.0, enu);
            TruthPoint point{p.t_s,
                             enu[0],
                             enu[1],
                             0.0,
                             static_cast<int>(std::lround(p.floor)),
                             false,
                             posi_name(p.counter)};
            builder.add_truth(p.line, point);
        }
        builder.set_units(stream_truth, "deg", "m (ENU from the first POSI)");
        std::snprintf(text, sizeof text,
                      "%zu POSI ground-truth points, local ENU metres from lat %.8f lon %.8f", posi.size(),
                      posi.front().lat, posi.front().lon);
        builder.note(text);
    }
    if (!ignored.empty()) {
        std::string list;
        for (const auto& [tag, count] : ignored)
            list += (list.empty() ? "" : ", ") + tag + " " + std::to_string(count);
        builder.note("lines ignored: " + list);
    }
    log.axes = kAndroidAxesText;
}

}  // namespace

std::unique_ptr<RowReader> open_ipin(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                     SensorLog& log) {
    return open_whole_file(input, options, builder, log, read_ipin);
}

}  // namespace pednav::io::detail

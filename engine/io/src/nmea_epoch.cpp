// SPDX-License-Identifier: Apache-2.0
#include "nmea_epoch.hpp"

#include "pednav_io/text_fields.hpp"

namespace pednav::io::detail {

namespace {

// Fields each sentence needs (through its last field the reader uses).
size_t fields_needed(std::string_view type) {
    if (type == "GGA") return 11;  // time .. geoid separation
    if (type == "RMC") return 9;   // time .. date
    if (type == "GSA") return 17;  // mode .. VDOP
    if (type == "GST") return 8;   // time .. altitude sigma
    if (type == "VTG") return 8;   // course T .. speed km/h K
    if (type == "ZDA") return 4;   // time .. year
    return 0;
}

// An optional number: empty is NaN; false when the text is not a number.
bool optional_number(std::string_view field, double* v) {
    *v = NAN;
    const NumberStatus st = parse_number(field, v);
    if (st == NumberStatus::empty) {
        *v = NAN;
        return true;
    }
    return st == NumberStatus::ok;
}

bool fail(std::string* problem, std::string_view type, const char* what, std::string_view field) {
    *problem = "bad " + std::string(what) + " '" + std::string(field.substr(0, 24)) + "' in " + std::string(type);
    return false;
}

// Latitude and longitude fields at `i` (value, hemisphere, value, hemisphere);
// all four empty = no position (NaN).
bool position(const NmeaSentence& s, size_t i, double* lat, double* lon, std::string* problem) {
    *lat = *lon = NAN;
    if (s.fields[i].empty() && s.fields[i + 2].empty()) return true;
    if (!nmea_latitude_deg(s.fields[i], s.fields[i + 1], lat))
        return fail(problem, s.type, "latitude", std::string(s.fields[i]) + "," + std::string(s.fields[i + 1]));
    if (!nmea_longitude_deg(s.fields[i + 2], s.fields[i + 3], lon))
        return fail(problem, s.type, "longitude",
                    std::string(s.fields[i + 2]) + "," + std::string(s.fields[i + 3]));
    return true;
}

int fix_type_of_mode(char mode) {
    switch (mode) {
        case 'D': return PN_GNSS_FIX_DIFFERENTIAL;
        case 'R': return PN_GNSS_FIX_RTK_FIXED;
        case 'F': return PN_GNSS_FIX_RTK_FLOAT;
        case 'E': return PN_GNSS_FIX_DEAD_RECKONING;
        default: return PN_GNSS_FIX_AUTONOMOUS;  // A (autonomous), P (precise), or no mode field
    }
}

}  // namespace

bool nmea_sentence_time(const NmeaSentence& s, int64_t* time_of_day_ns) {
    if (s.type != "GGA" && s.type != "RMC" && s.type != "GST" && s.type != "ZDA") return false;
    return !s.fields.empty() && nmea_time_of_day_ns(s.fields[0], time_of_day_ns);
}

bool apply_nmea_sentence(const NmeaSentence& s, NmeaEpoch* e, std::string* problem) {
    const size_t needed = fields_needed(s.type);
    if (needed == 0 || s.talker == "P") return true;
    if (s.fields.size() < needed) {
        *problem = "truncated " + std::string(s.type) + ": " + std::to_string(s.fields.size()) + " fields, " +
                   std::to_string(needed) + " expected";
        return false;
    }
    const auto& f = s.fields;
    int64_t tod = 0;
    if (s.type != "GSA" && s.type != "VTG" && !nmea_time_of_day_ns(f[0], &tod))
        return fail(problem, s.type, "time", f[0]);

    if (s.type == "GGA") {
        NmeaEpoch::Gga g;
        g.present = true;
        g.talker = std::string(s.talker);
        double q = 0;
        if (parse_number(f[5], &q) != NumberStatus::ok || q < 0 || q > 8 || q != std::floor(q))
            return fail(problem, s.type, "fix quality", f[5]);
        g.quality = static_cast<int>(q);
        if (!position(s, 1, &g.lat_deg, &g.lon_deg, problem)) return false;
        double sats = 0;
        if (!optional_number(f[6], &sats) || sats < 0) return fail(problem, s.type, "satellite count", f[6]);
        g.satellites = std::isfinite(sats) ? static_cast<int>(sats) : -1;
        if (!optional_number(f[7], &g.hdop)) return fail(problem, s.type, "HDOP", f[7]);
        if (!optional_number(f[8], &g.altitude_msl_m)) return fail(problem, s.type, "altitude", f[8]);
        if (!optional_number(f[10], &g.geoid_separation_m)) return fail(problem, s.type, "geoid separation", f[10]);
        e->gga = g;
    } else if (s.type == "RMC") {
        NmeaEpoch::Rmc r;
        r.present = true;
        if (f[1] != "A" && f[1] != "V") return fail(problem, s.type, "status", f[1]);
        r.mode = f.size() > 11 && f[11].size() == 1 ? f[11][0] : 0;
        r.valid = f[1] == "A" && r.mode != 'N';
        if (!position(s, 2, &r.lat_deg, &r.lon_deg, problem)) return false;
        double knots = 0;
        if (!optional_number(f[6], &knots) || knots < 0) return fail(problem, s.type, "speed", f[6]);
        r.speed_mps = knots * kKnotToMps;
        if (!optional_number(f[7], &r.course_deg)) return fail(problem, s.type, "course", f[7]);
        int64_t days = 0;
        if (!f[8].empty()) {
            if (!nmea_date_days(f[8], &days)) return fail(problem, s.type, "date", f[8]);
            e->has_date = true;
            e->date_days = days;
        }
        e->rmc = r;
    } else if (s.type == "GSA") {
        NmeaEpoch::Gsa a;
        a.talker = std::string(s.talker);
        double mode = 0;
        if (parse_number(f[1], &mode) != NumberStatus::ok || (mode != 1 && mode != 2 && mode != 3))
            return fail(problem, s.type, "fix mode", f[1]);
        a.fix_mode = static_cast<int>(mode);
        for (size_t i = 2; i < 14; ++i) a.satellite_ids += f[i].empty() ? 0 : 1;
        double pdop = 0;
        if (!optional_number(f[14], &pdop)) return fail(problem, s.type, "PDOP", f[14]);
        if (!optional_number(f[15], &a.hdop)) return fail(problem, s.type, "HDOP", f[15]);
        if (!optional_number(f[16], &a.vdop)) return fail(problem, s.type, "VDOP", f[16]);
        e->gsa.push_back(a);
    } else if (s.type == "GST") {
        NmeaEpoch::Gst g;
        g.present = true;
        if (!optional_number(f[5], &g.sigma_lat_m)) return fail(problem, s.type, "latitude sigma", f[5]);
        if (!optional_number(f[6], &g.sigma_lon_m)) return fail(problem, s.type, "longitude sigma", f[6]);
        if (!optional_number(f[7], &g.sigma_alt_m)) return fail(problem, s.type, "altitude sigma", f[7]);
        e->gst = g;
    } else if (s.type == "VTG") {
        NmeaEpoch::Vtg v;
        v.present = true;
        const char mode = f.size() > 8 && f[8].size() == 1 ? f[8][0] : 0;
        v.valid = mode != 'N';
        if (!optional_number(f[0], &v.course_deg)) return fail(problem, s.type, "course", f[0]);
        double kmh = 0, knots = 0;
        if (!optional_number(f[6], &kmh) || kmh < 0) return fail(problem, s.type, "speed", f[6]);
        if (!optional_number(f[4], &knots) || knots < 0) return fail(problem, s.type, "speed", f[4]);
        v.speed_mps = std::isfinite(kmh) ? kmh * kKmhToMps : knots * kKnotToMps;
        e->vtg = v;
    } else if (s.type == "ZDA") {
        double day = 0, month = 0, year = 0;
        if (parse_number(f[1], &day) != NumberStatus::ok || parse_number(f[2], &month) != NumberStatus::ok ||
            parse_number(f[3], &year) != NumberStatus::ok || day < 1 || day > 31 || month < 1 || month > 12 ||
            year < 1980 || year > 2200)
            return fail(problem, s.type, "date", std::string(f[1]) + "," + std::string(f[2]) + "," + std::string(f[3]));
        e->has_date = true;
        e->date_days = days_from_civil(static_cast<int64_t>(year), static_cast<unsigned>(month),
                                       static_cast<unsigned>(day));
    }
    return true;
}

FixFields nmea_epoch_fix(const NmeaEpoch& e, NoFix* why) {
    FixFields f;
    *why = NoFix::none;
    const NmeaEpoch::Gga& gga = e.gga;
    // The GSAs that describe this solution: those of the GGA's talker, a
    // combined (GN) one, or, for a combined GGA, every constellation's. A GSA
    // of another talker (GLONASS beside a GPS-only GGA) describes another solution.
    std::vector<const NmeaEpoch::Gsa*> gsa;
    for (const auto& a : e.gsa) {
        if (!gga.present || a.talker == gga.talker || a.talker == "GN" || gga.talker == "GN") gsa.push_back(&a);
    }
    if (gga.present && gga.quality > 0 && std::isfinite(gga.lat_deg)) {
        if (gga.quality >= 7) {  // 7 manual input, 8 simulation
            *why = NoFix::not_measured;
            return f;
        }
        f.lat_deg = gga.lat_deg;
        f.lon_deg = gga.lon_deg;
        if (std::isfinite(gga.altitude_msl_m))
            f.height_m = gga.altitude_msl_m + (std::isfinite(gga.geoid_separation_m) ? gga.geoid_separation_m : 0.0);
        f.fix_type = gga.quality;
        f.hdop = gga.hdop;
        if (gga.satellites >= 0) {
            f.satellites = gga.satellites;
        } else {
            for (const auto* a : gsa) f.satellites += a->satellite_ids;
        }
    } else if (!gga.present && e.rmc.present && e.rmc.valid && std::isfinite(e.rmc.lat_deg)) {
        f.lat_deg = e.rmc.lat_deg;
        f.lon_deg = e.rmc.lon_deg;
        f.fix_type = fix_type_of_mode(e.rmc.mode);
        for (const auto* a : gsa) f.satellites += a->satellite_ids;
    } else {
        if (gga.present && gga.quality == 0)
            *why = NoFix::gga_quality_zero;
        else if (!gga.present && e.rmc.present && !e.rmc.valid)
            *why = NoFix::rmc_void;
        else
            *why = NoFix::no_position;
        return f;
    }
    if (!gsa.empty()) {
        if (!std::isfinite(f.hdop)) f.hdop = gsa.front()->hdop;
        f.vdop = gsa.front()->vdop;
        if (gsa.front()->fix_mode == 2) f.height_reliable = false;
    }
    if (e.gst.present && e.gst.sigma_lat_m > 0 && e.gst.sigma_lon_m > 0)
        f.h_sigma_m = std::hypot(e.gst.sigma_lat_m, e.gst.sigma_lon_m);
    if (e.gst.present && e.gst.sigma_alt_m > 0) f.v_sigma_m = e.gst.sigma_alt_m;
    if (e.rmc.present && e.rmc.valid && std::isfinite(e.rmc.speed_mps)) {
        f.speed_mps = e.rmc.speed_mps;
        f.course_deg = e.rmc.course_deg;
    } else if (e.vtg.present && e.vtg.valid && std::isfinite(e.vtg.speed_mps)) {
        f.speed_mps = e.vtg.speed_mps;
        f.course_deg = e.vtg.course_deg;
    }
    return f;
}

}  // namespace pednav::io::detail

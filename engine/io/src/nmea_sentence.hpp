// SPDX-License-Identifier: Apache-2.0
// Internal: one NMEA 0183 sentence ("$GPGGA,...*hh") taken apart, and the
// field types of the sentences the GNSS reader uses (time of day, latitude
// and longitude in degrees and minutes, date).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pednav::io::detail {

struct NmeaSentence {
    std::string_view talker;              // "GP", "GN", "GL", "GA", ...; "P" for a proprietary sentence
    std::string_view type;                // "GGA", "RMC", ...; the rest of the address when proprietary
    std::vector<std::string_view> fields;  // the data fields after the address, fields[0] the first
    bool text_before = false;             // the line had text before the '$' (a logger's prefix)
};

// Parses a line holding one sentence. Returns false with `problem` set when
// it is not a sentence or is damaged: no '$', no checksum, a checksum that
// does not match, an address that is not a talker and a sentence type.
bool parse_nmea_sentence(std::string_view line, NmeaSentence* out, std::string* problem);

// hhmmss or hhmmss.sss: nanoseconds since midnight.
bool nmea_time_of_day_ns(std::string_view field, int64_t* ns);
// ddmm.mmmm (latitude) or dddmm.mmmm (longitude) and its hemisphere letter:
// signed degrees (south and west negative).
bool nmea_latitude_deg(std::string_view value, std::string_view hemisphere, double* deg);
bool nmea_longitude_deg(std::string_view value, std::string_view hemisphere, double* deg);
// ddmmyy (years 80-99 are 19xx): days since 1970-01-01.
bool nmea_date_days(std::string_view field, int64_t* days);
// Days since 1970-01-01 of a civil date.
int64_t days_from_civil(int64_t year, unsigned month, unsigned day);

constexpr double kKnotToMps = 1852.0 / 3600.0;
constexpr double kKmhToMps = 1.0 / 3.6;
constexpr int64_t kDay_ns = 86400LL * 1000000000LL;

}  // namespace pednav::io::detail

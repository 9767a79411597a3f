// SPDX-License-Identifier: Apache-2.0
#include "nmea_sentence.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "pednav_io/text_fields.hpp"

namespace pednav::io::detail {

namespace {

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

bool all_digits(std::string_view s) {
    if (s.empty()) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    return true;
}

// "123.456" with a fixed number of digits before the point; false otherwise.
bool fixed_number(std::string_view s, size_t integer_digits, double* value) {
    const size_t point = s.find('.');
    const std::string_view whole = s.substr(0, point);
    if (whole.size() != integer_digits || !all_digits(whole)) return false;
    if (point != std::string_view::npos && point + 1 < s.size() && !all_digits(s.substr(point + 1))) return false;
    return parse_number(s, value) == NumberStatus::ok;
}

// ddmm.mmmm / dddmm.mmmm: `degree_digits` digits of degrees, then minutes.
bool degrees_minutes(std::string_view value, size_t degree_digits, double limit, double* deg) {
    double raw = 0.0;
    if (!fixed_number(value, degree_digits + 2, &raw)) return false;
    const double whole = std::floor(raw / 100.0);
    const double minutes = raw - 100.0 * whole;
    if (minutes >= 60.0 || whole > limit) return false;
    *deg = whole + minutes / 60.0;
    return *deg <= limit;
}

}  // namespace

bool parse_nmea_sentence(std::string_view line, NmeaSentence* out, std::string* problem) {
    line = trim(line);
    const size_t start = line.find_first_of("$!");
    if (start == std::string_view::npos) {
        *problem = "not an NMEA sentence (no '$')";
        return false;
    }
    out->text_before = start > 0;
    const std::string_view sentence = line.substr(start);
    const size_t star = sentence.rfind('*');
    if (star == std::string_view::npos) {
        *problem = "no checksum (*hh): truncated sentence?";
        return false;
    }
    const std::string_view body = sentence.substr(1, star - 1);
    const std::string_view given = trim(sentence.substr(star + 1));
    if (given.size() != 2 || hex_value(given[0]) < 0 || hex_value(given[1]) < 0) {
        *problem = "bad checksum field '*" + std::string(given.substr(0, 8)) + "': truncated sentence?";
        return false;
    }
    unsigned sum = 0;
    for (char c : body) sum ^= static_cast<unsigned char>(c);
    const unsigned expected = static_cast<unsigned>(hex_value(given[0]) * 16 + hex_value(given[1]));
    const size_t comma = body.find(',');
    const std::string_view address = body.substr(0, comma);
    if (sum != expected) {
        char text[120];
        std::snprintf(text, sizeof text, "checksum mismatch in %.*s: computed %02X, the sentence says %02X",
                      static_cast<int>(std::min<size_t>(address.size(), 10)), address.data(), sum, expected);
        *problem = text;
        return false;
    }
    for (char c : address) {
        if (!std::isupper(static_cast<unsigned char>(c)) && !std::isdigit(static_cast<unsigned char>(c))) {
            *problem = "bad address '" + std::string(address.substr(0, 10)) + "'";
            return false;
        }
    }
    if (!address.empty() && address[0] == 'P') {
        out->talker = address.substr(0, 1);
        out->type = address.substr(1);
    } else if (address.size() == 5) {
        out->talker = address.substr(0, 2);
        out->type = address.substr(2);
    } else {
        *problem = "bad address '" + std::string(address.substr(0, 10)) +
                   "': a two-letter talker and a three-letter sentence type expected";
        return false;
    }
    out->fields.clear();
    if (comma != std::string_view::npos) split_into(body.substr(comma + 1), ',', out->fields);
    return true;
}

bool nmea_time_of_day_ns(std::string_view field, int64_t* ns) {
    const size_t point = field.find('.');
    const std::string_view whole = field.substr(0, point);
    if (whole.size() != 6 || !all_digits(whole)) return false;
    const int h = (whole[0] - '0') * 10 + (whole[1] - '0');
    const int m = (whole[2] - '0') * 10 + (whole[3] - '0');
    double s = 0.0;
    if (!fixed_number(field.substr(4), 2, &s)) return false;
    if (h > 23 || m > 59 || s >= 61.0) return false;
    *ns = (static_cast<int64_t>(h) * 3600 + m * 60) * 1000000000LL + std::llround(s * 1e9);
    return true;
}

bool nmea_latitude_deg(std::string_view value, std::string_view hemisphere, double* deg) {
    if (!degrees_minutes(value, 2, 90.0, deg)) return false;
    if (hemisphere == "S") *deg = -*deg;
    return hemisphere == "N" || hemisphere == "S";
}

bool nmea_longitude_deg(std::string_view value, std::string_view hemisphere, double* deg) {
    if (!degrees_minutes(value, 3, 180.0, deg)) return false;
    if (hemisphere == "W") *deg = -*deg;
    return hemisphere == "E" || hemisphere == "W";
}

int64_t days_from_civil(int64_t y, unsigned m, unsigned d) {
    // H. Hinnant's algorithm: proleptic Gregorian calendar.
    y -= m <= 2;
    const int64_t era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = static_cast<unsigned>(y - era * 400);
    const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + static_cast<int64_t>(doe) - 719468;
}

bool nmea_date_days(std::string_view field, int64_t* days) {
    if (field.size() != 6 || !all_digits(field)) return false;
    const unsigned d = static_cast<unsigned>((field[0] - '0') * 10 + (field[1] - '0'));
    const unsigned m = static_cast<unsigned>((field[2] - '0') * 10 + (field[3] - '0'));
    const int yy = (field[4] - '0') * 10 + (field[5] - '0');
    if (d < 1 || d > 31 || m < 1 || m > 12) return false;
    *days = days_from_civil(yy >= 80 ? 1900 + yy : 2000 + yy, m, d);
    return true;
}

}  // namespace pednav::io::detail

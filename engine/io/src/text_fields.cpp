// SPDX-License-Identifier: Apache-2.0
#include "pednav_io/text_fields.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace pednav::io {

namespace {

// Every power of ten up to 1e22 is a double exactly (5^22 < 2^53).
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// The digits from p on into m (m 10^count + their value); returns where they end.
const char* take_digits(const char* p, const char* end, uint64_t& m) {
    unsigned d = 0;
    while (p != end && (d = static_cast<unsigned char>(*p) - '0') < 10) {
        m = 10 * m + d;
        ++p;
    }
    return p;
}

// A decimal [-]digits[.digits][(e|E)[+|-]digits] whose significant digits
// make an integer m <= 2^53 and whose scale 10^q has |q| <= 22: m and 10^|q|
// are doubles exactly, so m * 10^q (or m / 10^-q) carries the one rounding of
// the exact value, which is what std::from_chars returns (Clinger's fast path).
// False for anything else: from_chars decides.
bool parse_decimal_fast(const char* p, const char* end, double* value) {
    const bool negative = p != end && *p == '-';
    if (negative) ++p;
    // Every digit goes into m; more than 19 digit characters could overflow it
    // (leading zeros included, which only the rare long fraction has): those
    // are left to from_chars.
    uint64_t m = 0;
    const char* const int_begin = p;
    p = take_digits(p, end, m);
    ptrdiff_t digit_chars = p - int_begin;
    int scale = 0;  // the value is m 10^scale
    if (p != end && *p == '.') {
        const char* const frac_begin = ++p;
        p = take_digits(p, end, m);
        scale = -static_cast<int>(p - frac_begin);
        digit_chars += p - frac_begin;
    }
    if (digit_chars == 0 || digit_chars > 19) return false;
    if (p != end && (*p == 'e' || *p == 'E')) {
        ++p;
        const bool exp_negative = p != end && *p == '-';
        if (p != end && (*p == '-' || *p == '+')) ++p;
        const char* const exp_begin = p;
        int e = 0;
        unsigned d = 0;
        while (p != end && (d = static_cast<unsigned char>(*p) - '0') < 10 && e < 1000) {
            e = 10 * e + static_cast<int>(d);
            ++p;
        }
        if (p == exp_begin) return false;
        scale += exp_negative ? -e : e;
    }
    if (p != end || m > (uint64_t{1} << 53) || scale < -22 || scale > 22) return false;
    double v = static_cast<double>(m);  // exact
    v = scale < 0 ? v / kPow10[-scale] : v * kPow10[scale];
    *value = negative ? -v : v;
    return true;
}

}  // namespace

namespace {
// One comparison for the characters of a field (all above ' ').
bool is_blank(char c) { return c <= ' ' && (c == ' ' || c == '\t' || c == '\r'); }
}  // namespace

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
    return s;
}

void split_into(std::string_view line, char delim, std::vector<std::string_view>& out) {
    out.clear();
    if (delim == ' ') {
        size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
            if (i >= line.size()) break;
            size_t j = i;
            while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
            out.push_back(line.substr(i, j - i));
            i = j;
        }
        return;
    }
    size_t start = 0;
    while (true) {
        size_t end = line.find(delim, start);
        if (end == std::string_view::npos) {
            out.push_back(trim(line.substr(start)));
            break;
        }
        out.push_back(trim(line.substr(start, end - start)));
        start = end + 1;
    }
}

std::vector<std::string_view> split(std::string_view line, char delim) {
    std::vector<std::string_view> out;
    split_into(line, delim, out);
    return out;
}

NumberStatus parse_number(std::string_view field, double* value) {
    field = trim(field);
    if (field.empty()) return NumberStatus::empty;
    if (field.front() == '+') field.remove_prefix(1);
    double v = 0.0;
    const char* first = field.data();
    const char* last = field.data() + field.size();
    if (parse_decimal_fast(first, last, &v)) {
        *value = v;
        return NumberStatus::ok;
    }
    auto result = std::from_chars(first, last, v);
    if (result.ec != std::errc() || result.ptr != last) {
        if (result.ec == std::errc::result_out_of_range && result.ptr == last)
            return NumberStatus::non_finite;
        return NumberStatus::not_a_number;
    }
    *value = v;
    if (!std::isfinite(v)) return NumberStatus::non_finite;
    return NumberStatus::ok;
}

std::string describe_bad_number(NumberStatus status, std::string_view field, std::string_view column) {
    std::string text;
    switch (status) {
        case NumberStatus::empty: text = "empty value"; break;
        case NumberStatus::non_finite: text = "non-finite value '" + std::string(trim(field)) + "'"; break;
        default: text = "not a number: '" + std::string(trim(field).substr(0, 40)) + "'"; break;
    }
    if (!column.empty()) text += " in column " + std::string(column);
    return text;
}

int find_column(const std::vector<std::string>& names, const std::string& name) {
    for (size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace pednav::io

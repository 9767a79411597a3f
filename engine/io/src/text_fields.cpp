// SPDX-License-Identifier: Apache-2.0
#include "pednav_io/text_fields.hpp"

#include <charconv>
#include <cmath>

namespace pednav::io {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
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

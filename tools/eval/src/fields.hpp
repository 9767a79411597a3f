// SPDX-License-Identifier: Apache-2.0
// Internal: the track and truth readers split lines and parse numbers with the
// rules of the recording readers (pednav_io/text_fields.hpp), and stop at the
// first bad value.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <pednav_io/text_fields.hpp>

namespace pednav::eval::detail {

// The number in `field`; throws std::runtime_error "path:line: not a number: 'x' in column c".
inline double number(std::string_view field, const std::string& path, size_t line, std::string_view column = {}) {
    double v = 0.0;
    const io::NumberStatus status = io::parse_number(field, &v);
    if (status != io::NumberStatus::ok)
        throw std::runtime_error(path + ":" + std::to_string(line) + ": " +
                                 io::describe_bad_number(status, field, column));
    return v;
}

inline std::vector<std::string> to_strings(const std::vector<std::string_view>& fields) {
    return {fields.begin(), fields.end()};
}

}  // namespace pednav::eval::detail

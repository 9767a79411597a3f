// SPDX-License-Identifier: Apache-2.0
// Internal: a text file held in memory as lines; field helpers are public in
// pednav_io/text_fields.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "pednav_io/text_fields.hpp"

namespace pednav::io::detail {

struct TextFile {
    std::string path;
    std::string data;                     // whole file
    std::vector<std::string_view> lines;  // without "\n" / "\r\n"; lines[i] is line i + 1
};

// Loads a file; throws ReadError when missing, unreadable, empty or binary.
TextFile load_text_file(const std::string& path);

// trim, split, split_into, parse_number, describe_bad_number, find_column:
// pednav_io/text_fields.hpp (namespace pednav::io).

// Picks the delimiter of a header line among ',', '\t', ';' and ' '.
char guess_delimiter(std::string_view header);

std::string to_lower(std::string_view s);
bool starts_with(std::string_view s, std::string_view prefix);
bool ends_with(std::string_view s, std::string_view suffix);

}  // namespace pednav::io::detail

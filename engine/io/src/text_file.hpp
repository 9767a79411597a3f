// Internal: a text file held in memory as lines, and strict field parsing.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace pednav::io::detail {

struct TextFile {
    std::string path;
    std::string data;                     // whole file
    std::vector<std::string_view> lines;  // without "\n" / "\r\n"; lines[i] is line i + 1
};

// Loads a file; throws ReadError when missing, unreadable, empty or binary.
TextFile load_text_file(const std::string& path);

std::string_view trim(std::string_view s);

// Splits on `delim`; with delim == ' ' any run of spaces or tabs separates.
std::vector<std::string_view> split(std::string_view line, char delim);
void split_into(std::string_view line, char delim, std::vector<std::string_view>& out);

enum class NumberStatus { ok, empty, not_a_number, non_finite };

// Parses the whole trimmed field as a double (locale-independent).
NumberStatus parse_number(std::string_view field, double* value);

// "bad value 'abc' in column Acc_X" style text for a failed parse.
std::string describe_bad_number(NumberStatus status, std::string_view field, std::string_view column);

// Picks the delimiter of a header line among ',', '\t', ';' and ' '.
char guess_delimiter(std::string_view header);

std::string to_lower(std::string_view s);
bool starts_with(std::string_view s, std::string_view prefix);
bool ends_with(std::string_view s, std::string_view suffix);

}  // namespace pednav::io::detail

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

class LineReader;

struct TextFile {
    std::string path;
    std::string data;                     // the lines, without their ends
    std::vector<std::string_view> lines;  // lines[i] is line i + 1
};

// Lines added one at a time (copied), then seen as a TextFile.
class TextFileBuilder {
public:
    explicit TextFileBuilder(std::string path) { file_.path = std::move(path); }
    void add(std::string_view line);
    size_t size() const { return ends_.size(); }
    // The lines added so far; the reference stays valid, the views until the next add().
    const TextFile& file();
    // The lines, moved out (the builder is then empty).
    TextFile take();

private:
    TextFile file_;
    std::vector<size_t> ends_;  // end of each line in file_.data
};

// Loads a whole file (LineReader's checks); throws ReadError when missing,
// unreadable, empty, blank or binary.
TextFile load_text_file(const std::string& path);

// Adds every remaining line of `reader` to `builder`.
void add_remaining_lines(LineReader& reader, TextFileBuilder& builder);

// trim, split, split_into, parse_number, describe_bad_number, find_column:
// pednav_io/text_fields.hpp (namespace pednav::io).

// Picks the delimiter of a header line among ',', '\t', ';' and ' '.
char guess_delimiter(std::string_view header);

std::string to_lower(std::string_view s);
bool starts_with(std::string_view s, std::string_view prefix);
bool ends_with(std::string_view s, std::string_view suffix);

}  // namespace pednav::io::detail

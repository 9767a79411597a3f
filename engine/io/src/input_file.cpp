// SPDX-License-Identifier: Apache-2.0
#include "input_file.hpp"

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

namespace {

constexpr size_t kHeadContentLines = 100;
constexpr size_t kHeadBytes = size_t{4} << 20;

bool is_comment(std::string_view trimmed) {
    return trimmed[0] == '#' || trimmed[0] == '%' || starts_with(trimmed, "//");
}

}  // namespace

InputFile::InputFile(const std::string& path) : reader_(path), head_(path) {
    size_t content = 0, bytes = 0;
    bool any_text = false;
    std::string_view line;
    while (content < kHeadContentLines && bytes < kHeadBytes && reader_.next(&line)) {
        head_.add(line);
        bytes += line.size() + 1;
        const std::string_view t = trim(line);
        if (t.empty()) continue;
        any_text = true;
        if (!is_comment(t)) ++content;
    }
    head_file_ = &head_.file();
    if (any_text) return;
    // Only blank lines so far: the file is empty unless text follows.
    while (reader_.next(&line)) {
        if (!trim(line).empty())
            throw ReadError(path, reader_.line_number(),
                            "more than " + std::to_string(kHeadBytes >> 20) +
                                " MiB of blank lines before the first text: not a recording");
    }
    throw ReadError(path, 0, "the file is empty (only blank lines)");
}

void InputFile::extend_head(size_t lines) {
    std::string_view line;
    while (head_.size() < lines && reader_.next(&line)) head_.add(line);
    head_file_ = &head_.file();
}

TextFile InputFile::read_all() {
    add_remaining_lines(reader_, head_);
    TextFile all = head_.take();
    head_file_ = &head_.file();
    return all;
}

bool LineCursor::next(std::string_view* line, size_t* line_no) {
    const TextFile& head = input_.head();
    cut_ = false;
    if (index_ < head.lines.size()) {
        *line = head.lines[index_++];
        *line_no = index_;
        return true;
    }
    LineReader& rest = input_.rest();
    while (rest.line_number() < index_) {  // a first line beyond the head
        std::string_view skipped;
        if (!rest.next(&skipped)) return false;
    }
    if (!rest.next(line)) return false;
    ++index_;
    *line_no = rest.line_number();
    cut_ = rest.line_cut();
    return true;
}

}  // namespace pednav::io::detail

// SPDX-License-Identifier: Apache-2.0
// Internal: a recording file opened for reading. Its head (the first lines:
// enough to detect the format and read a header or preamble) is held in
// memory; the lines after it are read on demand, in order.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "line_reader.hpp"
#include "text_file.hpp"

namespace pednav::io::detail {

class InputFile {
public:
    // Opens `path` and reads its head: lines up to the 100th that is not blank
    // or a comment ('#', '%', '//'), at most 4 MiB. Throws ReadError as
    // load_text_file does (missing, empty, only blank lines, binary).
    explicit InputFile(const std::string& path);

    const std::string& path() const { return reader_.path(); }
    const TextFile& head() const { return *head_file_; }
    // Reads more lines into the head until it holds `lines` lines or the file ends.
    void extend_head(size_t lines);
    // The lines after the head.
    LineReader& rest() { return reader_; }
    // The whole file in memory: the head and every line after it (for a
    // format read whole). Call once, before reading rest().
    TextFile read_all();

private:
    LineReader reader_;
    TextFileBuilder head_;
    const TextFile* head_file_ = nullptr;  // head_.file(), made again when it grows
};

// The lines of an InputFile from 0-based index `first` on: the head's, then the rest's.
class LineCursor {
public:
    LineCursor(InputFile& input, size_t first) : input_(input), index_(first) {}
    // The next line and its 1-based number; false at the end of the file.
    bool next(std::string_view* line, size_t* line_no);
    // The line last given was cut at LineReader::kMaxLineBytes.
    bool line_cut() const { return cut_; }

private:
    InputFile& input_;
    size_t index_;
    bool cut_ = false;
};

}  // namespace pednav::io::detail

// SPDX-License-Identifier: Apache-2.0
// Internal: a text file read a chunk at a time and cut into lines, in memory
// bounded by the chunk and the longest line. The one place where lines are
// cut (LF, CR LF or a lone CR) and where a file is found to be text:
//   - a UTF-16 start is refused; a UTF-8 byte order mark is skipped;
//   - a NUL byte in the first 64 KiB is refused at once; one further on ends
//     the file there: the lines before it are given, then the refusal;
//   - more than 5 % control characters (other than tab, CR, LF) is refused,
//     judged on the first KiB, on the first 64 KiB and on the whole file;
//   - a pipe or device (no size) is cut at 1 GiB: reading must end.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace pednav::io::detail {

class LineReader {
public:
    // Opens `path` and checks its first 64 KiB; throws ReadError naming the
    // file when it is missing, a folder, unreadable, empty or not text.
    explicit LineReader(const std::string& path);
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    // The next line, without its end; false at the end of the file. The view
    // stays valid until the next call. Throws ReadError when the rest of the
    // file cannot be read, or at a NUL byte (after the lines before it).
    bool next(std::string_view* line);
    // 1-based number of the line last returned (0 before the first).
    size_t line_number() const { return line_number_; }
    // The line last returned was longer than kMaxLineBytes: only its start is given.
    bool line_cut() const { return line_cut_; }

    const std::string& path() const { return path_; }
    uint64_t bytes_read() const { return offset_; }
    // The file's size, 0 for a pipe or device.
    uint64_t size_bytes() const { return size_bytes_; }

    // A line longer than this is cut: a recording's rows are far shorter.
    static constexpr size_t kMaxLineBytes = size_t{16} << 20;

private:
    // Reads more after [begin_, end_) (moved to the front); false at the end of the file.
    bool fill();
    // Checks the bytes just read, at [from, to) of buffer_.
    void check_bytes(size_t from, size_t to);
    void check_control_share() const;
    [[noreturn]] void refuse_nul(uint64_t offset) const;

    std::string path_;
    int fd_ = -1;
    bool regular_ = true;
    uint64_t size_bytes_ = 0;
    std::string buffer_;
    size_t begin_ = 0, end_ = 0;  // unread bytes of buffer_
    bool eof_ = false;
    uint64_t nul_offset_ = 0;  // of a NUL byte past the first 64 KiB: the file ends there
    bool nul_ = false;
    uint64_t offset_ = 0;         // bytes read from the file
    uint64_t control_bytes_ = 0;  // control characters among them
    bool wide_checked_ = false;
    size_t line_number_ = 0;
    bool line_cut_ = false;
    bool skipping_ = false;  // inside the rest of a cut line
};

}  // namespace pednav::io::detail

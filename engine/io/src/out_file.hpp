// SPDX-License-Identifier: Apache-2.0
// Internal: an output file that reports a failed write, with a text buffer
// for the writers of one row per output: numbers formatted as printf formats
// them (decimal_format.hpp) and handed to the C library 64 KiB at a time.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace pednav::io::detail {

class OutFile {
public:
    // Throws std::runtime_error when the file cannot be opened for writing.
    explicit OutFile(const std::string& path);
    ~OutFile();
    OutFile(const OutFile&) = delete;
    OutFile& operator=(const OutFile&) = delete;

    // The file for direct writes; the buffered text goes to it first.
    std::FILE* get();
    // What is written so far goes to the file: it outlives a crash of the process.
    void flush();
    // Throws std::runtime_error when any write failed.
    void close();

    // Buffered text.
    void fixed(double x, int decimals);       // printf "%.*f"
    void general(double x, int significant);  // printf "%.*g"
    void integer(long long v);                // printf "%lld"
    void text(std::string_view s);
    void put(char c) {
        if (used_ == kBufferBytes) spill();
        buffer_[used_++] = c;
    }

private:
    static constexpr size_t kBufferBytes = 64 * 1024;
    char* room(size_t bytes);  // at least `bytes` free at the end of the buffer
    void spill();              // the buffer to the file

    std::string path_;
    std::FILE* file_;
    std::unique_ptr<char[]> buffer_;
    size_t used_ = 0;
};

}  // namespace pednav::io::detail

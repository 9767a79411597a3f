// SPDX-License-Identifier: Apache-2.0
#include "out_file.hpp"

#include <charconv>
#include <cstring>
#include <stdexcept>

#include "decimal_format.hpp"

namespace pednav::io::detail {

OutFile::OutFile(const std::string& path)
    : path_(path), file_(std::fopen(path.c_str(), "w")), buffer_(new char[kBufferBytes]) {
    if (file_ == nullptr) throw std::runtime_error(path + ": cannot open for writing");
}

OutFile::~OutFile() {
    if (file_ == nullptr) return;
    spill();
    std::fclose(file_);
}

std::FILE* OutFile::get() {
    spill();
    return file_;
}

void OutFile::flush() {
    spill();
    if (std::fflush(file_) != 0) throw std::runtime_error(path_ + ": write failed");
}

void OutFile::close() {
    spill();
    const bool failed = std::ferror(file_) != 0;
    const int rc = std::fclose(file_);
    file_ = nullptr;
    if (failed || rc != 0) throw std::runtime_error(path_ + ": write failed");
}

void OutFile::spill() {
    // A failed write sets the stream's error flag, which close() reports.
    if (used_ != 0) std::fwrite(buffer_.get(), 1, used_, file_);
    used_ = 0;
}

char* OutFile::room(size_t bytes) {
    if (kBufferBytes - used_ < bytes) spill();
    return buffer_.get() + used_;
}

void OutFile::fixed(double x, int decimals) {
    char* at = room(kMaxDecimalChars);
    used_ = static_cast<size_t>(format_fixed(at, x, decimals) - buffer_.get());
}

void OutFile::general(double x, int significant) {
    char* at = room(kMaxDecimalChars);
    used_ = static_cast<size_t>(format_general(at, x, significant) - buffer_.get());
}

void OutFile::integer(long long v) {
    char* at = room(24);
    used_ = static_cast<size_t>(std::to_chars(at, at + 24, v).ptr - buffer_.get());
}

void OutFile::text(std::string_view s) {
    if (s.size() > kBufferBytes) {
        spill();
        std::fwrite(s.data(), 1, s.size(), file_);
        return;
    }
    std::memcpy(room(s.size()), s.data(), s.size());
    used_ += s.size();
}

}  // namespace pednav::io::detail

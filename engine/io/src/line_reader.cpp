// SPDX-License-Identifier: Apache-2.0
#include "line_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

namespace {

// Recordings are text; a device (/dev/zero), a pipe or a file that is not text
// must be refused after its first KiB, not after reading all of it.
constexpr size_t kProbeBytes = 1024;
constexpr uint64_t kWideProbeBytes = 65536;
constexpr size_t kChunkBytes = size_t{64} << 10;
// A pipe or device has no size to read up to; text beyond this is refused.
constexpr uint64_t kMaxStreamBytes = uint64_t{1} << 30;

// Control characters other than tab, CR, LF in [p, p + n); sets *nul when a NUL is among them.
uint64_t count_control(const unsigned char* p, size_t n, bool* nul) {
    uint64_t control = 0;
    unsigned char zero = 0;
    while (n > 0) {  // blocks a 32-bit count holds: the inner loop vectorises
        const size_t m = n < 4096 ? n : 4096;
        uint32_t block = 0;
        for (size_t i = 0; i < m; ++i) {
            const unsigned char c = p[i];
            block += (c < 32) & (c != '\t') & (c != '\r') & (c != '\n');
            zero |= (c == 0);
        }
        control += block;
        p += m;
        n -= m;
    }
    *nul = zero != 0;
    return control;
}

}  // namespace

LineReader::LineReader(const std::string& path) : path_(path) {
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) throw ReadError(path, 0, "file not found");
    if (S_ISDIR(st.st_mode)) throw ReadError(path, 0, "is a folder, not a file");
    fd_ = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0)
        throw ReadError(path, 0, std::string("cannot open the file for reading: ") + std::strerror(errno));
    regular_ = S_ISREG(st.st_mode);
    size_bytes_ = regular_ ? static_cast<uint64_t>(st.st_size) : 0;
    buffer_.resize(kChunkBytes);
    try {
        // The first KiB alone, as a device gives it, then up to 64 KiB before any line is cut.
        ssize_t got;
        do {
            got = read(fd_, &buffer_[0], kProbeBytes);
        } while (got < 0 && errno == EINTR);
        if (got < 0) throw ReadError(path, 0, std::string("cannot read the file: ") + std::strerror(errno));
        if (got >= 2 && ((buffer_[0] == '\xff' && buffer_[1] == '\xfe') ||
                         (buffer_[0] == '\xfe' && buffer_[1] == '\xff')))
            throw ReadError(path, 0, "UTF-16 text: save the file as UTF-8 or ASCII");
        end_ = static_cast<size_t>(got);
        offset_ = end_;
        if (got == 0) eof_ = true;
        check_bytes(0, end_);
        check_control_share();
        while (!eof_ && offset_ < kWideProbeBytes) fill();
        if (offset_ == 0) throw ReadError(path, 0, "the file is empty");
        if (end_ >= 3 && buffer_.compare(0, 3, "\xef\xbb\xbf") == 0) begin_ = 3;  // UTF-8 byte order mark
    } catch (...) {
        close(fd_);
        throw;
    }
}

LineReader::~LineReader() {
    if (fd_ >= 0) close(fd_);
}

void LineReader::check_bytes(size_t from, size_t to) {
    const uint64_t start = offset_ - (to - from);  // file offset of buffer_[from]
    const auto* p = reinterpret_cast<const unsigned char*>(buffer_.data());
    size_t split = to;
    if (!wide_checked_ && start + (to - from) >= kWideProbeBytes)
        split = from + static_cast<size_t>(kWideProbeBytes - start);
    for (const auto& [a, b] :
         {std::pair<size_t, size_t>{from, split}, std::pair<size_t, size_t>{split, to}}) {
        bool nul = false;
        control_bytes_ += count_control(p + a, b - a, &nul);
        if (nul) {
            const void* at = std::memchr(p + a, 0, b - a);
            const size_t i = static_cast<size_t>(static_cast<const unsigned char*>(at) - p);
            const uint64_t offset = start + (i - from);
            if (offset < kWideProbeBytes) refuse_nul(offset);  // not a text file
            // Corrupt further on (a log cut by a power loss is padded with zeros):
            // the text before it is read, then the file is refused.
            nul_ = true;
            nul_offset_ = offset;
            end_ = i;
            eof_ = true;
            return;
        }
        if (b == split && !wide_checked_ && start + (split - from) == kWideProbeBytes) {
            wide_checked_ = true;
            if (control_bytes_ * 20 > kWideProbeBytes)
                throw ReadError(path_, 0, "binary file (control characters), not a text recording");
        }
    }
}

void LineReader::refuse_nul(uint64_t offset) const {
    throw ReadError(path_, 0, "binary file (a NUL byte at offset " + std::to_string(offset) + "), not a text recording");
}

void LineReader::check_control_share() const {
    if (control_bytes_ * 20 > offset_)
        throw ReadError(path_, 0, "binary file (control characters), not a text recording");
}

bool LineReader::fill() {
    if (eof_) return false;
    if (begin_ > 0) {
        std::memmove(&buffer_[0], &buffer_[begin_], end_ - begin_);
        end_ -= begin_;
        begin_ = 0;
    }
    if (end_ == buffer_.size()) buffer_.resize(buffer_.size() * 2);
    ssize_t got;
    do {
        got = read(fd_, &buffer_[end_], buffer_.size() - end_);
    } while (got < 0 && errno == EINTR);
    if (got < 0) throw ReadError(path_, 0, std::string("cannot read the file: ") + std::strerror(errno));
    if (got == 0) {
        eof_ = true;
        check_control_share();  // the whole file
        return false;
    }
    const size_t from = end_;
    end_ += static_cast<size_t>(got);
    offset_ += static_cast<uint64_t>(got);
    check_bytes(from, end_);
    if (nul_) return false;
    if (!regular_ && offset_ > kMaxStreamBytes) {
        throw ReadError(path_, 0,
                        "more than " + std::to_string(kMaxStreamBytes >> 20) +
                            " MiB from a pipe or device without an end: write it to a file first");
    }
    return true;
}

bool LineReader::next(std::string_view* line) {
    line_cut_ = false;
    if (skipping_) begin_ = end_;  // the rest of a cut line: drop up to its end
    size_t scanned = 0;            // bytes after begin_ known to hold no line end
    for (;;) {
        const char* base = buffer_.data();
        const char* from = base + begin_ + scanned;
        const char* to = base + end_;
        const char* lf = static_cast<const char*>(std::memchr(from, '\n', static_cast<size_t>(to - from)));
        const char* limit = lf != nullptr ? lf : to;
        const char* cr = static_cast<const char*>(std::memchr(from, '\r', static_cast<size_t>(limit - from)));
        const size_t e = static_cast<size_t>((cr != nullptr ? cr : limit) - base);
        if (e < end_) {
            if (base[e] == '\r' && e + 1 == end_ && !eof_) {  // CR LF split by the chunk?
                scanned = e - begin_;
                fill();
                continue;
            }
            const size_t start = begin_;
            begin_ = e + 1;
            if (base[e] == '\r' && begin_ < end_ && base[begin_] == '\n') ++begin_;
            if (skipping_) {
                skipping_ = false;
                scanned = 0;
                continue;
            }
            *line = std::string_view(base + start, e - start);
            ++line_number_;
            return true;
        }
        if (eof_) {
            if (skipping_) {
                skipping_ = false;
                begin_ = end_;
            }
            if (nul_) refuse_nul(nul_offset_);  // the line it is on is lost with it
            if (begin_ == end_) return false;
            *line = std::string_view(base + begin_, end_ - begin_);
            begin_ = end_;
            ++line_number_;
            return true;
        }
        if (skipping_) {
            begin_ = end_;
            scanned = 0;
        } else if (end_ - begin_ >= kMaxLineBytes) {
            *line = std::string_view(base + begin_, kMaxLineBytes);
            line_cut_ = true;
            skipping_ = true;
            ++line_number_;
            return true;
        } else {
            scanned = end_ - begin_;
        }
        fill();
    }
}

}  // namespace pednav::io::detail

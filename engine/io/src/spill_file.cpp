// SPDX-License-Identifier: Apache-2.0
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "spill_vector.hpp"

namespace pednav::io::detail {

namespace {

// An unnamed file in $TMPDIR (else /tmp): created, then unlinked at once.
int temporary_file() {
    const char* dir = std::getenv("TMPDIR");
    std::string path = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/pednav-spill-XXXXXX";
    const int fd = mkostemp(&path[0], O_CLOEXEC);
    if (fd >= 0) unlink(path.c_str());
    return fd;
}

}  // namespace

SpillFile::~SpillFile() {
    if (fd_ >= 0) close(fd_);
}

bool SpillFile::append(const void* data, size_t bytes) {
    if (failed_) return false;
    if (fd_ < 0) {
        fd_ = temporary_file();
        if (fd_ < 0) {
            failed_ = true;
            return false;
        }
    }
    const char* p = static_cast<const char*>(data);
    size_t done = 0;
    while (done < bytes) {
        const ssize_t n = pwrite(fd_, p + done, bytes - done, static_cast<off_t>(size_ + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {  // disk full: this block stays in memory, and the ones after it
            failed_ = true;
            return false;
        }
        done += static_cast<size_t>(n);
    }
    size_ += bytes;
    return true;
}

void SpillFile::read(uint64_t offset, void* data, size_t bytes) const {
    char* p = static_cast<char*>(data);
    size_t done = 0;
    while (done < bytes) {
        const ssize_t n = pread(fd_, p + done, bytes - done, static_cast<off_t>(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            throw std::runtime_error(std::string("cannot read back a temporary file: ") +
                                     (n < 0 ? std::strerror(errno) : "it is shorter than written"));
        done += static_cast<size_t>(n);
    }
}

}  // namespace pednav::io::detail

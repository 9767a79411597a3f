// SPDX-License-Identifier: Apache-2.0
// Internal: what the writers of run outputs share: an output file that reports
// a failed write, and the fields of positions and strides as written.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <pednav/pn_types.h>

namespace pednav::io::detail {

constexpr double kRadToDeg = 57.29577951308232;

class OutFile {
public:
    explicit OutFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "w")) {
        if (file_ == nullptr) throw std::runtime_error(path + ": cannot open for writing");
    }
    ~OutFile() {
        if (file_ != nullptr) std::fclose(file_);
    }
    OutFile(const OutFile&) = delete;
    OutFile& operator=(const OutFile&) = delete;
    std::FILE* get() { return file_; }
    // What is written so far goes to the file: it outlives a crash of the process.
    void flush() {
        if (std::fflush(file_) != 0) throw std::runtime_error(path_ + ": write failed");
    }
    void close() {
        const bool failed = std::ferror(file_) != 0;
        const int rc = std::fclose(file_);
        file_ = nullptr;
        if (failed || rc != 0) throw std::runtime_error(path_ + ": write failed");
    }

private:
    std::string path_;
    std::FILE* file_;
};

inline double heading_deg(double heading_rad) {
    double d = std::fmod(heading_rad * kRadToDeg, 360.0);
    if (d < 0) d += 360.0;
    return d;
}

inline const char* class_name(int32_t c) {
    switch (c) {
        case PN_STRIDE_CLASS_LEVEL: return "level";
        case PN_STRIDE_CLASS_STAIRS_UP: return "stairs_up";
        case PN_STRIDE_CLASS_STAIRS_DOWN: return "stairs_down";
        default: return "unknown";
    }
}

inline bool has_floor(const pn_position_t& p) { return (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) != 0; }

inline double h_sigma_m(const pn_position_t& p) {
    return std::sqrt(std::max(0.0, p.cov_enu_m2[0] + p.cov_enu_m2[4]));
}

}  // namespace pednav::io::detail

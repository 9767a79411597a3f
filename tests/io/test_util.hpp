// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the io tests.
#pragma once

#include <sys/stat.h>
#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::test {

inline std::string data_dir() { return PEDNAV_SHARED_DATA_DIR; }

inline bool exists(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0;
}

// Folders made by temp_dir(); test_main.cpp removes them when the run ends.
inline std::vector<std::string>& temp_dirs() {
    static std::vector<std::string> dirs;
    return dirs;
}

// A fresh folder under TMPDIR for files a test writes.
inline std::string temp_dir() {
    const char* base = std::getenv("TMPDIR");
    std::string templ = std::string(base ? base : "/tmp") + "/pednav_io_test_XXXXXX";
    char* made = mkdtemp(templ.data());
    if (made == nullptr) return std::string();
    temp_dirs().emplace_back(made);
    return made;
}

inline std::string write_file(const std::string& dir, const std::string& name, const std::string& content) {
    std::string path = dir + "/" + name;
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
}

inline double norm3(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Mean of accel over the first n IMU samples.
inline void mean_accel(const SensorLog& log, size_t n, double out[3]) {
    out[0] = out[1] = out[2] = 0.0;
    n = std::min(n, log.imu.size());
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) out[k] += log.imu[i].accel_mps2[k] / static_cast<double>(n);
    }
}

inline double max_gyro_norm(const SensorLog& log) {
    double m = 0.0;
    for (const auto& r : log.imu) m = std::max(m, norm3(r.gyro_radps));
    return m;
}

inline double max_accel_norm(const SensorLog& log) {
    double m = 0.0;
    for (const auto& r : log.imu) m = std::max(m, norm3(r.accel_mps2));
    return m;
}

inline bool has_issue(const SensorLog& log, size_t line, const std::string& text) {
    for (const auto& i : log.issues) {
        if (i.line == line && i.message.find(text) != std::string::npos) return true;
    }
    return false;
}

}  // namespace pednav::io::test

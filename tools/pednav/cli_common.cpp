// SPDX-License-Identifier: Apache-2.0
#include "cli_common.hpp"

#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <pednav_io/text_fields.hpp>

#ifndef PEDNAV_PLUGIN_DIR_FROM_BIN
#define PEDNAV_PLUGIN_DIR_FROM_BIN "../lib/pednav/plugins"
#endif
#ifndef PEDNAV_CONFIG_DIR_FROM_BIN
#define PEDNAV_CONFIG_DIR_FROM_BIN "../share/pednav/configs"
#endif

namespace pednav::cli {

std::string executable_dir() {
    char buf[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) return ".";
    buf[n] = '\0';
    std::string path(buf);
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::string default_plugin_dir() { return executable_dir() + "/" PEDNAV_PLUGIN_DIR_FROM_BIN; }
std::string default_config_dir() { return executable_dir() + "/" PEDNAV_CONFIG_DIR_FROM_BIN; }

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<double> parse_numbers(const std::string& text, size_t count, const std::string& option) {
    // The numbers of the readers (io::parse_number): decimal, finite.
    const std::string expected = count == 1 ? "a number" : std::to_string(count) + " comma-separated numbers";
    const std::vector<std::string_view> items = io::split(text, ',');
    std::vector<double> out(items.size());
    for (size_t i = 0; i < items.size(); ++i)
        if (io::parse_number(items[i], &out[i]) != io::NumberStatus::ok)
            throw UsageError(option + " expects " + expected + ", got \"" + text + "\"");
    if (out.size() != count) throw UsageError(option + " expects " + expected + ", got \"" + text + "\"");
    return out;
}

double parse_positive_rate(const std::string& text, const std::string& option) {
    const double hz = parse_numbers(text, 1, option)[0];
    if (!(hz > 0.0 && hz <= 100000.0)) throw UsageError(option + " expects a rate in Hz in (0, 100000], got \"" + text + "\"");
    return hz;
}

uint64_t parse_count(const std::string& text, const std::string& option) {
    const std::string_view digits = io::trim(text);
    uint64_t v = 0;
    bool ok = !digits.empty();
    for (const char c : digits) {
        if (c < '0' || c > '9' || v > (UINT64_MAX - (c - '0')) / 10) {
            ok = false;
            break;
        }
        v = 10 * v + static_cast<uint64_t>(c - '0');
    }
    if (!ok) throw UsageError(option + " expects a non-negative integer, got \"" + text + "\"");
    return v;
}

}  // namespace pednav::cli

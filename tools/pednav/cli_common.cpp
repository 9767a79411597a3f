#include "cli_common.hpp"

#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

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
    const std::string expected = count == 1 ? "a number" : std::to_string(count) + " comma-separated numbers";
    std::vector<double> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !std::isfinite(v))
            throw UsageError(option + " expects " + expected + ", got \"" + text + "\"");
        out.push_back(v);
    }
    if (out.size() != count) throw UsageError(option + " expects " + expected + ", got \"" + text + "\"");
    return out;
}

uint64_t parse_count(const std::string& text, const std::string& option) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE)
        throw UsageError(option + " expects a non-negative integer, got \"" + text + "\"");
    return static_cast<uint64_t>(v);
}

}  // namespace pednav::cli

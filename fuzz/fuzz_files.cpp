// SPDX-License-Identifier: Apache-2.0
#include "fuzz_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace pednav::fuzz {

const std::string& work_dir() {
    static const std::string dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        std::string d = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/pednav_fuzz_" +
                        std::to_string(static_cast<long>(getpid()));
        if (mkdir(d.c_str(), 0700) != 0 && errno != EEXIST) throw std::runtime_error("cannot create " + d);
        return d;
    }();
    return dir;
}

std::string write_work_file(const std::string& name, std::string_view bytes) {
    const std::string path = work_dir() + "/" + name;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) throw std::runtime_error("cannot write " + path);
    const size_t written = bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), f);
    if (std::fclose(f) != 0 || written != bytes.size()) throw std::runtime_error("cannot write " + path);
    return path;
}

std::vector<std::string_view> split_parts(const uint8_t* data, size_t size, size_t max_parts) {
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    std::vector<std::string_view> parts;
    while (parts.size() + 1 < max_parts) {
        const size_t at = rest.find(kPartSeparator);
        if (at == std::string_view::npos) break;
        parts.push_back(rest.substr(0, at));
        rest.remove_prefix(at + kPartSeparator.size());
    }
    parts.push_back(rest);
    parts.resize(max_parts);
    return parts;
}

}  // namespace pednav::fuzz

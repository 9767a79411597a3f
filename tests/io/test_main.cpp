// SPDX-License-Identifier: Apache-2.0
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <dirent.h>

#include "test_util.hpp"

namespace {

// The tests write only plain files into their temporary folders.
void remove_dir(const std::string& dir) {
    if (DIR* d = opendir(dir.c_str())) {
        while (dirent* e = readdir(d)) {
            const std::string name = e->d_name;
            if (name != "." && name != "..") unlink(std::string(dir).append("/").append(name).c_str());
        }
        closedir(d);
    }
    rmdir(dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int result = context.run();
    for (const auto& dir : pednav::io::test::temp_dirs()) remove_dir(dir);
    return result;
}

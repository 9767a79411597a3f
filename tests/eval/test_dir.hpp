// SPDX-License-Identifier: Apache-2.0
// A folder of this test process's own under the system temp folder, so that
// two builds running their tests at once do not share files; removed when
// the process ends.
#pragma once

#include <stdlib.h>

#include <stdexcept>

#include <filesystem>
#include <string>

namespace pednav::eval_test {

inline const std::string& test_dir() {
    struct Dir {
        std::string path;
        Dir() {
            std::string pattern = (std::filesystem::temp_directory_path() / "pednav_eval_XXXXXX").string();
            if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create " + pattern);
            path = pattern;
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Dir dir;
    return dir.path;
}

}  // namespace pednav::eval_test

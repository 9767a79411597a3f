// SPDX-License-Identifier: Apache-2.0
// Runs one check in a child process (fork) with a timeout, so that a plugin
// that crashes, aborts, hangs or calls _exit ends only that check.
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace pednav::validate {

struct IsolatedResult {
    bool finished = false;   // the child sent its result and exited 0
    nlohmann::json result;   // what the child's function returned (when finished)
    std::string failure;     // otherwise: "killed by signal 11 (Segmentation fault)",
                             // "timed out after 5 s", "exited with status 3 before reporting"
};

// Forks; the child runs `body` and sends its JSON back through a pipe, then
// _exit(0)s (an exception in `body` is sent as {"exception": what}). The
// parent waits at most `timeout_s`, then kills the child (SIGKILL).
IsolatedResult run_isolated(const std::function<nlohmann::json()>& body, double timeout_s);

}  // namespace pednav::validate

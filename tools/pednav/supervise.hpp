// SPDX-License-Identifier: Apache-2.0
// Runs a command in a child process and watches it finish. A plugin can end
// the process from inside the engine (abort, a segfault, exit or _exit) where
// nothing in-process can catch it; _exit(0) would even leave the command's
// exit status 0 with no output. The parent sees the child end without its
// "finished" word and says so, with a non-zero exit status.
#pragma once

#include <functional>

namespace pednav::cli {

// Runs `body` in a child process and returns its exit status when it
// finished; otherwise prints "pednav <command>: the run did not complete: ..."
// on stderr (the signal, or the exit status the process ended with) and
// returns 1. Without fork() (or if it fails) runs `body` in this process.
int run_supervised(const char* command, const std::function<int()>& body);

}  // namespace pednav::cli

// SPDX-License-Identifier: Apache-2.0
#include "supervise.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace pednav::cli {

namespace {

// What the child writes on the pipe after its body returned: a marker and the status.
struct Finished {
    uint32_t magic;
    int32_t status;
};
constexpr uint32_t kMagic = 0x706e6f6b;  // "pnok"

}  // namespace

int run_supervised(const char* command, const std::function<int()>& body) {
    int fds[2];
    if (pipe(fds) != 0) return body();
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t child = fork();
    if (child < 0) {
        close(fds[0]);
        close(fds[1]);
        return body();
    }
    if (child == 0) {
        close(fds[0]);
        const int status = body();
        std::fflush(nullptr);
        const Finished done{kMagic, status};
        if (write(fds[1], &done, sizeof done) != static_cast<ssize_t>(sizeof done)) return 1;
        close(fds[1]);
        return status;
    }
    close(fds[1]);
    Finished done{0, 0};
    size_t got = 0;
    for (;;) {  // until the child's end closes the pipe
        const ssize_t n = read(fds[0], reinterpret_cast<char*>(&done) + got, got < sizeof done ? sizeof done - got : 0);
        if (n > 0) {
            got += static_cast<size_t>(n);
            if (got == sizeof done) {
                char rest;
                while (read(fds[0], &rest, 1) > 0) {
                }
                break;
            }
        } else if (n == 0 || errno != EINTR) {
            break;
        }
    }
    close(fds[0]);
    int wstatus = 0;
    while (waitpid(child, &wstatus, 0) < 0 && errno == EINTR) {
    }
    const bool finished = got == sizeof done && done.magic == kMagic;
    if (finished && WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == (done.status & 0xff)) return done.status;
    if (WIFSIGNALED(wstatus)) {
        const int sig = WTERMSIG(wstatus);
        std::fprintf(stderr,
                     "pednav %s: the run did not complete: the process was killed by signal %d (%s) inside the engine "
                     "or a plugin; the track and steps CSVs hold the outputs computed before it (written as the run "
                     "goes), the other outputs are written at the end of a run, so none of them were written\n",
                     command, sig, strsignal(sig));
    } else if (!finished) {
        std::fprintf(stderr,
                     "pednav %s: the run did not complete: the process ended with exit status %d before the run "
                     "finished (a plugin called exit or _exit?); the track and steps CSVs hold the outputs computed "
                     "before it (written as the run goes), the other outputs are written at the end of a run, so none "
                     "of them were written\n",
                     command, WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
    } else {
        std::fprintf(stderr, "pednav %s: the run finished with status %d but the process ended with status %d\n",
                     command, done.status, WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1);
    }
    return 1;
}

}  // namespace pednav::cli

// SPDX-License-Identifier: Apache-2.0
#include "pednav_validate/isolated.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace pednav::validate {
namespace {

double now_s() {
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void write_all(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<size_t>(n);
    }
}

std::string describe_status(int status) {
    char text[160];
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        std::snprintf(text, sizeof text, "killed by signal %d (%s)", sig, strsignal(sig));
    } else if (WIFEXITED(status)) {
        std::snprintf(text, sizeof text, "exited with status %d before reporting", WEXITSTATUS(status));
    } else {
        std::snprintf(text, sizeof text, "ended with wait status %d", status);
    }
    return text;
}

// Kills a child that is past its deadline and says so.
std::string kill_timed_out(pid_t pid, double timeout_s) {
    int status = 0;
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    char msg[80];
    std::snprintf(msg, sizeof msg, "timed out after %g s (killed)", timeout_s);
    return msg;
}

}  // namespace

IsolatedResult run_isolated(const std::function<nlohmann::json()>& body, double timeout_s) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
        close(fds[0]);
        std::string text;
        try {
            text = body().dump();
        } catch (const std::exception& e) {
            text = nlohmann::json{{"exception", e.what()}}.dump();
        } catch (...) {
            text = nlohmann::json{{"exception", "an exception that is not a std::exception"}}.dump();
        }
        write_all(fds[1], text);
        close(fds[1]);
        _exit(0);  // no atexit handlers, no static destructors of the parent's state
    }
    close(fds[1]);
    IsolatedResult r;
    std::string text;
    bool timed_out = false;
    const double deadline = now_s() + timeout_s;
    for (;;) {
        const double left_s = deadline - now_s();
        if (left_s <= 0) {
            timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, static_cast<int>(std::ceil(std::min(left_s, 1.0) * 1000)));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) continue;
        char buf[4096];
        const ssize_t n = read(fds[0], buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // the child closed its end: exited or about to
        text.append(buf, static_cast<size_t>(n));
    }
    close(fds[0]);
    int status = 0;
    if (timed_out) {
        r.failure = kill_timed_out(pid, timeout_s);
        return r;
    }
    // The pipe closed; the child exits at once after closing it, but one
    // that closed it early and then hangs is killed at the deadline too.
    for (;;) {
        const pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) break;
        if (now_s() > deadline) {
            r.failure = kill_timed_out(pid, timeout_s);
            return r;
        }
        usleep(2000);
    }
    if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
        r.failure = describe_status(status);
        return r;
    }
    try {
        r.result = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&) {
        r.failure = "exited 0 without a complete result (the plugin called exit or _exit)";
        return r;
    }
    r.finished = true;
    return r;
}

}  // namespace pednav::validate

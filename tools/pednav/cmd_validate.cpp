// SPDX-License-Identifier: Apache-2.0
#include "cmd_validate.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>

#include <pednav_validate/validate.hpp>

#include "cli_common.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav validate LIB.so [--plugin ID] [--mount M] [--json] [--timeout S] [--plugin-dir DIR]...\n"
    "  the conformance checks every plugin must pass (docs/writing-a-plugin.md): the library loads\n"
    "  and its manifest matches; then each plugin (--plugin: only ID), in its role of the preset of\n"
    "  each mount it declares (--mount: only M), on a simulated walk: lifecycle, outputs time-ordered,\n"
    "  finite and with symmetric PSD covariances, reset idempotent, determinism, bad params refused\n"
    "  naming the key, logging from every callback. Each check runs in a child process killed after\n"
    "  --timeout S seconds (default 60). The other stages' plugins come from the first-party plugin\n"
    "  directory and each --plugin-dir. --json: the report as JSON on stdout.\n"
    "  Exit 0 when every check passes, 1 when one fails, 2 on a usage error.\n";

}  // namespace

const char* const pednav_cmd_validate_usage = kUsage;

int pednav_cmd_validate(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    validate::Options options;
    options.config_dir = cli::default_config_dir();
    options.plugin_dirs = {cli::default_plugin_dir()};
    bool json = false;
    std::string library;
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--json") json = true;
        else if (a == "--plugin") options.plugin_id = args.value(a);
        else if (a == "--mount") options.mount = args.value(a);
        else if (a == "--plugin-dir") options.plugin_dirs.push_back(args.value(a));
        else if (a == "--timeout") {
            const std::string v = args.value(a);
            char* end = nullptr;
            options.timeout_s = std::strtod(v.c_str(), &end);
            if (end == v.c_str() || *end || !(options.timeout_s > 0))
                throw cli::UsageError("--timeout needs a positive number of seconds, not \"" + v + "\"");
        } else if (a.rfind("-", 0) == 0) {
            throw cli::UsageError("unknown option " + a + " for validate");
        } else if (library.empty()) {
            library = a;
        } else {
            throw cli::UsageError("one library at a time (got " + library + " and " + a + ")");
        }
    }
    if (library.empty()) throw cli::UsageError("which library? (pednav validate LIB.so)");
    if (access(library.c_str(), R_OK) != 0) throw cli::UsageError("cannot read " + library);
    if (!options.mount.empty() && options.mount != "foot" && options.mount != "chest" &&
        options.mount != "handheld" && options.mount != "waist")
        throw cli::UsageError("--mount is foot, chest, handheld or waist, not \"" + options.mount + "\"");

    auto print = [&](const validate::CheckResult& c) {
        if (json) return;
        std::string what = c.check;
        if (!c.plugin.empty()) what += " " + c.plugin + (c.mount.empty() ? "" : " (" + c.mount + ")");
        std::printf("%s %s%s%s\n", c.passed ? "pass" : "FAIL", what.c_str(), c.passed ? "" : ": ", c.reason.c_str());
        std::fflush(stdout);
    };
    const validate::Report report = validate::validate_library(library, options, print);
    if (json) {
        std::cout << validate::to_json(report).dump(2) << "\n";
    } else {
        size_t failed = 0;
        for (const auto& c : report.checks) failed += c.passed ? 0 : 1;
        std::printf("%s: %zu checks, %zu failed\n", library.c_str(), report.checks.size(), failed);
    }
    return report.passed() ? 0 : 1;
}

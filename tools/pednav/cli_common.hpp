// SPDX-License-Identifier: Apache-2.0
// Small helpers shared by the pednav subcommands: argument parsing, where the
// first-party plugins and presets are, reading text files.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace pednav::cli {

// A command-line mistake; main prints it with the usage and exits 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// `pednav <command> --help`: main prints what() (the command's usage) on stdout and exits 0.
class HelpRequested : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Walks "--name value" / "--flag" arguments. Given the command's usage text,
// next() answers "--help" and "-h" by throwing HelpRequested with it.
class Args {
public:
    explicit Args(std::vector<std::string> args, std::string usage = {})
        : args_(std::move(args)), usage_(std::move(usage)) {}
    bool done() const { return i_ >= args_.size(); }
    const std::string& peek() const { return args_[i_]; }
    std::string next() {
        std::string a = args_[i_++];
        if (!usage_.empty() && (a == "--help" || a == "-h")) throw HelpRequested(usage_);
        return a;
    }
    // The value after the option just taken.
    std::string value(const std::string& option) {
        if (done()) throw UsageError(option + " needs a value");
        return args_[i_++];
    }

private:
    std::vector<std::string> args_;
    std::string usage_;
    size_t i_ = 0;
};

std::string executable_dir();
// The first-party plugin directory next to the executable (build tree and
// installed layout alike).
std::string default_plugin_dir();
// Folder of the mount presets (configs/<mount>.json) next to the executable.
std::string default_config_dir();
std::string read_text_file(const std::string& path);  // throws std::runtime_error naming the file
std::vector<double> parse_numbers(const std::string& text, size_t count, const std::string& option);
// A sample rate in Hz, in (0, 100000]; throws UsageError naming the option.
double parse_positive_rate(const std::string& text, const std::string& option);
// A non-negative integer (a seed, a count); throws UsageError naming the option.
uint64_t parse_count(const std::string& text, const std::string& option);

}  // namespace pednav::cli

// SPDX-License-Identifier: Apache-2.0
#include "column_checks.hpp"

#include <cmath>
#include <cstdio>

namespace pednav::io::detail {

namespace {

// Flat tops: at least this share of the samples at the extreme, in a run of at least kMinRun.
constexpr double kMinShare = 0.01;
constexpr size_t kMinCount = 10;
constexpr size_t kMinRun = 5;

}  // namespace

void ColumnCheck::Extreme::reset(double v, size_t line) {
    *this = Extreme{};
    value = v;
    add(line);
}

void ColumnCheck::Extreme::add(size_t line) {
    ++count;
    if (run == 0) run_first = line;
    ++run;
    if (run > longest_run) {
        longest_run = run;
        longest_first = run_first;
        longest_last = line;
    }
}

void ColumnCheck::add(double value, size_t line) {
    ++samples_;
    if (std::fabs(value) > absurd_) {
        if (absurd_count_ < 3) absurd_lines_[absurd_count_] = line;
        ++absurd_count_;
        if (std::fabs(value) > std::fabs(absurd_max_)) absurd_max_ = value;
    }
    if (samples_ == 1 || value > max_.value) {
        max_.reset(value, line);
    } else if (value == max_.value) {
        max_.add(line);
    } else {
        max_.run = 0;
    }
    if (samples_ == 1 || value < min_.value) {
        min_.reset(value, line);
    } else if (value == min_.value) {
        min_.add(line);
    } else {
        min_.run = 0;
    }
}

void ColumnCheck::report(LogBuilder& builder) const {
    char text[320];
    if (absurd_count_ > 0) {
        std::string lines = std::to_string(absurd_lines_[0]);
        for (size_t i = 1; i < absurd_count_ && i < 3; ++i) lines += ", " + std::to_string(absurd_lines_[i]);
        std::snprintf(text, sizeof text,
                      "implausible values: column %s holds %zu values beyond %g %s (lines %s%s; the largest "
                      "%g %s): kept, but no body-worn IMU measures them",
                      column_.c_str(), absurd_count_, absurd_, unit_, lines.c_str(),
                      absurd_count_ > 3 ? ", ..." : "", absurd_max_, unit_);
        builder.issue(absurd_lines_[0], text);
    }
    for (const Extreme* e : {&max_, &min_}) {
        if (e == &min_ && min_.value == max_.value) break;
        if (std::fabs(e->value) < floor_ || e->longest_run < kMinRun || e->count < kMinCount ||
            static_cast<double>(e->count) < kMinShare * static_cast<double>(samples_))
            continue;
        std::snprintf(text, sizeof text,
                      "saturated sensor: column %s sits at its %s %g %s on %zu of %zu samples (%.1f %%), in "
                      "runs of up to %zu (lines %zu-%zu): flat tops where the sensor clips",
                      column_.c_str(), e == &max_ ? "maximum" : "minimum", e->value, unit_, e->count, samples_,
                      100.0 * static_cast<double>(e->count) / static_cast<double>(samples_), e->longest_run,
                      e->longest_first, e->longest_last);
        builder.issue(e->longest_first, text);
    }
}

}  // namespace pednav::io::detail

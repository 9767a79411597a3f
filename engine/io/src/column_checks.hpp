// SPDX-License-Identifier: Apache-2.0
// Internal: per-column plausibility of the inertial cells of a table, in SI
// units before the rotation to body axes, so that a warning names the column.
//   absurd:    |value| beyond what any body-worn IMU measures (1e6 in ax);
//   saturated: flat tops, the column sitting at its own maximum (or minimum)
//              on many samples in runs, where a clipped sensor stops.
#pragma once

#include <cstddef>
#include <string>

#include "log_builder.hpp"

namespace pednav::io::detail {

class ColumnCheck {
public:
    // `absurd` and `saturation_floor` in the column's SI unit: a flat top
    // below the floor is a quiet sensor at rest, not a clipped one.
    ColumnCheck(std::string column, const char* unit, double absurd, double saturation_floor)
        : column_(std::move(column)), unit_(unit), absurd_(absurd), floor_(saturation_floor) {}

    void add(double value, size_t line);
    // Issues at most one warning per finding, naming the column and lines.
    void report(LogBuilder& builder) const;

private:
    struct Extreme {
        double value = 0.0;
        size_t count = 0;          // samples at exactly this value
        size_t run = 0;            // current run length at it
        size_t longest_run = 0;
        size_t longest_first = 0;  // lines of the longest run
        size_t longest_last = 0;
        size_t run_first = 0;
        void add(size_t line);
        void reset(double v, size_t line);
    };
    std::string column_;
    const char* unit_;
    double absurd_, floor_;
    size_t samples_ = 0;
    size_t absurd_count_ = 0;
    size_t absurd_lines_[3] = {0, 0, 0};
    double absurd_max_ = 0.0;
    Extreme max_, min_;
};

}  // namespace pednav::io::detail

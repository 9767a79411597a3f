// SPDX-License-Identifier: Apache-2.0
// The truth's floor index: the floor the walker last arrived at. It starts
// as the start height rounded to a floor and changes when the height of the
// floor walked on comes within kArrivalM of another floor's level (index x
// floor height). A landing half-way up a stairwell is on no floor: the walker
// is still on the floor left until the flight above ends. Rounding the
// height instead would put such a landing exactly on the tie between two
// floors, where the body's bounce decides.
#pragma once

#include <cmath>

namespace pednav::sim::detail {

class TruthFloor {
public:
    // Within this of a floor's level, m: less than a stair's rise (0.17 m
    // by default), more than the body's bounce.
    static constexpr double kArrivalM = 0.1;

    explicit TruthFloor(double floor_height_m) : floor_height_m_(floor_height_m) {}

    // The floor at the height of the floor walked on (the sensor's height
    // less its height above that floor), m.
    int at(double walked_height_m) {
        const long nearest = std::lround(walked_height_m / floor_height_m_);
        const bool arrived =
            std::fabs(walked_height_m - static_cast<double>(nearest) * floor_height_m_) < kArrivalM;
        if (!started_ || arrived) floor_ = static_cast<int>(nearest);
        started_ = true;
        return floor_;
    }

private:
    double floor_height_m_;
    bool started_ = false;
    int floor_ = 0;
};

}  // namespace pednav::sim::detail

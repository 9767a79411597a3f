// SPDX-License-Identifier: Apache-2.0
// The heights of the level floors a walk has stood on.
//
// HUPT (foot-imu-height-update-hupt eq. (5)) holds the height of a level floor
// at the height of the stance before; it cannot undo the error a flight of
// stairs left behind. Buildings have few floor heights, and walks come back to
// them: when a level stretch begins after stairs at a height within
// `match_m` of a level stood on before, it is that level again, and HUPT
// holds it at the height it had then. A level not seen before is remembered.
// match_m should stay below one stair riser (about 0.15 m), so that a level
// one riser away is not taken for its neighbour; 0 turns the memory off.
#pragma once

#include <cmath>

namespace pednav::zupt_ins {

class LevelMemory {
public:
    static constexpr int kMaxLevels = 64;  // further levels are not remembered

    explicit LevelMemory(double match_m) : match_m_(match_m) {}

    // The reference height of a level stretch that begins at height h_m:
    // the nearest remembered level within match_m, else h_m (remembered).
    double arrive(double h_m) {
        int best = -1;
        for (int i = 0; i < n_; ++i)
            if (std::abs(levels_m_[i] - h_m) <= match_m_ &&
                (best < 0 || std::abs(levels_m_[i] - h_m) < std::abs(levels_m_[best] - h_m)))
                best = i;
        if (best >= 0) return levels_m_[best];
        if (match_m_ > 0 && n_ < kMaxLevels) levels_m_[n_++] = h_m;
        return h_m;
    }

    int size() const { return n_; }

private:
    double match_m_;
    double levels_m_[kMaxLevels] = {};
    int n_ = 0;
};

}  // namespace pednav::zupt_ins

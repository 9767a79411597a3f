// SPDX-License-Identifier: Apache-2.0
// Internal: Android device axes (x right, y up the screen, z out of the
// screen) turned into forward-left-up for a phone held in portrait in front of
// the walker: forward = y, left = -x, up = z (a 90 degree turn about z).
#pragma once

namespace pednav::io::detail {

inline void android_to_flu(const double device[3], double body[3]) {
    body[0] = device[1];
    body[1] = -device[0];
    body[2] = device[2];
}

constexpr const char* kAndroidAxesText =
    "Android device axes turned to forward-left-up for a phone held in portrait: (y, -x, z); not levelled";

}  // namespace pednav::io::detail

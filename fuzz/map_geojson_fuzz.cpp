// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: a pednav.map/1 document (docs/maps.md) through the map
// loader, its checks and the matcher's index (map_exercise.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "map_exercise.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    pednav::fuzz::exercise_map(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}

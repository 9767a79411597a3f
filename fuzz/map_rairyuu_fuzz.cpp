// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: rairyuu's MapEditor files (core, node, link, polygon and
// arrow .txt, in that order, cut at kPartSeparator) through the converter of
// `pednav map convert` (map_convert.hpp), and the document it writes through
// the map loader. A std::runtime_error naming the file and line is the
// expected answer to a bad source.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz_files.hpp"
#include "map_exercise.hpp"
#include "pednav_indoor_map/map_convert.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    namespace im = pednav::indoor_map;
    const auto parts = pednav::fuzz::split_parts(data, size, 5);
    im::RairyuuMapFiles files{{"core.txt", std::string(parts[0])},
                              {"node.txt", std::string(parts[1])},
                              {"link.txt", std::string(parts[2])},
                              {"polygon.txt", std::string(parts[3])},
                              {"arrow.txt", std::string(parts[4])}};
    std::string document;
    try {
        document = im::rairyuu_to_geojson(files, {});
    } catch (const std::runtime_error&) {
        return 0;
    }
    pednav::fuzz::exercise_map(document);
    return 0;
}

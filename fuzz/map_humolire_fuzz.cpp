// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: HuMoLiRe's map_data.json through the converter of
// `pednav map convert` (map_convert.hpp), with and without a geodetic origin,
// and the document it writes through the map loader. A std::runtime_error
// naming the file is the expected answer to a bad source.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "map_exercise.hpp"
#include "pednav_indoor_map/map_convert.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    namespace im = pednav::indoor_map;
    im::SourceFile source{"map_data.json", std::string(reinterpret_cast<const char*>(data), size)};
    im::MapConversion conversion;
    if (size > 0 && (data[size - 1] & 1) != 0) conversion.origin = pednav::geodesy::GeodeticPoint{35.0, 135.7, 0.0};
    std::string document;
    try {
        document = im::humolire_to_geojson(source, conversion);
    } catch (const std::runtime_error&) {
        return 0;
    }
    pednav::fuzz::exercise_map(document);
    return 0;
}

// SPDX-License-Identifier: Apache-2.0
// Builds a pednav.map/1 document from positions in a source's metres (x
// right, y down an image), for the converters of map_convert.hpp.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pednav_indoor_map/map_convert.hpp"

namespace pednav::indoor_map::detail {

using SourcePoint = std::array<double, 2>;  // source metres, x right, y down

class MapWriter {
public:
    MapWriter(const MapConversion& conversion, const SourcePoint& zero_source_m);

    // A feature of `kind` on `floor` (kind empty: a feature map readers
    // ignore, for what the format has no kind for), with more properties.
    void line(const std::string& kind, int floor, const std::vector<SourcePoint>& points, nlohmann::json properties);
    void polygon(const std::string& kind, int floor, std::vector<SourcePoint> ring, nlohmann::json properties);
    void point(const std::string& kind, int floor, const SourcePoint& p, nlohmann::json properties);
    void top(const std::string& key, nlohmann::json value) { doc_[key] = std::move(value); }
    std::string dump() const { return doc_.dump(1) + "\n"; }

private:
    nlohmann::json position(const SourcePoint& p) const;
    void add(const std::string& kind, int floor, nlohmann::json geometry, nlohmann::json properties);

    MapConversion conversion_;
    SourcePoint zero_;
    nlohmann::json doc_;
};

}  // namespace pednav::indoor_map::detail

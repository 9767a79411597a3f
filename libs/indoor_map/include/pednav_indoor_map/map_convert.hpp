// SPDX-License-Identifier: Apache-2.0
// Floor plans drawn in pixels of an image (x to the right, y down the image)
// to pednav.map/1 documents (docs/maps.md): the MapEditor JSON of HuMoLiRe
// and the node/link/polygon/arrow text files of rairyuu's MapEditor.
//
// Pixels times the source's scale are image metres (x right, y down); the
// converted map's local frame has east = x and north = -y (the plan seen from
// above). Each source states positions in its own metres: rairyuu's in image
// metres, HuMoLiRe's (keypoints.json) with y up from the image's bottom edge.
// Local (0, 0) is the walk's start when one is known (given, or the rairyuu
// core's start point), else the origin of the source's metres. Floors are
// renumbered so that the source's start floor is floor 0.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <pednav_geodesy/enu.hpp>

#include "map.hpp"

namespace pednav::indoor_map {

struct MapConversion {
    // Write WGS-84 around this origin (the geodetic position of local (0, 0)),
    // else local-enu metres.
    std::optional<geodesy::GeodeticPoint> origin;
    // The walk's start in the source's metres (rairyuu: x right, y down the
    // image; HuMoLiRe: x right, y up from the image's bottom edge): local (0, 0).
    std::optional<std::array<double, 2>> start_source_m;
    // Metres per pixel in place of the source's own scale (a scale measured
    // on another rendering of the plan than the one its nodes were drawn on);
    // the source's metres above are then in this scale. Must be positive.
    std::optional<double> scale_m_per_px;
};

// A source file's name (for error messages, "node.txt:12: ...") and text.
struct SourceFile {
    std::string name;
    std::string text;
};

// The source's metres (x right, y down) in the converted map's local frame
// whose (0, 0) is `zero_source_m`.
inline Point2 image_metres_to_local(double x_m, double y_m, const std::array<double, 2>& zero_source_m) {
    return {x_m - zero_source_m[0], -(y_m - zero_source_m[1])};
}

// HuMoLiRe's map_data.json: "links" of "node0"/"node1" {x, y} pixels and
// their "layer", "scale" in m per pixel, "y_range" (the image's rows, px),
// "start_floor", "height" (floor height, m). HuMoLiRe's metres (its
// keypoints, start points and headings) have y up from the image's bottom
// edge: y_m = y_range[1] x scale - image y_m (upstream's MapHandler turns
// its walls so), which keeps the walks' turns in the sense the gyroscope
// measures them. Without a start, local (0, 0) is that frame's origin, so a
// keypoint (x, y) is local (x, y). Throws std::runtime_error naming the file
// and JSON pointer.
std::string humolire_to_geojson(const SourceFile& map_data, const MapConversion& conversion);

// rairyuu's MapEditor files. core.txt: "floor", "height", "start",
// "start_point" (px), "dir", "scale" (m per pixel); node.txt "id,layer,x,y";
// link.txt "id,type,node0,node1" (walls); polygon.txt
// "id,type,count,node..." (type 0: no particles; type 1: where the floor may
// change); arrow.txt "id,type,node0,node1" on the floor arrived at, from
// node0 on the floor left (type 0 from below, 1 from above, 2 either) to
// node1. Throws std::runtime_error naming the file and line.
struct RairyuuMapFiles {
    SourceFile core, node, link, polygon, arrow;
};
std::string rairyuu_to_geojson(const RairyuuMapFiles& files, const MapConversion& conversion);

}  // namespace pednav::indoor_map

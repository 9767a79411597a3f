// SPDX-License-Identifier: Apache-2.0
// The outputs written at the end of a run from a PositionLog (positions on disk
// past a few thousand) are the bytes written from the same positions in memory.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "pednav_io/position_log.hpp"
#include "pednav_io/writers.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("GeoJSON, GPX and geo CSV from a PositionLog of 12 000 positions equal those from a vector") {
    // 120 s at 100 Hz: floors 0, 1, 0 (none for the first 2 s), sources inertial then fused, a stride a second
    // (two before the first position, one after the last).
    std::vector<pn_position_t> positions;
    PositionLog log;
    for (int i = 0; i < 12000; ++i) {
        pn_position_t p{};
        p.header.struct_size = sizeof p;
        p.header.type = PN_REC_POSITION;
        p.header.t_ns = 1000000000 + static_cast<int64_t>(i) * 10000000;
        p.pos_enu_m[0] = 50.0 * std::sin(i * 1e-3);
        p.pos_enu_m[1] = 0.01 * i;
        p.pos_enu_m[2] = i < 4000 || i >= 8000 ? 0.0 : 3.5;
        p.heading_rad = i * 1e-4;
        p.cov_enu_m2[0] = p.cov_enu_m2[4] = 0.01 + i * 1e-6;
        p.cov_enu_m2[8] = 0.5;
        if (i >= 200) {
            p.header.flags |= PN_POSITION_FLAG_HAS_FLOOR;
            p.floor = i < 4000 || i >= 8000 ? 0 : 1;
        }
        p.source = i < 6000 ? PN_POSITION_SOURCE_INERTIAL : PN_POSITION_SOURCE_FUSED;
        positions.push_back(p);
        log.add(p);
    }
    std::vector<pn_stride_t> strides;
    for (int k = -2; k <= 120; ++k) {
        pn_stride_t s{};
        s.header.struct_size = sizeof s;
        s.header.type = PN_REC_STRIDE;
        s.header.t_ns = 1000000000 + static_cast<int64_t>(k) * 1000000000 + 5000000;
        s.t_start_ns = s.header.t_ns - 1000000000;
        s.index = k + 2;
        s.length_m = 1.2;
        s.stride_class = PN_STRIDE_CLASS_LEVEL;
        strides.push_back(s);
    }
    REQUIRE(log.size() == 12000);
    const std::string dir = temp_dir();
    const Origin origin{48.8566, 2.3522, 50.0, true, 1714557600000000000LL};
    GeoJsonExtras extras;
    extras.position_points = true;
    write_geojson(dir + "/vector.geojson", positions, strides, origin, extras);
    write_geojson(dir + "/log.geojson", log, strides, origin, extras);
    write_gpx(dir + "/vector.gpx", positions, origin);
    write_gpx(dir + "/log.gpx", log, origin);
    write_geo_track_csv(dir + "/vector.csv", positions, origin);
    write_geo_track_csv(dir + "/log.csv", log, origin);
    const std::string geojson = read_all(dir + "/vector.geojson");
    CHECK(geojson.size() > 400000);
    CHECK(read_all(dir + "/log.geojson") == geojson);
    CHECK(read_all(dir + "/log.gpx") == read_all(dir + "/vector.gpx"));
    CHECK(read_all(dir + "/log.csv") == read_all(dir + "/vector.csv"));
    // 123 steps, 2 floor changes, 1 change of source.
    size_t steps = 0, floor_changes = 0, source_changes = 0;
    for (size_t at = 0; (at = geojson.find("\"kind\": \"step\"", at)) != std::string::npos; ++at) ++steps;
    for (size_t at = 0; (at = geojson.find("\"kind\": \"floor_change\"", at)) != std::string::npos; ++at)
        ++floor_changes;
    for (size_t at = 0; (at = geojson.find("\"kind\": \"source_change\"", at)) != std::string::npos; ++at)
        ++source_changes;
    CHECK(steps == 123);
    CHECK(floor_changes == 2);
    CHECK(source_changes == 1);
}

// SPDX-License-Identifier: Apache-2.0
// The map matcher around the particle filter: it takes a dead-reckoned track
// (positions between steps, one displacement per step) and the barometer, and
// gives positions that stay inside the map.
//
// - Steps move the cloud (particle_filter.hpp). The output is the particle at
//   the cloud's mode (cloud_route.hpp): the mean itself may stand in a wall
//   between two groups of particles, and the particle nearest it in the
//   smaller group.
// - Between steps the output follows the dead-reckoned track from the last
//   step's estimate, rotated by the cloud's heading offset and scaled.
// - The output track never crosses a wall: a move that would is cut short of
//   the first wall in its way (by wall_clearance_m) and slides along it for
//   the rest, so that it rounds corners; where that does not bring it to the
//   estimate, it goes round through the cloud, or back along its own track
//   (CloudRoute::next_waypoint). A recovery (the cloud
//   was lost and reseeded) restarts the output track at the new cloud, and
//   the position that follows is flagged recovered.
// - Floors come from the barometer. A floor is where the walker arrives:
//   where most of the cloud is on a connector linking two floors (the map
//   says the floor may change there), the floor changes once the altitude has
//   come within map_floor_margin_m of the other floor's level, so a landing
//   half-way up belongs to the floor left. Elsewhere the altitude past half a
//   floor by the altimeter's hysteresis decides. A floor change moves the
//   cloud through the connectors (ParticleFilter::change_floor).
// - In an altitude-update zone the barometer's drift is reset to the zone's
//   height (BarometricAltimeter::set_altitude) while the walker is level. On
//   a floor the map gives no altitude zone, with floor_level_reset, anywhere
//   off stairs and lifts serves as one at the floor's height (floor index x
//   floor height: the map says its floors are that far apart).
// - Without a map the positions pass through, with the barometer's floor.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_indoor_map/indexed_map.hpp>

#include "cloud_route.hpp"
#include "particle_filter.hpp"

namespace pednav::map_matching {

struct MapMatcherConfig {
    ParticleFilterConfig filter;
    barometry::BarometricAltimeterConfig baro;
    double wall_cell_m;                 // grid cell of the wall and zone indexes, m
    double map_floor_margin_m;          // on a connector, the floor changes this close to the next floor's level, m
    double altitude_zone_max_rate_mps;  // altitude zones reset the drift only below this vertical rate
    double wall_clearance_m;            // an output stopped by a wall stands this far short of it, m
    bool floor_level_reset;             // on a floor without altitude zones, level and off connectors, the
                                        // altitude is the floor's (floor index x floor height)
    double mode_cell_m;                 // cells in which the cloud's mode is counted, m
};

// Fills a config from a params view (any type with number(key),
// integer(key) and boolean(key)): the particle filter's keys, the
// altimeter's under "baro_", and the matcher's own.
template <class Params>
MapMatcherConfig map_matcher_config(Params& v) {
    MapMatcherConfig c;
    c.filter = particle_filter_config(v);
    c.baro = barometry::barometric_altimeter_config(v, "baro_");
    c.wall_cell_m = v.number("wall_cell_m");
    c.map_floor_margin_m = v.number("map_floor_margin_m");
    c.altitude_zone_max_rate_mps = v.number("altitude_zone_max_rate_mps");
    c.wall_clearance_m = v.number("wall_clearance_m");
    c.floor_level_reset = v.boolean("floor_level_reset");
    c.mode_cell_m = v.number("mode_cell_m");
    return c;
}

// A position of the dead-reckoned track (the upstream filter's).
struct TrackPosition {
    int64_t t_ns;
    double pos_enu_m[3];
    double cov_enu_m2[9];
    double heading_rad;
};

struct MatchedPosition {
    double pos_enu_m[3];
    double cov_enu_m2[9];
    double heading_rad;
    bool has_floor;
    int floor;
    bool map_matched;         // from the particle filter (false: passed through, no map)
    uint32_t live_particles;  // survivors of the latest step (before regeneration; 0 after a recovery)
    bool recovered;           // the cloud was reseeded since the previous output
    uint32_t recoveries;      // since the start
};

enum class MatchEvent { none, recovery, stall_recovery, floor_change, floor_recovery, altitude_reset };

class MapMatcher {
public:
    // Throws std::invalid_argument for a config out of range.
    explicit MapMatcher(const MapMatcherConfig& config);

    // Replaces the map; the cloud restarts at the next position.
    void set_map(indoor_map::Map map);
    bool has_map() const { return map_ != nullptr; }
    const indoor_map::IndexedMap* map() const { return map_.get(); }
    // Start point and heading (NaN: the track's own) of the walk.
    void set_start(const double pos_enu_m[3], double heading_rad);

    void on_baro(int64_t t_ns, double pressure_pa);
    // One step's horizontal displacement, in the track's frame.
    void on_stride(int64_t t_ns, double de_m, double dn_m);
    MatchedPosition on_position(const TrackPosition& p);

    // The latest event (recoveries and floor changes, for the log), then none.
    MatchEvent take_event(int& floor, uint32_t& recoveries);

    const ParticleFilter& filter() const { return *filter_; }
    const barometry::BarometricAltimeter& altimeter() const { return altimeter_; }
    double floor_height_m() const;

private:
    void ensure_started(const TrackPosition* p);
    void update_floor();
    void reset_drift();
    bool on_connector(const indoor_map::Point2& p) const;
    void note(MatchEvent e);
    indoor_map::Point2 move_clear_of_walls(const indoor_map::Point2& from, const indoor_map::Point2& to) const;
    indoor_map::Point2 move_output(const indoor_map::Point2& to);
    // Anchors the output at the cloud's mode after a step or a floor change.
    void anchor_at_mode();

    MapMatcherConfig c_;
    std::unique_ptr<indoor_map::IndexedMap> map_;
    std::unique_ptr<ParticleFilter> filter_;
    std::unique_ptr<CloudRoute> route_;
    barometry::BarometricAltimeter altimeter_;
    bool has_start_ = false;
    double start_[3] = {0, 0, 0};
    bool has_track_ = false;
    TrackPosition last_track_{};
    // The output follows the track from these: where the track and the
    // estimate were at the latest step.
    double anchor_track_[2] = {0, 0};
    bool anchor_pending_ = false;      // anchor_track_ is the next position at or after this time
    int64_t anchor_pending_t_ns_ = 0;
    indoor_map::Point2 anchor_map_{0, 0};
    indoor_map::Point2 output_{0, 0};
    CloudEstimate cloud_{};
    int live_ = 0;
    bool recovered_pending_ = false;
    MatchEvent event_ = MatchEvent::none;
};

}  // namespace pednav::map_matching

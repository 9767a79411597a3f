// SPDX-License-Identifier: Apache-2.0
// Map matcher: the particle filter of libs/map_matching behind any pipeline
// that emits strides and positions (chest, handheld, foot), with the
// barometer for floors; maps in pednav.map/1 (docs/maps.md).
#include <cmath>
#include <string>

#include <pednav_barometry/params_schema.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_map_matching/map_matcher.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
namespace mm = pednav::map_matching;

class ParticleFilterMatcher : public MapMatcher {
public:
    static constexpr const char* kId = "org.pednav.map.particle_filter";
    static constexpr const char* kName = "map matcher, particle filter";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* kDescription =
        "particle filter on the map's walls, zones and connectors (chest-imu-particle-filter-map-matching, sec. 3.3, "
        "with ERRATA.md): particles with heading offset and step scale, wall and no-particle deaths, Algorithm 1 "
        "regeneration with the backtracking test, circular-mean heading, floors from the barometer through stairs "
        "and lifts, recovery when every particle dies; without a map, positions pass through with the barometer's floor";
    static constexpr const char* const kFeatures[] = {"mount:chest", "mount:handheld", "mount:foot", "needs:position",
                                                      "uses:stride", nullptr};
    static constexpr uint64_t kConsumes =
        PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_BARO);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_POSITION);
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "particles": {"type": "integer", "minimum": 1, "maximum": 100000, "default": 512,
      "description": "particles in the cloud (the paper: 256 in corridors, 512 in halls)"},
    "seed": {"type": "integer", "minimum": 0, "maximum": 2147483647, "default": 1,
      "description": "seed of the random numbers: the same seed gives the same run, bit for bit"},
    "scale_min": {"type": "number", "minimum": 0.1, "maximum": 10, "default": 0.9,
      "description": "smallest step scale s_i of a particle (eq. 4)"},
    "scale_max": {"type": "number", "minimum": 0.1, "maximum": 10, "default": 1.1,
      "description": "largest step scale s_i of a particle (eq. 4)"},
    "scale_walk_sd": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.0025,
      "description": "relative random walk of each particle's step scale, per step (standard deviation of a uniform); new particles take their parent's scale, so the walls select the scale as they select positions; 0 = the paper: scales drawn uniform in [scale_min, scale_max] for each new particle"},
    "init_position_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 100, "default": 0.3,
      "description": "spread of the first cloud around the start point, per axis"},
    "init_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.05,
      "description": "spread of the first cloud's heading offsets"},
    "heading_walk_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 1, "default": 0.01,
      "description": "random walk of each particle's heading offset, per step (follows heading drift)"},
    "step_length_sd": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.03,
      "description": "relative noise on each particle's step length, per step (standard deviation of a uniform)"},
    "position_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.05,
      "description": "position noise per step and axis (standard deviation of a uniform)"},
    "regen_radius_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 100, "default": 1.0,
      "description": "Algorithm 1's Radius: new particles within it of a random survivor (the paper: 3 m)"},
    "regen_tries": {"type": "integer", "minimum": 1, "maximum": 1000, "default": 8,
      "description": "Algorithm 1's TryTimeMax: proposals around one survivor before another is drawn"},
    "regen_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.03,
      "description": "a new particle's heading offset around the cloud's circular mean (eq. 3 corrected)"},
    "backtrack_steps": {"type": "integer", "minimum": 0, "maximum": 1000, "default": 10,
      "description": "recent steps a new particle is walked back over; it must cross no wall on the way; 0 = no backtracking test"},
    "recovery_radius_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 1000, "default": 2.0,
      "description": "every particle died: the cloud is reseeded within this of the last estimate"},
    "recovery_growth": {"type": "number", "minimum": 1, "maximum": 10, "default": 2.0,
      "description": "the recovery radius is multiplied by this at each consecutive recovery"},
    "recovery_max_radius_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 10000, "default": 30,
      "description": "largest recovery radius"},
    "recovery_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.3,
      "description": "spread of a reseeded cloud's heading offsets around the last circular mean"},
    "stall_progress": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.5,
      "description": "the cloud is lost, and reseeded where the track puts the walker, when over the last backtrack_steps steps its mean went less than this share of the track's way, at each of backtrack_steps steps in a row (it stalls at a wall the map has no door in); 0 = never"},
    "wall_cell_m": {"type": "number", "x-unit": "m", "minimum": 0.1, "maximum": 100, "default": 2.0,
      "description": "cell side of the grids that index walls and zones per floor"},
    "map_floor_margin_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "where most particles are on stairs or a lift linking two floors, the floor changes on arrival: once the altitude has come this close to the other floor's level (a landing half-way belongs to the floor left; elsewhere baro_floor_hysteresis_m past the half)"},
    "altitude_zone_max_rate_mps": {"type": "number", "x-unit": "m/s", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "in an altitude-update zone the barometer's drift is reset while the vertical rate is below this; 0 = never"},
    "floor_level_reset": {"type": "boolean", "default": true,
      "description": "on a floor the map gives no altitude zone, level and off stairs and lifts, the barometer's drift is reset to the floor's height (floor index x floor height), as an altitude zone would; false = only altitude zones reset it"},
    "mode_cell_m": {"type": "number", "x-unit": "m", "minimum": 0.1, "maximum": 100, "default": 1.0,
      "description": "the output is at the cloud's mode: particles are counted in square cells this wide, the cell whose 3 x 3 block holds the most and the cells joined to it with no wall between are the output's group, and the output is its particle nearest its mean; also the step of the output's way round walls through the cloud"},
    "wall_clearance_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 1, "default": 0.05,
      "description": "an output move that a wall would cut stops this far short of the wall"},
    )json" PEDNAV_BAROMETER_PARAMS_SCHEMA(5, 0.3, 0.5, 3.4, 0.5, 2) R"json(
  }
})json";

    ParticleFilterMatcher(Params& p, const CreateContext&) : matcher_(read(p)) {}

    void on_baro(const pn_baro_t& b) override { matcher_.on_baro(b.header.t_ns, b.pressure_pa); }
    void on_stride(const pn_stride_t& s) override {
        matcher_.on_stride(s.header.t_ns, s.displacement_enu_m[0], s.displacement_enu_m[1]);
        log_events();
    }
    void on_position(const pn_position_t& p) override {
        mm::TrackPosition t;
        t.t_ns = p.header.t_ns;
        for (int i = 0; i < 3; ++i) t.pos_enu_m[i] = p.pos_enu_m[i];
        for (int i = 0; i < 9; ++i) t.cov_enu_m2[i] = p.cov_enu_m2[i];
        t.heading_rad = p.heading_rad;
        const mm::MatchedPosition m = matcher_.on_position(t);
        log_events();
        auto r = make_record<pn_position_t>(p.header.t_ns);
        for (int i = 0; i < 3; ++i) r.pos_enu_m[i] = m.pos_enu_m[i];
        for (int i = 0; i < 9; ++i) r.cov_enu_m2[i] = m.cov_enu_m2[i];
        r.heading_rad = m.heading_rad;
        if (m.map_matched) {
            r.source = PN_POSITION_SOURCE_MAP;
            r.header.flags = PN_POSITION_FLAG_HAS_PARTICLES | (m.recovered ? PN_POSITION_FLAG_RECOVERED : 0u);
            r.live_particles = m.live_particles;
            r.recoveries = m.recoveries;
        } else {  // no map: the track as it is, with the barometer's floor unless it has one
            r = p;
            r.header.struct_size = sizeof r;
            if (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) {
                emit(r);
                return;
            }
        }
        if (m.has_floor) {
            r.header.flags |= PN_POSITION_FLAG_HAS_FLOOR;
            r.floor = m.floor;
        }
        emit(r);
    }
    bool set_start(const double pos[3], double heading_rad) override {
        matcher_.set_start(pos, heading_rad);
        return true;
    }
    bool load_map(const std::string& format, const void* bytes, size_t size) override {
        if (format != "pednav.map/1")
            throw InputError("", "unsupported map format \"" + format + "\" (this matcher reads pednav.map/1)");
        const std::string_view doc(static_cast<const char*>(bytes), size);
        pednav::indoor_map::Map map;
        try {
            std::optional<pednav::geodesy::GeodeticPoint> origin;
            pn_geo_point_t o;
            if (!this->origin(o)) {
                if (const auto declared = pednav::indoor_map::geojson_map_origin(doc)) {
                    const pn_geo_point_t offer{declared->lat_deg, declared->lon_deg, declared->height_m};
                    offer_origin(offer);
                }
            }
            if (this->origin(o)) origin = pednav::geodesy::GeodeticPoint{o.lat_deg, o.lon_deg, o.height_m};
            map = pednav::indoor_map::read_geojson_map(doc, origin);
        } catch (const pednav::indoor_map::MapError& e) {
            throw InputError(e.pointer, e.what());
        }
        matcher_.set_map(std::move(map));
        return true;
    }

private:
    void log_events() {
        int floor = 0;
        uint32_t recoveries = 0;
        switch (matcher_.take_event(floor, recoveries)) {
            case mm::MatchEvent::recovery:
                log(PNP_LOG_WARN, "every particle died; cloud reseeded around the last estimate (recovery " +
                                      std::to_string(recoveries) + ")");
                break;
            case mm::MatchEvent::stall_recovery:
                log(PNP_LOG_WARN, "the cloud stalled while the track went on (a wall without a door in the map?); "
                                  "reseeded where the track puts the walker (recovery " +
                                      std::to_string(recoveries) + ")");
                break;
            case mm::MatchEvent::floor_recovery:
                log(PNP_LOG_WARN, "floor change to " + std::to_string(floor) +
                                      " with no particle on stairs or a lift; cloud reseeded at the nearest (recovery " +
                                      std::to_string(recoveries) + ")");
                break;
            case mm::MatchEvent::floor_change:
                log(PNP_LOG_INFO, "floor " + std::to_string(floor));
                break;
            case mm::MatchEvent::altitude_reset:
            case mm::MatchEvent::none: break;
        }
    }
    static mm::MapMatcherConfig read(Params& p) {
        const mm::MapMatcherConfig c = mm::map_matcher_config(p);
        if (c.filter.scale_min > c.filter.scale_max) throw ConfigError("scale_min", "scale_min must not exceed scale_max");
        if (c.filter.recovery_max_radius_m < c.filter.recovery_radius_m)
            throw ConfigError("recovery_max_radius_m", "recovery_max_radius_m must not be below recovery_radius_m");
        if (!(c.baro.floor_hysteresis_m < 0.5 * c.baro.floor_height_m))
            throw ConfigError("baro_floor_hysteresis_m", "baro_floor_hysteresis_m must be below half of baro_floor_height_m");
        return c;
    }

    mm::MapMatcher matcher_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.map.particle_filter", "1.0.0", ParticleFilterMatcher)

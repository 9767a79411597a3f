// SPDX-License-Identifier: Apache-2.0
#include "pednav_map_matching/map_matcher.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace pednav::map_matching {

using indoor_map::Point2;

namespace {
constexpr int kOutputHistory = 1024;  // output positions kept for retracing (16 KiB)
}  // namespace

MapMatcher::MapMatcher(const MapMatcherConfig& c) : c_(c), altimeter_(c.baro) {
    if (!(c.wall_cell_m > 0)) throw std::invalid_argument("wall_cell_m must be positive");
    if (!(c.map_floor_margin_m >= 0)) throw std::invalid_argument("map_floor_margin_m must not be negative");
    if (!(c.altitude_zone_max_rate_mps >= 0)) throw std::invalid_argument("altitude_zone_max_rate_mps must not be negative");
    if (!(c.wall_clearance_m >= 0)) throw std::invalid_argument("wall_clearance_m must not be negative");
    if (!(c.mode_cell_m > 0)) throw std::invalid_argument("mode_cell_m must be positive");
    filter_ = std::make_unique<ParticleFilter>(c.filter, nullptr);  // checks the filter's config
}

double MapMatcher::floor_height_m() const {
    return map_ && std::isfinite(map_->map.floor_height_m) && map_->map.floor_height_m > 0 ? map_->map.floor_height_m
                                                                                           : c_.baro.floor_height_m;
}

void MapMatcher::set_map(indoor_map::Map map) {
    map_ = std::make_unique<indoor_map::IndexedMap>(std::move(map), c_.wall_cell_m);
    filter_ = std::make_unique<ParticleFilter>(c_.filter, map_.get());
    route_ = std::make_unique<CloudRoute>(c_.mode_cell_m, c_.filter.particles, kOutputHistory);
}

// The track starts with the same heading (the engine gives both the same
// start), so the heading offsets start around zero whatever it is.
void MapMatcher::set_start(const double pos[3], double) {
    has_start_ = true;
    for (int i = 0; i < 3; ++i) start_[i] = pos[i];
}

void MapMatcher::note(MatchEvent e) { event_ = e; }

MatchEvent MapMatcher::take_event(int& floor, uint32_t& recoveries) {
    const MatchEvent e = event_;
    event_ = MatchEvent::none;
    floor = filter_->floor();
    recoveries = filter_->recoveries();
    return e;
}

// The cloud starts where the walk starts: the start point when one was set,
// else the track's first position. Both frames agree there, so the heading
// offsets start around zero.
void MapMatcher::ensure_started(const TrackPosition* p) {
    if (!map_ || filter_->started()) return;
    Point2 at{0, 0};
    if (has_start_) at = {start_[0], start_[1]};
    else if (p) at = {p->pos_enu_m[0], p->pos_enu_m[1]};
    else if (has_track_) at = {last_track_.pos_enu_m[0], last_track_.pos_enu_m[1]};
    filter_->start(at, 0, 0.0);
    cloud_ = filter_->estimate();
    live_ = static_cast<int>(filter_->particles().size());
    anchor_map_ = output_ = at;
    route_->clear_outputs();
    route_->record_output(output_);
    const TrackPosition& t = p ? *p : last_track_;
    anchor_track_[0] = (p || has_track_) ? t.pos_enu_m[0] : at.e_m;
    anchor_track_[1] = (p || has_track_) ? t.pos_enu_m[1] : at.n_m;
}

// Moves from `from` towards `to` without crossing a wall: a move a wall cuts
// stops wall_clearance_m short of it and slides along the wall for what is
// left of it (so the output rounds a corner instead of sticking to it). The
// output track records the straight step from `from` to the result, so the
// result is checked as such: if the slid point is not in sight of `from`, the
// output stops where the straight move met the wall, and if even that is not
// (rounding at a grazing angle), it stays.
Point2 MapMatcher::move_clear_of_walls(const Point2& from, const Point2& to) const {
    const int floor = filter_->floor();
    Point2 at = from, first_stop = from;
    double re = to.e_m - from.e_m, rn = to.n_m - from.n_m;
    for (int slide = 0; slide < 4; ++slide) {
        const Point2 goal{at.e_m + re, at.n_m + rn};
        double t = 0;
        Point2 a, b;
        if (!map_->walls.first_crossing(floor, at, goal, &t, &a, &b)) {
            at = goal;
            break;
        }
        const double len = std::hypot(re, rn);
        const double safe = len > 0 ? std::max(0.0, t - c_.wall_clearance_m / len) : 0.0;
        at = {at.e_m + safe * re, at.n_m + safe * rn};
        if (slide == 0) first_stop = at;
        // What is left of the move, along the wall.
        const double we = b.e_m - a.e_m, wn = b.n_m - a.n_m, wl2 = we * we + wn * wn;
        if (wl2 <= 0) break;
        const double along = ((1.0 - safe) * (re * we + rn * wn)) / wl2;
        re = along * we;
        rn = along * wn;
        if (std::hypot(re, rn) < 1e-4) break;
    }
    if (!map_->walls.crosses_wall(floor, from, at)) return at;
    if (!map_->walls.crosses_wall(floor, from, first_stop)) return first_stop;
    return from;
}

void MapMatcher::anchor_at_mode() {
    const std::vector<Particle>& particles = filter_->particles();
    route_->index(particles);
    const int k = route_->mode_particle(&map_->walls, filter_->floor(), particles);
    const Particle& best = particles[static_cast<size_t>(k >= 0 ? k : filter_->nearest(cloud_.mean))];
    anchor_map_ = {best.e_m, best.n_m};
}

// The output's move towards `to`: straight when no wall is in the way, else
// sliding along the walls in the way when that brings it within a cell of
// `to`, else round through the cloud or back along its track.
Point2 MapMatcher::move_output(const Point2& to) {
    const int floor = filter_->floor();
    if (!map_->walls.crosses_wall(floor, output_, to)) return to;
    const Point2 slid = move_clear_of_walls(output_, to);
    if (std::hypot(slid.e_m - to.e_m, slid.n_m - to.n_m) < c_.mode_cell_m) return slid;
    Point2 waypoint;
    return route_->next_waypoint(map_->walls, floor, output_, to, waypoint) ? waypoint : slid;
}

void MapMatcher::on_baro(int64_t t_ns, double pressure_pa) {
    altimeter_.push(t_ns, pressure_pa);
    if (map_ && filter_->started() && altimeter_.ready()) update_floor();
}

// Eq. (5) corrected: the altimeter's barometric formula gives the height
// above the start; a floor is floor_height_m of it. The altitude's low-pass
// (time constant baro_smoothing_s) lags a climb by rate x time constant; the
// floor decision adds that back.
//
// A floor is where the walker arrives: where most of the cloud is on a
// connector linking the two floors, the floor changes once the altitude has
// come within map_floor_margin_m of the other floor's level (the flight above a
// half-way landing still belongs to the floor left, and noise on the landing,
// exactly between two floors, cannot flip it). Elsewhere (a map that links
// no floors, or a cloud that is not on the connector) the altitude past half
// a floor by baro_floor_hysteresis_m decides.
void MapMatcher::update_floor() {
    const double h = floor_height_m();
    const double altitude = altimeter_.altitude_m() + altimeter_.vertical_rate_mps() * c_.baro.smoothing_s;
    for (int guard = 0; guard < 8; ++guard) {
        const int f = filter_->floor();
        const double above = altitude - f * h;  // m above the cloud's floor
        const int to = above > 0 ? f + 1 : f - 1;
        const double past_half = std::abs(above) - 0.5 * h;
        if (past_half < 0) return;
        const bool arrived = to > f ? altitude >= to * h - c_.map_floor_margin_m : altitude <= to * h + c_.map_floor_margin_m;
        const bool certain = past_half > c_.baro.floor_hysteresis_m;
        if (!arrived && !certain) return;
        if (!(filter_->share_on_link(to) >= 0.5 ? arrived : certain)) return;
        const bool recovered = filter_->change_floor(to, output_);
        altimeter_.set_floor(to);
        cloud_ = filter_->estimate();
        live_ = static_cast<int>(filter_->particles().size());
        if (recovered) recovered_pending_ = true;
        note(recovered ? MatchEvent::floor_recovery : MatchEvent::floor_change);
        anchor_at_mode();
        output_ = anchor_map_;  // another floor: nothing to cross on the way
        route_->clear_outputs();
        route_->record_output(output_);
        anchor_track_[0] = last_track_.pos_enu_m[0];
        anchor_track_[1] = last_track_.pos_enu_m[1];
    }
}

void MapMatcher::on_stride(int64_t t_ns, double de, double dn) {
    if (!map_) return;
    ensure_started(nullptr);
    const StepReport r = filter_->step(de, dn, output_);
    live_ = r.survivors;
    if (r.recovered) {
        recovered_pending_ = true;
        note(r.stalled ? MatchEvent::stall_recovery : MatchEvent::recovery);
    }
    cloud_ = filter_->estimate();
    anchor_at_mode();
    // The track's position at the end of the stride: the latest one when it
    // is that old already, else the next one (a position filter emits a
    // step's STRIDE before the POSITION at the same time; the track before
    // the step would count the step twice).
    if (has_track_ && last_track_.t_ns >= t_ns) {
        anchor_track_[0] = last_track_.pos_enu_m[0];
        anchor_track_[1] = last_track_.pos_enu_m[1];
        anchor_pending_ = false;
    } else {
        anchor_pending_ = true;
        anchor_pending_t_ns_ = t_ns;
    }
    // A recovery restarts the output track where the new cloud is (the
    // position says so with PN_POSITION_FLAG_RECOVERED): the old one was lost.
    if (r.recovered) {
        output_ = anchor_map_;
        route_->clear_outputs();
        route_->record_output(output_);
    }
    reset_drift();
}

bool MapMatcher::on_connector(const Point2& p) const {
    const int f = filter_->floor();
    for (const indoor_map::Connector& c : map_->map.connectors)
        if ((c.floor == f || c.floor_to == f || c.kind == indoor_map::ConnectorKind::lift) && near_connector(c, p))
            return true;
    return false;
}

// Drift of the barometer reset in altitude-update zones while level: a
// zone's height is an up like the positions' (the start's is start_[2]).
void MapMatcher::reset_drift() {
    if (!altimeter_.ready() || !(std::abs(altimeter_.vertical_rate_mps()) < c_.altitude_zone_max_rate_mps)) return;
    const int f = filter_->floor();
    const double h = floor_height_m();
    if (!(std::abs(altimeter_.altitude_m() - f * h) < 0.5 * h - c_.baro.floor_hysteresis_m)) return;
    double target = NAN;
    if (const indoor_map::Zone* z = map_->zones.zone_at(f, anchor_map_, indoor_map::ZoneKind::altitude)) {
        target = z->height_m - start_[2];
    } else if (c_.floor_level_reset && !map_->zones.has_kind(f, indoor_map::ZoneKind::altitude) &&
               !on_connector(anchor_map_)) {
        target = f * h;
    }
    if (!std::isfinite(target)) return;
    altimeter_.set_altitude(target, f);
    if (event_ == MatchEvent::none) note(MatchEvent::altitude_reset);
}

MatchedPosition MapMatcher::on_position(const TrackPosition& p) {
    MatchedPosition out{};
    const bool first = !has_track_;
    last_track_ = p;
    has_track_ = true;
    out.heading_rad = p.heading_rad;
    for (int i = 0; i < 9; ++i) out.cov_enu_m2[i] = p.cov_enu_m2[i];
    for (int i = 0; i < 3; ++i) out.pos_enu_m[i] = p.pos_enu_m[i];
    if (!map_) {
        out.has_floor = altimeter_.ready();
        out.floor = altimeter_.floor();
        return out;
    }
    if (first || !filter_->started()) ensure_started(&p);
    if (anchor_pending_ && p.t_ns >= anchor_pending_t_ns_) {
        anchor_track_[0] = p.pos_enu_m[0];
        anchor_track_[1] = p.pos_enu_m[1];
        anchor_pending_ = false;
    }
    // The track's motion since the latest step, turned and scaled as the cloud says.
    const double de = p.pos_enu_m[0] - anchor_track_[0], dn = p.pos_enu_m[1] - anchor_track_[1];
    const double c = std::cos(cloud_.heading_rad), s = std::sin(cloud_.heading_rad);
    const double k = cloud_.scale > 0 ? cloud_.scale : 1.0;
    const Point2 want{anchor_map_.e_m + k * (de * c + dn * s), anchor_map_.n_m + k * (dn * c - de * s)};
    output_ = move_output(want);
    route_->record_output(output_);
    out.pos_enu_m[0] = output_.e_m;
    out.pos_enu_m[1] = output_.n_m;
    if (altimeter_.ready()) out.pos_enu_m[2] = start_[2] + altimeter_.altitude_m();
    // Horizontal covariance from the cloud, the vertical from the track.
    out.cov_enu_m2[0] = cloud_.cov_m2[0];
    out.cov_enu_m2[1] = out.cov_enu_m2[3] = cloud_.cov_m2[1];
    out.cov_enu_m2[4] = cloud_.cov_m2[2];
    out.cov_enu_m2[2] = out.cov_enu_m2[6] = out.cov_enu_m2[5] = out.cov_enu_m2[7] = 0.0;
    out.heading_rad = std::remainder(p.heading_rad + cloud_.heading_rad, 2.0 * M_PI);
    out.has_floor = true;
    out.floor = filter_->floor();
    out.map_matched = true;
    out.live_particles = static_cast<uint32_t>(live_);
    out.recovered = recovered_pending_;
    recovered_pending_ = false;
    out.recoveries = filter_->recoveries();
    return out;
}

}  // namespace pednav::map_matching

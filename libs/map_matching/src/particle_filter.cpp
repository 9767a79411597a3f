// SPDX-License-Identifier: Apache-2.0
// The particle filter's cloud: start, the step (eq. 4 and the wall test), the
// estimate (eq. 2, eq. 3 corrected). Regeneration and recovery are in
// regeneration.cpp, floor changes in floor_change.cpp.
#include "pednav_map_matching/particle_filter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pednav::map_matching {

namespace {
void require(bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("particle filter: ") + what);
}
}  // namespace

ParticleFilter::ParticleFilter(const ParticleFilterConfig& c, const indoor_map::IndexedMap* map)
    : c_(c), map_(map), rng_(c.seed) {
    require(c.particles >= 1 && c.particles <= 100000, "particles must be in [1, 100000]");
    require(c.scale_min > 0 && c.scale_min <= c.scale_max, "scale_min must be in (0, scale_max]");
    require(c.init_position_sd_m >= 0 && c.init_heading_sd_rad >= 0 && c.heading_walk_sd_rad >= 0 &&
                c.step_length_sd >= 0 && c.scale_walk_sd >= 0 && c.position_sd_m >= 0 && c.regen_heading_sd_rad >= 0 &&
                c.recovery_heading_sd_rad >= 0,
            "standard deviations must not be negative");
    require(c.regen_radius_m >= 0, "regen_radius_m must not be negative");
    require(c.regen_tries >= 1, "regen_tries must be at least 1");
    require(c.backtrack_steps >= 0, "backtrack_steps must not be negative");
    require(c.recovery_radius_m > 0 && c.recovery_growth >= 1 && c.recovery_max_radius_m >= c.recovery_radius_m,
            "recovery radius must be positive, growth >= 1, max radius >= radius");
    particles_.reserve(static_cast<size_t>(c.particles));
    require(c.stall_progress >= 0 && c.stall_progress <= 1, "stall_progress must be in [0, 1]");
    history_.resize(static_cast<size_t>(c.backtrack_steps > 0 ? c.backtrack_steps : 1));
    means_.resize(history_.size());
}

namespace {
// Back into (-pi, pi] after a turn: one comparison for the small turns of a
// step (navmath::wrap_pi's fmod costs more than the rest of a particle's
// heading update), std::remainder for anything else.
double rewrap_after_turn(double a) {
    if (a > M_PI) a -= 2.0 * M_PI;
    else if (a <= -M_PI) a += 2.0 * M_PI;
    return std::abs(a) <= M_PI ? a : std::remainder(a, 2.0 * M_PI);
}
}  // namespace

void ParticleFilter::set_heading(Particle& p, double h) const {
    p.heading_rad = rewrap_after_turn(h);
    p.cos_h = std::cos(p.heading_rad);
    p.sin_h = std::sin(p.heading_rad);
}

// Turns the heading offset by a small angle: the cosine and sine by the
// angle-sum formulas with the series of cos dh and sin dh (error below 1e-9
// for |dh| < 0.05 rad, then renormalised), sin and cos for larger turns.
void ParticleFilter::turn(Particle& p, double dh) const {
    if (std::abs(dh) > 0.05) {
        set_heading(p, p.heading_rad + dh);
        return;
    }
    const double d2 = dh * dh;
    const double c = 1.0 - 0.5 * d2 + d2 * d2 / 24.0, s = dh * (1.0 - d2 / 6.0 + d2 * d2 / 120.0);
    const double nc = p.cos_h * c - p.sin_h * s, ns = p.sin_h * c + p.cos_h * s;
    const double norm = 1.0 / std::sqrt(nc * nc + ns * ns);
    p.cos_h = nc * norm;
    p.sin_h = ns * norm;
    p.heading_rad = rewrap_after_turn(p.heading_rad + dh);
}

bool ParticleFilter::blocked(const Point2& a, const Point2& b) const {
    return map_ && map_->walls.crosses_wall(floor_, a, b);
}

bool ParticleFilter::forbidden(const Point2& p) const {
    return map_ && map_->zones.in_zone(floor_, p, indoor_map::ZoneKind::no_particles);
}

void ParticleFilter::start(const Point2& p, int floor, double heading_rad) {
    rng_ = Random(c_.seed);
    floor_ = floor;
    history_size_ = history_head_ = 0;
    recoveries_ = 0;
    consecutive_recoveries_ = 0;
    last_heading_rad_ = rewrap_after_turn(heading_rad);
    stalled_steps_ = 0;
    particles_.clear();
    const int n = c_.particles;
    for (int i = 0, tries = 0; i < n; ++tries) {
        Particle q;
        q.e_m = p.e_m + c_.init_position_sd_m * rng_.normal();
        q.n_m = p.n_m + c_.init_position_sd_m * rng_.normal();
        set_heading(q, heading_rad + c_.init_heading_sd_rad * rng_.normal());
        q.scale = rng_.uniform(c_.scale_min, c_.scale_max);
        const Point2 at{q.e_m, q.n_m};
        // Where the spread would put it behind a wall, at the start point.
        if (tries > 20 * n || (!blocked(p, at) && !forbidden(at))) {
            if (tries > 20 * n) q.e_m = p.e_m, q.n_m = p.n_m;
            particles_.push_back(q);
            ++i;
        }
    }
    started_ = true;
    update_estimate();
}

StepReport ParticleFilter::step(double de, double dn, const Point2& anchor) {
    StepReport report;
    if (!started_) start(anchor, floor_);
    last_heading_rad_ = estimate_.heading_rad;
    const int slot = history_head_;
    history_[slot] = {de, dn, floor_};
    history_head_ = (history_head_ + 1) % static_cast<int>(history_.size());
    if (history_size_ < static_cast<int>(history_.size())) ++history_size_;
    // Eq. (4): P_i += R(D s_i, h_i), heading clockwise positive, plus noise
    // (the heading offset's walk normal, the step length's and the
    // position's uniform); survivors are packed to the front.
    int live = 0;
    const bool zones = map_ && map_->zones.has_kind(floor_, indoor_map::ZoneKind::no_particles);
    const double length_halfwidth = std::sqrt(3.0) * c_.step_length_sd;
    const double position_halfwidth = std::sqrt(3.0) * c_.position_sd_m;
    const double scale_halfwidth = std::sqrt(3.0) * c_.scale_walk_sd;
    for (size_t i = 0; i < particles_.size(); ++i) {
        Particle q = particles_[i];
        if (c_.heading_walk_sd_rad > 0) turn(q, c_.heading_walk_sd_rad * rng_.normal());
        if (scale_halfwidth > 0)
            q.scale = std::clamp(q.scale * (1.0 + scale_halfwidth * (2.0 * rng_.uniform() - 1.0)), c_.scale_min,
                                 c_.scale_max);
        // Length and position noise uniform with the configured standard
        // deviations (half-width sqrt(3) sd): their shape does not matter to
        // the cloud, and uniforms cost a fraction of normals.
        const double k = q.scale * (1.0 + length_halfwidth * (2.0 * rng_.uniform() - 1.0));
        const double se = k * (de * q.cos_h + dn * q.sin_h), sn = k * (dn * q.cos_h - de * q.sin_h);
        const Point2 from{q.e_m, q.n_m};
        q.e_m += se + position_halfwidth * (2.0 * rng_.uniform() - 1.0);
        q.n_m += sn + position_halfwidth * (2.0 * rng_.uniform() - 1.0);
        const Point2 to{q.e_m, q.n_m};
        if (blocked(from, to) || (zones && forbidden(to))) continue;
        particles_[live++] = q;
    }
    report.survivors = live;
    particles_.resize(static_cast<size_t>(live));
    if (live == 0) {
        recover(anchor);
        report.recovered = true;
    } else {
        consecutive_recoveries_ = 0;
        regenerate(live);
    }
    update_estimate();
    means_[slot] = estimate_.mean;
    // Stalled over a whole window after the window, so that a cloud that
    // waits at a corridor's end for the track to turn (the walker was behind
    // it) is not taken for lost.
    Point2 expected;
    stalled_steps_ = !report.recovered && stalled(expected) ? stalled_steps_ + 1 : 0;
    if (stalled_steps_ >= static_cast<int>(history_.size())) {
        stalled_steps_ = 0;
        recover(expected);
        update_estimate();
        report.recovered = report.stalled = true;
        consecutive_recoveries_ = 0;
        history_size_ = 0;  // a fresh window for the new cloud
    }
    return report;
}

// Over the window of the recent steps: how far the track went (each step
// turned and scaled by the cloud's offset and scale) against how far the
// cloud's mean went. `expected` gets where the track puts the walker.
bool ParticleFilter::stalled(Point2& expected) const {
    const int size = static_cast<int>(history_.size());
    if (c_.stall_progress <= 0 || size < 3 || history_size_ < size) return false;
    const CloudEstimate& e = estimate_;
    const double ch = std::cos(e.heading_rad), sh = std::sin(e.heading_rad);
    double te = 0, tn = 0;
    for (int k = 0; k < size - 1; ++k) {  // the steps after the oldest mean
        const HistoryStep& s = history_[(history_head_ - 1 - k + 2 * size) % size];
        if (s.floor != floor_) return false;
        te += e.scale * (s.de_m * ch + s.dn_m * sh);
        tn += e.scale * (s.dn_m * ch - s.de_m * sh);
    }
    const double way2 = te * te + tn * tn;
    constexpr double kMinWayM = 2.0;  // shorter ways are within the cloud's own spread
    if (way2 < kMinWayM * kMinWayM) return false;
    const Point2& old = means_[history_head_ % size];  // the oldest slot is the next one written
    const double ce = e.mean.e_m - old.e_m, cn = e.mean.n_m - old.n_m;
    if (ce * te + cn * tn >= c_.stall_progress * way2) return false;
    expected = {old.e_m + te, old.n_m + tn};
    return true;
}

double ParticleFilter::survivors_heading(int survivors) const {
    double ss = 0, sc = 0;
    for (int i = 0; i < survivors; ++i) {
        ss += particles_[static_cast<size_t>(i)].sin_h;
        sc += particles_[static_cast<size_t>(i)].cos_h;
    }
    return std::atan2(ss, sc);  // eq. (3) corrected
}

void ParticleFilter::update_estimate() {
    CloudEstimate& e = estimate_;
    e = CloudEstimate{};
    const double n = static_cast<double>(particles_.size());
    if (particles_.empty()) return;
    double se = 0, sn = 0, ss = 0, sc = 0, scale = 0;
    for (const Particle& p : particles_) {
        se += p.e_m;
        sn += p.n_m;
        ss += p.sin_h;
        sc += p.cos_h;
        scale += p.scale;
    }
    e.mean = {se / n, sn / n};
    e.heading_rad = std::atan2(ss, sc);  // eq. (3) corrected
    e.scale = scale / n;
    double ee = 0, en = 0, nn = 0;
    for (const Particle& p : particles_) {
        const double a = p.e_m - e.mean.e_m, b = p.n_m - e.mean.n_m;
        ee += a * a;
        en += a * b;
        nn += b * b;
    }
    e.cov_m2[0] = ee / n;
    e.cov_m2[1] = en / n;
    e.cov_m2[2] = nn / n;
}

int ParticleFilter::nearest(const Point2& p) const {
    int best = -1;
    double best_d2 = INFINITY;
    for (size_t i = 0; i < particles_.size(); ++i) {
        const double a = particles_[i].e_m - p.e_m, b = particles_[i].n_m - p.n_m;
        const double d2 = a * a + b * b;
        if (d2 < best_d2) best_d2 = d2, best = static_cast<int>(i);
    }
    return best;
}

}  // namespace pednav::map_matching

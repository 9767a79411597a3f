// SPDX-License-Identifier: Apache-2.0
// Producing new particles (chest paper, Algorithm 1, with the retry counter
// inside the inner loop) with the backtracking test, and the recovery when
// every particle has died.
#include <algorithm>
#include <cmath>

#include "pednav_map_matching/particle_filter.hpp"

namespace pednav::map_matching {

// Walks p back over the recent steps with its own heading offset and scale
// (the inverse of eq. 4 without noise): it must cross no wall. Steps taken on
// another floor end the walk.
bool ParticleFilter::passes_backtracking(const Particle& p) const {
    if (!map_) return true;
    Point2 at{p.e_m, p.n_m};
    const int size = static_cast<int>(history_.size());
    for (int k = 0; k < history_size_; ++k) {
        const HistoryStep& s = history_[(history_head_ - 1 - k + 2 * size) % size];
        if (s.floor != floor_) break;
        const double se = p.scale * (s.de_m * p.cos_h + s.dn_m * p.sin_h);
        const double sn = p.scale * (s.dn_m * p.cos_h - s.de_m * p.sin_h);
        const Point2 before{at.e_m - se, at.n_m - sn};
        if (blocked(before, at) || forbidden(before)) return false;
        at = before;
    }
    return true;
}

// ProposeNewParticle: uniform in the disc of the radius around the parent,
// heading offset around heading_center. The scale is the parent's when the
// scales walk (scale_walk_sd > 0: each particle's scale is estimated, and the
// walls that selected the parent's keep selecting), else uniform in its range
// as the paper draws it.
Particle ParticleFilter::propose_around(const Particle& parent, double radius_m, double heading_center,
                                        double heading_sd) {
    Particle q;
    double de, dn;
    rng_.in_disc(radius_m, de, dn);
    q.e_m = parent.e_m + de;
    q.n_m = parent.n_m + dn;
    set_heading(q, heading_center + heading_sd * rng_.normal());
    q.scale = c_.scale_walk_sd > 0 && parent.scale > 0 ? parent.scale : rng_.uniform(c_.scale_min, c_.scale_max);
    return q;
}

// Algorithm 1. A proposal is kept when it is outside no-particle zones, seen
// from its parent (no wall between them: a new particle stays in its parent's
// room) and passes the backtracking test. The retry counter counts inside
// the inner loop (ERRATA.md); should the survivors sit where proposals keep
// failing, the outer loop is bounded too and the rest are copies of
// survivors.
void ParticleFilter::regenerate(int survivors) {
    const int n_max = c_.particles;
    if (survivors >= n_max) return;
    const double heading_mean = survivors_heading(survivors);
    const int missing = n_max - survivors;
    const long outer_max = missing;
    long outer = 0;
    while (static_cast<int>(particles_.size()) < n_max && outer++ < outer_max) {
        const Particle parent = particles_[rng_.index(static_cast<uint32_t>(survivors))];
        for (int try_time = 1; try_time <= c_.regen_tries; ++try_time) {
            const Particle q = propose_around(parent, c_.regen_radius_m, heading_mean, c_.regen_heading_sd_rad);
            const Point2 at{q.e_m, q.n_m};
            if (!forbidden(at) && !blocked({parent.e_m, parent.n_m}, at) && passes_backtracking(q)) {
                particles_.push_back(q);
                break;
            }
        }
    }
    while (static_cast<int>(particles_.size()) < n_max)
        particles_.push_back(particles_[rng_.index(static_cast<uint32_t>(survivors))]);
}

// Every particle died: reseed around the last estimate within a radius that
// grows with each consecutive recovery (the walker is farther from where the
// track thought). Proposals must pass the backtracking test; when too few do
// (the recent steps fit nowhere near), the rest need only a free spot.
void ParticleFilter::recover(const Point2& anchor) {
    ++recoveries_;
    const double radius = std::min(c_.recovery_max_radius_m,
                                   c_.recovery_radius_m * std::pow(c_.recovery_growth, consecutive_recoveries_));
    ++consecutive_recoveries_;
    // The heading offsets the cloud had before it died are gone; start from
    // the one the recovery is centred on.
    const double heading_center = last_heading_rad_;
    Particle centre{};  // scale 0: proposals draw theirs uniform in the range
    centre.e_m = anchor.e_m;
    centre.n_m = anchor.n_m;
    const int n_max = c_.particles;
    particles_.clear();
    const long tries_max = static_cast<long>(c_.regen_tries) * n_max;
    for (long t = 0; t < tries_max && static_cast<int>(particles_.size()) < n_max; ++t) {
        const Particle q = propose_around(centre, radius, heading_center, c_.recovery_heading_sd_rad);
        if (!forbidden({q.e_m, q.n_m}) && passes_backtracking(q)) particles_.push_back(q);
    }
    for (long t = 0; t < tries_max && static_cast<int>(particles_.size()) < n_max; ++t) {
        const Particle q = propose_around(centre, radius, heading_center, c_.recovery_heading_sd_rad);
        if (!forbidden({q.e_m, q.n_m})) particles_.push_back(q);
    }
    while (static_cast<int>(particles_.size()) < n_max) {
        Particle q = centre;
        set_heading(q, heading_center);
        q.scale = 0.5 * (c_.scale_min + c_.scale_max);
        particles_.push_back(q);
    }
}

}  // namespace pednav::map_matching

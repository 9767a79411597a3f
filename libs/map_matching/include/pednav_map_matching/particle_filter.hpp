// SPDX-License-Identifier: Apache-2.0
// Particle-filter map matching of a step-by-step track (chest paper, sec. 3.3,
// with the corrections of ERRATA.md).
//
// Each particle carries a position on the cloud's floor, a heading offset h_i
// and a step scale s_i (uniform in [scale_min, scale_max]). A step D (the
// stride's horizontal displacement) moves particle i by R(D s_i, h_i) (eq. 4)
// plus noise; a particle whose step crosses a wall, or that lands in a
// no-particle zone, dies. The dead are replaced around random survivors by
// Algorithm 1 with its retry counter inside the loop (as printed it never
// ends), each proposal kept only if it passes the backtracking test: walked
// back over the recent steps with its own heading and scale, it crosses no
// wall. When every particle dies the cloud is reseeded around the last
// estimate with a radius that grows at each consecutive recovery.
//
// A cloud can also be lost without dying: walking into a wall the map has no
// door in, survivors behind it refill the cloud step after step and it
// stalls while the track goes on. When over the backtracking window the
// cloud's mean advanced less than stall_progress of the track's way, and did
// so for as many steps again (a cloud ahead of the walker waits at the end of
// a corridor for the turn, for a few steps), the cloud is reseeded where the
// track says the walker is (a recovery too).
//
// The estimate is the mean position (eq. 2) and the circular mean of the
// heading offsets (eq. 3 corrected: atan2 of the mean sine and cosine).
//
// Memory is allocated at construction; start, step and change_floor allocate
// nothing.
#pragma once

#include <cstdint>
#include <vector>

#include <pednav_indoor_map/indexed_map.hpp>

#include "particle_filter_config.hpp"
#include "random.hpp"

namespace pednav::map_matching {

using indoor_map::Point2;

struct Particle {
    double e_m, n_m;        // position
    double heading_rad;     // heading offset, clockwise positive: rotates the step before it is applied
    double cos_h, sin_h;    // of heading_rad
    double scale;           // step scale s_i
};

// The cloud's summary after a step.
struct CloudEstimate {
    Point2 mean;              // eq. (2)
    double cov_m2[3];         // ee, en, nn of the positions about the mean
    double heading_rad;       // eq. (3) corrected: circular mean of the heading offsets
    double scale;             // mean step scale
};

// What a step did.
struct StepReport {
    int survivors = 0;      // live after the wall and zone tests, before regeneration
    bool recovered = false; // the cloud was reseeded: every particle died, or it stalled
    bool stalled = false;   // it was reseeded because it stalled
};

class ParticleFilter {
public:
    // `map` must outlive the filter (nullptr: no walls, no zones). Throws
    // std::invalid_argument for a config out of range.
    ParticleFilter(const ParticleFilterConfig& config, const indoor_map::IndexedMap* map);

    // A fresh cloud around p on `floor`, heading offsets around heading_rad;
    // the random sequence restarts from the seed. Particles are placed where
    // they can be: seen from p (no wall between) and outside no-particle zones.
    void start(const Point2& p, int floor, double heading_rad = 0.0);
    bool started() const { return started_; }

    // One step of horizontal displacement (de, dn) in the track's frame.
    // `anchor` is where the last estimate stood, the centre of a recovery.
    StepReport step(double de_m, double dn_m, const Point2& anchor);

    // The floor changed by stairs, an escalator or a lift, from floor() to
    // `to`: particles on a connector that links the two floors go to its exit,
    // the others die. When none is on one, the cloud is reseeded at the exit
    // of the linking connector nearest `anchor` (a recovery). A map without
    // any link between the two floors moves every particle as it stands.
    // Returns true when it was a recovery.
    bool change_floor(int to, const Point2& anchor);

    // Share of the particles on a connector linking floor() to `to`.
    double share_on_link(int to) const;

    // Of the cloud as it is after the latest start, step or floor change.
    const CloudEstimate& estimate() const { return estimate_; }
    // Index of the live particle nearest to point p.
    int nearest(const Point2& p) const;

    const std::vector<Particle>& particles() const { return particles_; }
    int floor() const { return floor_; }
    uint32_t recoveries() const { return recoveries_; }
    const ParticleFilterConfig& config() const { return c_; }

private:
    struct HistoryStep {
        double de_m, dn_m;
        int floor;
    };
    bool blocked(const Point2& a, const Point2& b) const;
    bool forbidden(const Point2& p) const;
    bool passes_backtracking(const Particle& p) const;
    Particle propose_around(const Particle& parent, double radius_m, double heading_center, double heading_sd);
    void regenerate(int survivors);
    void recover(const Point2& anchor);
    bool stalled(Point2& expected) const;
    void set_heading(Particle& p, double h) const;
    void turn(Particle& p, double dh) const;
    void update_estimate();
    double survivors_heading(int survivors) const;

    ParticleFilterConfig c_;
    const indoor_map::IndexedMap* map_;
    Random rng_;
    std::vector<Particle> particles_;
    std::vector<HistoryStep> history_;  // ring of the last backtrack_steps steps
    std::vector<Point2> means_;         // the cloud's mean after each of them
    int history_head_ = 0, history_size_ = 0;
    int floor_ = 0;
    bool started_ = false;
    uint32_t recoveries_ = 0;
    int consecutive_recoveries_ = 0;
    double last_heading_rad_ = 0.0;  // circular mean heading offset before the latest step
    int stalled_steps_ = 0;          // consecutive steps the cloud has been stalled
    CloudEstimate estimate_{};
};

}  // namespace pednav::map_matching

// SPDX-License-Identifier: Apache-2.0
// Floor changes through the map's connectors (stairs, escalators, lifts): the
// chest paper matches the position to the exit of the nearest arrow when the
// barometer has climbed a floor.
#include <cmath>

#include "pednav_map_matching/particle_filter.hpp"

namespace pednav::map_matching {

using indoor_map::Connector;

double ParticleFilter::share_on_link(int to) const {
    if (!map_ || particles_.empty()) return 0.0;
    int on = 0;
    for (const Particle& p : particles_)
        for (const Connector& c : map_->map.connectors)
            {
                if (connector_links(c, floor_, to) && near_connector(c, {p.e_m, p.n_m})) {
                    ++on;
                    break;
                }
            }
    return static_cast<double>(on) / static_cast<double>(particles_.size());
}

bool ParticleFilter::change_floor(int to, const Point2& anchor) {
    if (to == floor_) return false;
    const int from = floor_;
    if (!map_ || !map_->has_link(from, to)) {
        floor_ = to;  // nothing in the map says where: every particle as it stands
        update_estimate();
        return false;
    }
    int live = 0;
    for (size_t i = 0; i < particles_.size(); ++i) {
        Particle q = particles_[i];
        const Point2 at{q.e_m, q.n_m};
        for (const Connector& c : map_->map.connectors) {
            if (!connector_links(c, from, to) || !near_connector(c, at)) continue;
            const Point2 exit = connector_exit(c, to, at);
            q.e_m = exit.e_m;
            q.n_m = exit.n_m;
            particles_[live++] = q;
            break;
        }
    }
    particles_.resize(static_cast<size_t>(live));
    floor_ = to;
    // The recent steps were on the other floor: backtracking starts afresh.
    history_size_ = 0;
    if (live > 0) {
        regenerate(live);
        update_estimate();
        return false;
    }
    // Nobody on a connector: the track was off; take the linking connector
    // nearest the last estimate and restart at its exit.
    const Connector* best = nullptr;
    double best_d = INFINITY;
    for (const Connector& c : map_->map.connectors) {
        if (!connector_links(c, from, to) || c.area.empty()) continue;
        double d = 0;
        if (!near_connector(c, anchor)) {
            d = INFINITY;
            for (const Point2& v : c.area) d = std::min(d, std::hypot(v.e_m - anchor.e_m, v.n_m - anchor.n_m));
        }
        if (d < best_d) best_d = d, best = &c;
    }
    Point2 centre = anchor;
    if (best) {
        if (best->is_arrow) {
            centre = connector_exit(*best, to, anchor);
        } else {
            double se = 0, sn = 0;
            for (const Point2& v : best->area) se += v.e_m, sn += v.n_m;
            centre = near_connector(*best, anchor) ? anchor
                                                   : Point2{se / static_cast<double>(best->area.size()),
                                                            sn / static_cast<double>(best->area.size())};
        }
    }
    recover(centre);
    update_estimate();
    return true;
}

}  // namespace pednav::map_matching

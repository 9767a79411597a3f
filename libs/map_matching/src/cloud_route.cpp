// SPDX-License-Identifier: Apache-2.0
#include "pednav_map_matching/cloud_route.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pednav::map_matching {

namespace {
constexpr int64_t kCellBias = int64_t{1} << 30;  // the largest cell index, either way
}  // namespace

CloudRoute::CloudRoute(double cell_m, int particles, int history) : cell_m_(cell_m) {
    if (!(cell_m > 0) || particles < 1 || history < 1)
        throw std::invalid_argument("cloud route: cell_m must be positive, particles and history at least 1");
    size_t slots = 16;
    while (slots < 2 * static_cast<size_t>(particles)) slots *= 2;  // at most half full
    cells_.reserve(static_cast<size_t>(particles));
    slots_.assign(slots, -1);
    queue_.reserve(static_cast<size_t>(particles));
    particle_cell_.reserve(static_cast<size_t>(particles));
    history_.resize(static_cast<size_t>(history));
}

// Cell indices are kept within +-2^30, so that a neighbour's index fits in
// 32 bits too; the key is the two indices side by side.
inline uint64_t CloudRoute::key_of_cell(int64_t ix, int64_t iy) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(ix)) << 32) | static_cast<uint32_t>(iy);
}

inline void CloudRoute::cell_of_key(uint64_t key, int64_t& ix, int64_t& iy) {
    ix = static_cast<int32_t>(static_cast<uint32_t>(key >> 32));
    iy = static_cast<int32_t>(static_cast<uint32_t>(key));
}

inline uint64_t CloudRoute::key_of(double e_m, double n_m) const {
    const double bound = static_cast<double>(kCellBias);
    const double ix = std::clamp(std::floor(e_m / cell_m_), -bound, bound);
    const double iy = std::clamp(std::floor(n_m / cell_m_), -bound, bound);
    return key_of_cell(static_cast<int64_t>(ix), static_cast<int64_t>(iy));
}

namespace {
inline size_t slot_hash(uint64_t key, size_t mask) {
    return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
}
}  // namespace

inline int CloudRoute::find(uint64_t key) const {
    const size_t mask = slots_.size() - 1;
    for (size_t s = slot_hash(key, mask);; s = (s + 1) & mask) {
        const int c = slots_[s];
        if (c < 0) return -1;
        if (cells_[static_cast<size_t>(c)].key == key) return c;
    }
}

void CloudRoute::index(const std::vector<Particle>& particles) {
    std::fill(slots_.begin(), slots_.end(), -1);
    cells_.clear();
    particle_cell_.clear();
    const size_t n = std::min(particles.size(), particle_cell_.capacity());
    const size_t mask = slots_.size() - 1;
    for (size_t i = 0; i < n; ++i) {
        const Particle& p = particles[i];
        const uint64_t key = key_of(p.e_m, p.n_m);
        size_t s = slot_hash(key, mask);
        while (slots_[s] >= 0 && cells_[static_cast<size_t>(slots_[s])].key != key) s = (s + 1) & mask;
        if (slots_[s] < 0) {
            slots_[s] = static_cast<int>(cells_.size());
            cells_.push_back({key, 0, 0.0, 0.0, {p.e_m, p.n_m}, -2});
        }
        Cell& c = cells_[static_cast<size_t>(slots_[s])];
        ++c.count;
        c.sum_e_m += p.e_m;
        c.sum_n_m += p.n_m;
        particle_cell_.push_back(slots_[s]);
    }
}

inline int CloudRoute::neighbour(const Cell& c, int64_t de, int64_t dn) const {
    int64_t ix, iy;
    cell_of_key(c.key, ix, iy);
    return find(key_of_cell(ix + de, iy + dn));
}

int CloudRoute::block_count(const Cell& c) const {
    int sum = 0;
    for (int64_t a = -1; a <= 1; ++a)
        for (int64_t b = -1; b <= 1; ++b) {
            const int k = neighbour(c, a, b);
            if (k >= 0) sum += cells_[static_cast<size_t>(k)].count;
        }
    return sum;
}

// The densest 3 x 3 block of cells, then the group of cells joined to it
// where no wall stands between neighbouring cells' nodes: the output is the
// particle of that group nearest its mean. A cloud in one piece gives the
// particle nearest its mean (eq. 2); a cloud split by walls, the same for
// its largest piece.
int CloudRoute::mode_particle(const indoor_map::WallIndex* walls, int floor,
                              const std::vector<Particle>& particles) {
    int best = -1, best_count = -1;
    for (size_t i = 0; i < cells_.size(); ++i) {
        const int c = block_count(cells_[i]);
        if (c > best_count) best_count = c, best = static_cast<int>(i);
    }
    if (best < 0) return -1;
    for (Cell& c : cells_) c.parent = -2;
    queue_.clear();
    cells_[static_cast<size_t>(best)].parent = -1;
    queue_.push_back(best);
    double se = 0, sn = 0;
    int n = 0;
    for (size_t head = 0; head < queue_.size(); ++head) {
        const Cell& cell = cells_[static_cast<size_t>(queue_[head])];
        se += cell.sum_e_m;
        sn += cell.sum_n_m;
        n += cell.count;
        for (int64_t a = -1; a <= 1; ++a)
            for (int64_t b = -1; b <= 1; ++b) {
                const int k = neighbour(cell, a, b);
                if (k < 0 || cells_[static_cast<size_t>(k)].parent != -2) continue;
                if (walls && walls->crosses_wall(floor, cell.node, cells_[static_cast<size_t>(k)].node))
                    continue;
                cells_[static_cast<size_t>(k)].parent = queue_[head];
                queue_.push_back(k);
            }
    }
    const Point2 mean{se / n, sn / n};
    int nearest = -1;
    double nearest_d2 = INFINITY;
    for (size_t i = 0; i < particle_cell_.size(); ++i) {
        if (cells_[static_cast<size_t>(particle_cell_[i])].parent == -2) continue;  // not in the group
        const Particle& p = particles[i];
        const double d2 = (p.e_m - mean.e_m) * (p.e_m - mean.e_m) + (p.n_m - mean.n_m) * (p.n_m - mean.n_m);
        if (d2 < nearest_d2) nearest_d2 = d2, nearest = static_cast<int>(i);
    }
    return nearest;
}

void CloudRoute::record_output(const Point2& p) {
    const int size = static_cast<int>(history_.size());
    if (history_size_ > 0) {
        const Point2& last = history_[static_cast<size_t>((history_head_ - 1 + size) % size)];
        if (last.e_m == p.e_m && last.n_m == p.n_m) return;
    }
    history_[static_cast<size_t>(history_head_)] = p;
    history_head_ = (history_head_ + 1) % size;
    history_size_ = std::min(history_size_ + 1, size);
}

bool CloudRoute::next_waypoint(const indoor_map::WallIndex& walls, int floor, const Point2& from,
                               const Point2& goal, Point2& waypoint) {
    const int m = static_cast<int>(cells_.size());
    queue_.clear();
    for (int i = 0; i < m; ++i) {
        Cell& c = cells_[static_cast<size_t>(i)];
        c.parent = -2;
        if (!walls.crosses_wall(floor, from, c.node)) {
            c.parent = -1;
            queue_.push_back(i);
        }
    }
    // Breadth-first through neighbouring cells whose nodes see each other.
    for (size_t head = 0; head < queue_.size(); ++head) {
        const int c = queue_[head];
        const Cell& cell = cells_[static_cast<size_t>(c)];
        if (!walls.crosses_wall(floor, cell.node, goal)) {
            // The farthest node of the way that the output sees.
            for (int k = c; k >= 0; k = cells_[static_cast<size_t>(k)].parent) {
                const Cell& on_way = cells_[static_cast<size_t>(k)];
                if (on_way.parent == -1 || !walls.crosses_wall(floor, from, on_way.node)) {
                    waypoint = on_way.node;
                    return true;
                }
            }
        }
        for (int64_t a = -1; a <= 1; ++a)
            for (int64_t b = -1; b <= 1; ++b) {
                const int k = neighbour(cell, a, b);
                if (k < 0 || cells_[static_cast<size_t>(k)].parent != -2) continue;
                if (walls.crosses_wall(floor, cell.node, cells_[static_cast<size_t>(k)].node)) continue;
                cells_[static_cast<size_t>(k)].parent = c;
                queue_.push_back(k);
            }
    }
    // No way through the cloud: back along the output's own track (each of
    // its moves crossed no wall) as far as the output sees, to the first
    // point from which it sees a node of the cloud. The entries after it are
    // dropped, so that the next retrace goes on backwards.
    const int size = static_cast<int>(history_.size());
    auto entry = [&](int back) -> const Point2& {  // back = 0: the newest
        return history_[static_cast<size_t>((history_head_ - 1 - back + 2 * size) % size)];
    };
    int chosen = -1;
    for (int back = 0; back < history_size_; ++back) {
        const Point2& h = entry(back);
        if ((h.e_m != from.e_m || h.n_m != from.n_m) && walls.crosses_wall(floor, from, h)) break;
        chosen = back;
        bool sees_cloud = false;
        for (int i = 0; i < m && !sees_cloud; ++i)
            sees_cloud = !walls.crosses_wall(floor, h, cells_[static_cast<size_t>(i)].node);
        if (sees_cloud) break;
    }
    if (chosen <= 0) return false;  // nowhere to go back to, or already where the cloud is in sight
    waypoint = entry(chosen);
    history_head_ = (history_head_ - chosen + size) % size;
    history_size_ -= chosen;
    return true;
}

}  // namespace pednav::map_matching

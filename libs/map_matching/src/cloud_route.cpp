// SPDX-License-Identifier: Apache-2.0
#include "pednav_map_matching/cloud_route.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pednav::map_matching {

namespace {
constexpr int64_t kCellBias = int64_t{1} << 30;  // cell indices of +-10^9 cells fit in 32 bits
}  // namespace

CloudRoute::CloudRoute(double cell_m, int particles, int history) : cell_m_(cell_m) {
    if (!(cell_m > 0) || particles < 1 || history < 1)
        throw std::invalid_argument("cloud route: cell_m must be positive, particles and history at least 1");
    order_.reserve(static_cast<size_t>(particles));
    cells_.reserve(static_cast<size_t>(particles));
    parent_.reserve(static_cast<size_t>(particles));
    queue_.reserve(static_cast<size_t>(particles));
    history_.resize(static_cast<size_t>(history));
}

uint64_t CloudRoute::key_of_cell(int64_t ix, int64_t iy) {
    ix = std::clamp<int64_t>(ix, -kCellBias + 1, kCellBias - 1);
    iy = std::clamp<int64_t>(iy, -kCellBias + 1, kCellBias - 1);
    return (static_cast<uint64_t>(ix + kCellBias) << 32) | static_cast<uint64_t>(iy + kCellBias);
}

uint64_t CloudRoute::key_of(double e_m, double n_m) const {
    const double bound = static_cast<double>(kCellBias);
    const double ix = std::clamp(std::floor(e_m / cell_m_), -bound, bound);
    const double iy = std::clamp(std::floor(n_m / cell_m_), -bound, bound);
    return key_of_cell(static_cast<int64_t>(ix), static_cast<int64_t>(iy));
}

void CloudRoute::index(const std::vector<Particle>& particles) {
    order_.clear();
    cells_.clear();
    const size_t n = std::min(particles.size(), order_.capacity());
    for (size_t i = 0; i < n; ++i) order_.push_back({key_of(particles[i].e_m, particles[i].n_m), static_cast<int>(i)});
    std::sort(order_.begin(), order_.end());
    for (size_t i = 0; i < order_.size(); ++i) {
        if (i == 0 || order_[i].first != order_[i - 1].first) {
            const Particle& p = particles[static_cast<size_t>(order_[i].second)];
            cells_.push_back({order_[i].first, 0, static_cast<int>(i), {p.e_m, p.n_m}});
        }
        ++cells_.back().count;
    }
}

int CloudRoute::find(uint64_t key) const {
    const auto it = std::lower_bound(cells_.begin(), cells_.end(), key,
                                     [](const Cell& c, uint64_t k) { return c.key < k; });
    return it != cells_.end() && it->key == key ? static_cast<int>(it - cells_.begin()) : -1;
}

int CloudRoute::block_count(const Cell& c) const {
    const int64_t ix = static_cast<int64_t>(c.key >> 32) - kCellBias;
    const int64_t iy = static_cast<int64_t>(c.key & 0xffffffffu) - kCellBias;
    int sum = 0;
    for (int64_t a = -1; a <= 1; ++a)
        for (int64_t b = -1; b <= 1; ++b) {
            const int k = find(key_of_cell(ix + a, iy + b));
            if (k >= 0) sum += cells_[static_cast<size_t>(k)].count;
        }
    return sum;
}

// The densest 3 x 3 block of cells, then the group of cells joined to it
// where no wall stands between neighbouring cells' nodes: the output is the
// particle of that group nearest its mean. A cloud in one piece gives the
// particle nearest its mean (eq. 2); a cloud split by walls, the same for
// its largest piece.
int CloudRoute::mode_particle(const indoor_map::WallIndex* walls, int floor, const std::vector<Particle>& particles) {
    int best = -1, best_count = -1;
    for (size_t i = 0; i < cells_.size(); ++i) {
        const int c = block_count(cells_[i]);
        if (c > best_count) best_count = c, best = static_cast<int>(i);
    }
    if (best < 0) return -1;
    const int m = static_cast<int>(cells_.size());
    parent_.assign(static_cast<size_t>(m), -2);
    queue_.clear();
    parent_[static_cast<size_t>(best)] = -1;
    queue_.push_back(best);
    for (size_t head = 0; head < queue_.size(); ++head) {
        const Cell& cell = cells_[static_cast<size_t>(queue_[head])];
        const int64_t ix = static_cast<int64_t>(cell.key >> 32) - kCellBias;
        const int64_t iy = static_cast<int64_t>(cell.key & 0xffffffffu) - kCellBias;
        for (int64_t a = -1; a <= 1; ++a)
            for (int64_t b = -1; b <= 1; ++b) {
                const int k = find(key_of_cell(ix + a, iy + b));
                if (k < 0 || parent_[static_cast<size_t>(k)] != -2) continue;
                if (walls && walls->crosses_wall(floor, cell.node, cells_[static_cast<size_t>(k)].node)) continue;
                parent_[static_cast<size_t>(k)] = queue_[head];
                queue_.push_back(k);
            }
    }
    double se = 0, sn = 0;
    int n = 0;
    for (const int c : queue_) {
        const Cell& cell = cells_[static_cast<size_t>(c)];
        for (int k = 0; k < cell.count; ++k) {
            const Particle& p = particles[static_cast<size_t>(order_[static_cast<size_t>(cell.first + k)].second)];
            se += p.e_m;
            sn += p.n_m;
        }
        n += cell.count;
    }
    const Point2 mean{se / n, sn / n};
    int nearest = -1;
    double nearest_d2 = INFINITY;
    for (const int c : queue_) {
        const Cell& cell = cells_[static_cast<size_t>(c)];
        for (int k = 0; k < cell.count; ++k) {
            const int i = order_[static_cast<size_t>(cell.first + k)].second;
            const Particle& p = particles[static_cast<size_t>(i)];
            const double d2 = (p.e_m - mean.e_m) * (p.e_m - mean.e_m) + (p.n_m - mean.n_m) * (p.n_m - mean.n_m);
            if (d2 < nearest_d2) nearest_d2 = d2, nearest = i;
        }
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

bool CloudRoute::next_waypoint(const indoor_map::WallIndex& walls, int floor, const Point2& from, const Point2& goal,
                               Point2& waypoint) {
    const int m = static_cast<int>(cells_.size());
    parent_.assign(static_cast<size_t>(m), -2);
    queue_.clear();
    for (int i = 0; i < m; ++i)
        if (!walls.crosses_wall(floor, from, cells_[static_cast<size_t>(i)].node)) {
            parent_[static_cast<size_t>(i)] = -1;
            queue_.push_back(i);
        }
    // Breadth-first through neighbouring cells whose nodes see each other.
    for (size_t head = 0; head < queue_.size(); ++head) {
        const int c = queue_[head];
        const Cell& cell = cells_[static_cast<size_t>(c)];
        if (!walls.crosses_wall(floor, cell.node, goal)) {
            // The farthest node of the way that the output sees.
            for (int k = c; k >= 0; k = parent_[static_cast<size_t>(k)]) {
                const Point2& node = cells_[static_cast<size_t>(k)].node;
                if (parent_[static_cast<size_t>(k)] == -1 || !walls.crosses_wall(floor, from, node)) {
                    waypoint = node;
                    return true;
                }
            }
        }
        const int64_t ix = static_cast<int64_t>(cell.key >> 32) - kCellBias;
        const int64_t iy = static_cast<int64_t>(cell.key & 0xffffffffu) - kCellBias;
        for (int64_t a = -1; a <= 1; ++a)
            for (int64_t b = -1; b <= 1; ++b) {
                const int k = find(key_of_cell(ix + a, iy + b));
                if (k < 0 || parent_[static_cast<size_t>(k)] != -2) continue;
                if (walls.crosses_wall(floor, cell.node, cells_[static_cast<size_t>(k)].node)) continue;
                parent_[static_cast<size_t>(k)] = c;
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
        for (int i = 0; i < m && !sees_cloud; ++i) sees_cloud = !walls.crosses_wall(floor, h, cells_[static_cast<size_t>(i)].node);
        if (sees_cloud) break;
    }
    if (chosen <= 0) return false;  // nowhere to go back to, or already where the cloud is in sight
    waypoint = entry(chosen);
    history_head_ = (history_head_ - chosen + size) % size;
    history_size_ -= chosen;
    return true;
}

}  // namespace pednav::map_matching

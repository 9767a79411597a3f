// SPDX-License-Identifier: Apache-2.0
// Where the matcher's output stands, and how it gets there, read from the
// particle cloud.
//
// - The mode. The cloud's mean (chest paper, eq. 2) stands between the groups
//   of a cloud split by a wall (a corridor and the rooms off it), and the
//   particle nearest it may be in the smaller group. The output takes the
//   largest group instead: the particles are counted in square cells of
//   cell_m, the cell whose 3 x 3 block holds the most is the mode, its group
//   is every cell joined to it through neighbouring cells whose first
//   particles see each other (no wall between), and the output is the
//   particle of the group nearest the group's mean. A cloud in one piece
//   gives the particle nearest its mean, as before.
// - The route. The output never crosses a wall, so where the estimate moves
//   out of its sight (into the next room, or from a group the output was in
//   to another) it needs a way round. The cloud is one: each occupied cell's
//   first particle is a node, nodes of neighbouring cells are joined where no
//   wall stands between them, and a breadth-first search from the nodes the
//   output sees reaches one that sees the goal. The output moves to the
//   farthest node of that way in its sight. Without such a way (the cloud
//   has left the output's room), it retraces its own track, which crossed no
//   wall, back to where it sees the cloud again.
//
// Memory is allocated at construction for `particles` particles and
// `history` output positions; nothing is allocated per call.
#pragma once

#include <cstdint>
#include <vector>

#include <pednav_indoor_map/wall_index.hpp>

#include "particle_filter.hpp"

namespace pednav::map_matching {

class CloudRoute {
public:
    // cell_m > 0; particles >= 1; history >= 1 (output positions kept for
    // retracing).
    CloudRoute(double cell_m, int particles, int history);

    // Counts the particles in cells; call after each change of the cloud.
    void index(const std::vector<Particle>& particles);
    // Index of the particle at the cloud's mode (of the latest index()), its
    // cells joined where `walls` on `floor` (nullptr: none) allow; -1 for an
    // empty cloud.
    int mode_particle(const indoor_map::WallIndex* walls, int floor, const std::vector<Particle>& particles);

    // Where an output at `from` that cannot see `goal` on `floor` moves next:
    // a point it sees on a way round through the indexed cloud, or back along
    // its own track. False when there is neither.
    bool next_waypoint(const indoor_map::WallIndex& walls, int floor, const Point2& from, const Point2& goal,
                       Point2& waypoint);

    // The output's positions, for retracing (a new floor or a restart of the
    // output track clears them).
    void record_output(const Point2& p);
    void clear_outputs() { history_size_ = 0; }

private:
    struct Cell {
        uint64_t key;
        int count;
        double sum_e_m, sum_n_m;
        Point2 node;  // its first particle's position
        int parent;   // breadth-first search: the cell before, -1 a start, -2 unseen
    };
    static uint64_t key_of_cell(int64_t ix, int64_t iy);
    static void cell_of_key(uint64_t key, int64_t& ix, int64_t& iy);
    uint64_t key_of(double e_m, double n_m) const;
    int find(uint64_t key) const;  // index into cells_, -1 if empty
    int neighbour(const Cell& c, int64_t de, int64_t dn) const;
    int block_count(const Cell& c) const;

    double cell_m_;
    std::vector<Cell> cells_;  // in the order their first particle came
    std::vector<int> slots_;   // open addressing: index into cells_, -1 empty
    std::vector<int> queue_;
    std::vector<int> particle_cell_;  // each particle's cell
    std::vector<Point2> history_;     // ring of output positions
    int history_head_ = 0, history_size_ = 0;
};

}  // namespace pednav::map_matching

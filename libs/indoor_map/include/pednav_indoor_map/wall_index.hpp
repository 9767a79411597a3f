// SPDX-License-Identifier: Apache-2.0
// Wall tests through a uniform grid per floor. Every wall segment is listed
// in each cell its bounding box overlaps; a query segment walks the cells it
// passes through (Amanatides-Woo traversal) and tests only the walls listed
// there, so a step costs a few segment tests whatever the size of the map.
// Built once per map; queries allocate nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "map.hpp"

namespace pednav::indoor_map {

class WallIndex {
public:
    WallIndex() = default;
    // cell_m: side of a grid cell, m (> 0); 1 to 4 m suits indoor walls.
    // Throws std::invalid_argument for a bad cell size.
    WallIndex(const std::vector<WallSegment>& walls, double cell_m);

    // Whether segment [p0, p1] on `floor` shares a point with a wall of that
    // floor (segments_intersect: touching counts). A floor without walls has
    // none to cross.
    bool crosses_wall(int floor, const Point2& p0, const Point2& p1) const;

    // The first wall of `floor` that segment [p0, p1] meets: true with *t
    // (0..1 along the segment) and the wall's ends; false when it meets none.
    bool first_crossing(int floor, const Point2& p0, const Point2& p1, double* t, Point2* wall_a,
                        Point2* wall_b) const;

    size_t wall_count() const { return segment_count_; }
    double cell_m() const { return cell_m_; }

private:
    struct Segment {
        double ae, an, be, bn;
        double e_lo, e_hi, n_lo, n_hi;  // its bounding box
    };
    struct FloorGrid {
        int floor = 0;
        double e0 = 0, n0 = 0;  // south-west corner of the grid, m
        int cols = 0, rows = 0;
        std::vector<uint32_t> cell_begin;  // rows * cols + 1 offsets into cell_walls
        std::vector<uint32_t> cell_walls;  // indices into segments
        std::vector<Segment> segments;
    };
    const FloorGrid* grid_of(int floor) const;
    static bool crosses_in_cell(const FloorGrid& g, int cell, const Point2& p0, const Point2& p1);
    // Visits the cells [p0, p1] passes, in order, until visit(cell, t_exit)
    // returns true; t_exit is where the segment leaves the cell (0..1).
    template <class Visit>
    void walk_cells(const FloorGrid& g, const Point2& p0, const Point2& p1, Visit&& visit) const;

    std::vector<FloorGrid> floors_;
    double cell_m_ = 1.0;
    size_t segment_count_ = 0;
};

}  // namespace pednav::indoor_map

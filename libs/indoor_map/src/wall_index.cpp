// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/wall_index.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "grid_cell.hpp"
#include "pednav_indoor_map/geometry_2d.hpp"

namespace pednav::indoor_map {

namespace {

// A margin around the walls' bounding box, so that a wall on the box's edge
// lies inside a cell rather than on the grid's border.
constexpr double kMarginM = 0.01;

int clamp_index(double v, int n) { return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1); }

}  // namespace

WallIndex::WallIndex(const std::vector<WallSegment>& walls, double cell_m_asked) {
    if (!(cell_m_asked > 0) || !std::isfinite(cell_m_asked))
        throw std::invalid_argument("wall index cell size must be positive");
    std::map<int, std::vector<const WallSegment*>> by_floor;
    for (const WallSegment& w : walls) by_floor[w.floor].push_back(&w);
    // One cell side for every floor, bounded by the widest floor's extent.
    double extent_e_m = 0, extent_n_m = 0;
    for (const auto& [floor, list] : by_floor) {
        double e_min = INFINITY, n_min = INFINITY, e_max = -INFINITY, n_max = -INFINITY;
        for (const WallSegment* w : list) {
            e_min = std::min({e_min, w->a.e_m, w->b.e_m});
            e_max = std::max({e_max, w->a.e_m, w->b.e_m});
            n_min = std::min({n_min, w->a.n_m, w->b.n_m});
            n_max = std::max({n_max, w->a.n_m, w->b.n_m});
        }
        extent_e_m = std::max(extent_e_m, e_max - e_min + 2 * kMarginM);
        extent_n_m = std::max(extent_n_m, n_max - n_min + 2 * kMarginM);
    }
    cell_m_ = detail::grid_cell_m(cell_m_asked, extent_e_m, extent_n_m);
    const double cell_m = cell_m_;
    segment_count_ = walls.size();
    for (const auto& [floor, list] : by_floor) {
        FloorGrid g;
        g.floor = floor;
        double e_min = INFINITY, n_min = INFINITY, e_max = -INFINITY, n_max = -INFINITY;
        for (const WallSegment* w : list) {
            e_min = std::min({e_min, w->a.e_m, w->b.e_m});
            e_max = std::max({e_max, w->a.e_m, w->b.e_m});
            n_min = std::min({n_min, w->a.n_m, w->b.n_m});
            n_max = std::max({n_max, w->a.n_m, w->b.n_m});
        }
        g.e0 = e_min - kMarginM;
        g.n0 = n_min - kMarginM;
        g.cols = std::max(1, static_cast<int>(std::ceil((e_max + kMarginM - g.e0) / cell_m)));
        g.rows = std::max(1, static_cast<int>(std::ceil((n_max + kMarginM - g.n0) / cell_m)));
        g.segments.reserve(list.size());
        std::vector<std::vector<uint32_t>> cells(static_cast<size_t>(g.cols) * g.rows);
        for (const WallSegment* w : list) {
            const auto index = static_cast<uint32_t>(g.segments.size());
            g.segments.push_back({w->a.e_m, w->a.n_m, w->b.e_m, w->b.n_m, std::min(w->a.e_m, w->b.e_m),
                                  std::max(w->a.e_m, w->b.e_m), std::min(w->a.n_m, w->b.n_m),
                                  std::max(w->a.n_m, w->b.n_m)});
            // Cells the segment itself passes through (not its whole bounding
            // box: a long diagonal wall would fill a square of cells).
            const Point2 a = w->a, b = w->b;
            const int c0 = clamp_index((std::min(a.e_m, b.e_m) - g.e0) / cell_m, g.cols);
            const int c1 = clamp_index((std::max(a.e_m, b.e_m) - g.e0) / cell_m, g.cols);
            const int r0 = clamp_index((std::min(a.n_m, b.n_m) - g.n0) / cell_m, g.rows);
            const int r1 = clamp_index((std::max(a.n_m, b.n_m) - g.n0) / cell_m, g.rows);
            for (int r = r0; r <= r1; ++r)
                for (int c = c0; c <= c1; ++c) {
                    // The cell as a closed box, widened by a hair so that a wall
                    // along a cell border is listed on both sides.
                    const double x0 = g.e0 + c * cell_m - 1e-9, x1 = g.e0 + (c + 1) * cell_m + 1e-9;
                    const double y0 = g.n0 + r * cell_m - 1e-9, y1 = g.n0 + (r + 1) * cell_m + 1e-9;
                    const Point2 p00{x0, y0}, p10{x1, y0}, p11{x1, y1}, p01{x0, y1};
                    const bool inside = a.e_m >= x0 && a.e_m <= x1 && a.n_m >= y0 && a.n_m <= y1;
                    if (inside || segments_intersect(a, b, p00, p10) || segments_intersect(a, b, p10, p11) ||
                        segments_intersect(a, b, p11, p01) || segments_intersect(a, b, p01, p00))
                        cells[static_cast<size_t>(r) * g.cols + c].push_back(index);
                }
        }
        g.cell_begin.resize(cells.size() + 1);
        g.cell_begin[0] = 0;
        for (size_t i = 0; i < cells.size(); ++i)
            g.cell_begin[i + 1] = g.cell_begin[i] + static_cast<uint32_t>(cells[i].size());
        g.cell_walls.reserve(g.cell_begin.back());
        for (const auto& c : cells) g.cell_walls.insert(g.cell_walls.end(), c.begin(), c.end());
        floors_.push_back(std::move(g));
    }
}

const WallIndex::FloorGrid* WallIndex::grid_of(int floor) const {
    for (const FloorGrid& g : floors_)
        if (g.floor == floor) return &g;
    return nullptr;
}

bool WallIndex::crosses_in_cell(const FloorGrid& g, int cell, const Point2& p0, const Point2& p1) {
    // Walls whose bounding box misses the query's cannot share a point with
    // it: most are rejected by four comparisons before the exact test.
    const double qe0 = std::min(p0.e_m, p1.e_m), qe1 = std::max(p0.e_m, p1.e_m);
    const double qn0 = std::min(p0.n_m, p1.n_m), qn1 = std::max(p0.n_m, p1.n_m);
    for (uint32_t k = g.cell_begin[cell]; k < g.cell_begin[cell + 1]; ++k) {
        const Segment& s = g.segments[g.cell_walls[k]];
        if (s.e_hi < qe0 || s.e_lo > qe1 || s.n_hi < qn0 || s.n_lo > qn1) continue;
        if (segments_intersect(p0, p1, {s.ae, s.an}, {s.be, s.bn})) return true;
    }
    return false;
}

template <class Visit>
void WallIndex::walk_cells(const FloorGrid& g, const Point2& p0, const Point2& p1, Visit&& visit) const {
    // Clip the query to the grid's box (Liang-Barsky): outside it there are no walls.
    const double x1 = g.e0 + g.cols * cell_m_, y1 = g.n0 + g.rows * cell_m_;
    const double de = p1.e_m - p0.e_m, dn = p1.n_m - p0.n_m;
    double t0 = 0.0, t1 = 1.0;
    const double p[4] = {-de, de, -dn, dn};
    const double q[4] = {p0.e_m - g.e0, x1 - p0.e_m, p0.n_m - g.n0, y1 - p0.n_m};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0) return;
        } else {
            const double t = q[i] / p[i];
            if (p[i] < 0) t0 = std::max(t0, t);
            else t1 = std::min(t1, t);
        }
    }
    if (t0 > t1) return;
    // Walk the cells from the clipped start to the clipped end.
    const double inv = 1.0 / cell_m_;
    const double se = (p0.e_m + t0 * de - g.e0) * inv, sn = (p0.n_m + t0 * dn - g.n0) * inv;
    const double ee = (p0.e_m + t1 * de - g.e0) * inv, en = (p0.n_m + t1 * dn - g.n0) * inv;
    int c = clamp_index(se, g.cols), r = clamp_index(sn, g.rows);
    const int c_end = clamp_index(ee, g.cols), r_end = clamp_index(en, g.rows);
    const int step_c = de > 0 ? 1 : -1, step_r = dn > 0 ? 1 : -1;
    const double dxe = ee - se, dyn = en - sn;
    // Parameter (over the clipped segment, 0..1) at the next column / row border.
    const double t_delta_c = dxe != 0 ? std::abs(1.0 / dxe) : INFINITY;
    const double t_delta_r = dyn != 0 ? std::abs(1.0 / dyn) : INFINITY;
    double t_max_c = dxe != 0 ? ((step_c > 0 ? c + 1 - se : se - c) * t_delta_c) : INFINITY;
    double t_max_r = dyn != 0 ? ((step_r > 0 ? r + 1 - sn : sn - r) * t_delta_r) : INFINITY;
    const int max_cells = std::abs(c_end - c) + std::abs(r_end - r) + 1;
    for (int visited = 0; visited < max_cells; ++visited) {
        const bool last = c == c_end && r == r_end;
        const double t_exit = last ? 1.0 : t0 + (t1 - t0) * std::min(1.0, std::min(t_max_c, t_max_r));
        if (visit(r * g.cols + c, t_exit) || last) return;
        // Step across the nearer border; an axis already at its end cell
        // (rounding near a corner) gives way to the other.
        if (r == r_end || (c != c_end && t_max_c < t_max_r)) {
            c += step_c;
            t_max_c += t_delta_c;
        } else {
            r += step_r;
            t_max_r += t_delta_r;
        }
    }
}

bool WallIndex::crosses_wall(int floor, const Point2& p0, const Point2& p1) const {
    const FloorGrid* g = grid_of(floor);
    if (!g) return false;
    // Both ends inside the grid in the same or neighbouring cells (most
    // steps): the segment lies within the square of those at most 2 x 2
    // cells; testing all of them finds the same walls as the traversal.
    const double inv = 1.0 / cell_m_;
    const double x0 = (p0.e_m - g->e0) * inv, y0 = (p0.n_m - g->n0) * inv;
    const double x1 = (p1.e_m - g->e0) * inv, y1 = (p1.n_m - g->n0) * inv;
    // Inside the grid the coordinates are >= 0, where truncation is floor.
    const bool inside =
        x0 >= 0 && x0 < g->cols && y0 >= 0 && y0 < g->rows && x1 >= 0 && x1 < g->cols && y1 >= 0 && y1 < g->rows;
    const int ca = inside ? static_cast<int>(x0) : 0, ra = inside ? static_cast<int>(y0) : 0;
    const int cb = inside ? static_cast<int>(x1) : 0, rb = inside ? static_cast<int>(y1) : 0;
    if (inside && std::abs(cb - ca) <= 1 && std::abs(rb - ra) <= 1) {
        if (crosses_in_cell(*g, ra * g->cols + ca, p0, p1)) return true;
        if (cb == ca && rb == ra) return false;
        if (crosses_in_cell(*g, rb * g->cols + cb, p0, p1)) return true;
        if (cb == ca || rb == ra) return false;
        return crosses_in_cell(*g, ra * g->cols + cb, p0, p1) || crosses_in_cell(*g, rb * g->cols + ca, p0, p1);
    }
    bool hit = false;
    walk_cells(*g, p0, p1, [&](int cell, double) { return hit = crosses_in_cell(*g, cell, p0, p1); });
    return hit;
}

namespace {

// Where along [p0, p1] (0..1) it first meets [a, b], given that they meet.
double meeting_parameter(const Point2& p0, const Point2& p1, const Point2& a, const Point2& b) {
    const double rx = p1.e_m - p0.e_m, ry = p1.n_m - p0.n_m, sx = b.e_m - a.e_m, sy = b.n_m - a.n_m;
    const double den = rx * sy - ry * sx;
    const double len2 = rx * rx + ry * ry;
    if (den != 0.0) return std::clamp(((a.e_m - p0.e_m) * sy - (a.n_m - p0.n_m) * sx) / den, 0.0, 1.0);
    if (len2 == 0.0) return 0.0;
    // Collinear: the first of p0 (when on the wall) and the wall's ends on the segment.
    if (distance_to_segment(p0, a, b) == 0.0) return 0.0;
    const double ta = ((a.e_m - p0.e_m) * rx + (a.n_m - p0.n_m) * ry) / len2;
    const double tb = ((b.e_m - p0.e_m) * rx + (b.n_m - p0.n_m) * ry) / len2;
    return std::clamp(std::min(ta, tb), 0.0, 1.0);
}

}  // namespace

bool WallIndex::first_crossing(int floor, const Point2& p0, const Point2& p1, double* t, Point2* wall_a,
                               Point2* wall_b) const {
    const FloorGrid* g = grid_of(floor);
    if (!g) return false;
    double best = INFINITY;
    const Segment* best_wall = nullptr;
    walk_cells(*g, p0, p1, [&](int cell, double t_exit) {
        for (uint32_t k = g->cell_begin[cell]; k < g->cell_begin[cell + 1]; ++k) {
            const Segment& s = g->segments[g->cell_walls[k]];
            const Point2 a{s.ae, s.an}, b{s.be, s.bn};
            if (!segments_intersect(p0, p1, a, b)) continue;
            const double u = meeting_parameter(p0, p1, a, b);
            if (u < best) best = u, best_wall = &s;
        }
        return best <= t_exit;  // nothing in a later cell comes earlier
    });
    if (!best_wall) return false;
    if (t) *t = best;
    if (wall_a) *wall_a = {best_wall->ae, best_wall->an};
    if (wall_b) *wall_b = {best_wall->be, best_wall->bn};
    return true;
}

}  // namespace pednav::indoor_map

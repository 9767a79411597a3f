// SPDX-License-Identifier: Apache-2.0
// Plane geometry on Point2: the predicates a map is checked and matched with.
// Orientation is the sign of the cross product (counter-clockwise positive).
#pragma once

#include <algorithm>
#include <vector>

#include "map.hpp"

namespace pednav::indoor_map {

// Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise.
inline double orientation(const Point2& a, const Point2& b, const Point2& c) {
    return (b.e_m - a.e_m) * (c.n_m - a.n_m) - (b.n_m - a.n_m) * (c.e_m - a.e_m);
}

namespace detail {
inline int sign(double v) { return (v > 0) - (v < 0); }

// q on segment [a, b], given the three are collinear.
inline bool within_box(const Point2& a, const Point2& b, const Point2& q) {
    return std::min(a.e_m, b.e_m) <= q.e_m && q.e_m <= std::max(a.e_m, b.e_m) && std::min(a.n_m, b.n_m) <= q.n_m &&
           q.n_m <= std::max(a.n_m, b.n_m);
}
}  // namespace detail

// Whether segments [p0, p1] and [q0, q1] share a point (touching and
// collinear overlaps count). Inline: the wall index calls it for every wall
// near a particle's step.
inline bool segments_intersect(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1) {
    using detail::sign;
    using detail::within_box;
    const int d1 = sign(orientation(q0, q1, p0)), d2 = sign(orientation(q0, q1, p1));
    const int d3 = sign(orientation(p0, p1, q0)), d4 = sign(orientation(p0, p1, q1));
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    if (d1 == 0 && within_box(q0, q1, p0)) return true;
    if (d2 == 0 && within_box(q0, q1, p1)) return true;
    if (d3 == 0 && within_box(p0, p1, q0)) return true;
    if (d4 == 0 && within_box(p0, p1, q1)) return true;
    return false;
}

// Whether p is inside the ring (even-odd rule; points on the boundary may go
// either way).
bool point_in_ring(const Point2& p, const std::vector<Point2>& ring);

// Inside the outer ring and outside every hole.
bool point_in_polygon(const Point2& p, const std::vector<std::vector<Point2>>& rings);

// Distance from p to segment [a, b], m.
double distance_to_segment(const Point2& p, const Point2& a, const Point2& b);

// Distance from p to a polyline (at least one point), m.
double distance_to_polyline(const Point2& p, const std::vector<Point2>& points);

// Whether two edges of the ring cross, other than neighbours at their shared
// point; *edge_a and *edge_b (when given) get the first such pair.
bool ring_self_intersects(const std::vector<Point2>& ring, int* edge_a = nullptr, int* edge_b = nullptr);

}  // namespace pednav::indoor_map

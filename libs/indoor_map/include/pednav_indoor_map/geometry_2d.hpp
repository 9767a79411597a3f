// SPDX-License-Identifier: Apache-2.0
// Plane geometry on Point2: the predicates a map is checked and matched with.
// Orientation is the sign of the cross product (counter-clockwise positive).
#pragma once

#include <vector>

#include "map.hpp"

namespace pednav::indoor_map {

// Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise.
double orientation(const Point2& a, const Point2& b, const Point2& c);

// Whether segments [p0, p1] and [q0, q1] share a point (touching and
// collinear overlaps count).
bool segments_intersect(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1);

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

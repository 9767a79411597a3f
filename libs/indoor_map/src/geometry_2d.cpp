// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/geometry_2d.hpp"

#include <algorithm>
#include <cmath>

namespace pednav::indoor_map {

double orientation(const Point2& a, const Point2& b, const Point2& c) {
    return (b.e_m - a.e_m) * (c.n_m - a.n_m) - (b.n_m - a.n_m) * (c.e_m - a.e_m);
}

namespace {

int sign(double v) { return (v > 0) - (v < 0); }

// q on segment [a, b], given the three are collinear.
bool within_box(const Point2& a, const Point2& b, const Point2& q) {
    return std::min(a.e_m, b.e_m) <= q.e_m && q.e_m <= std::max(a.e_m, b.e_m) && std::min(a.n_m, b.n_m) <= q.n_m &&
           q.n_m <= std::max(a.n_m, b.n_m);
}

}  // namespace

bool segments_intersect(const Point2& p0, const Point2& p1, const Point2& q0, const Point2& q1) {
    const int d1 = sign(orientation(q0, q1, p0)), d2 = sign(orientation(q0, q1, p1));
    const int d3 = sign(orientation(p0, p1, q0)), d4 = sign(orientation(p0, p1, q1));
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    if (d1 == 0 && within_box(q0, q1, p0)) return true;
    if (d2 == 0 && within_box(q0, q1, p1)) return true;
    if (d3 == 0 && within_box(p0, p1, q0)) return true;
    if (d4 == 0 && within_box(p0, p1, q1)) return true;
    return false;
}

bool point_in_ring(const Point2& p, const std::vector<Point2>& ring) {
    bool inside = false;
    const size_t n = ring.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {
        const Point2 &a = ring[i], &b = ring[j];
        if ((a.n_m > p.n_m) != (b.n_m > p.n_m)) {
            const double e = a.e_m + (p.n_m - a.n_m) * (b.e_m - a.e_m) / (b.n_m - a.n_m);
            if (p.e_m < e) inside = !inside;
        }
    }
    return inside;
}

bool point_in_polygon(const Point2& p, const std::vector<std::vector<Point2>>& rings) {
    if (rings.empty() || !point_in_ring(p, rings[0])) return false;
    for (size_t i = 1; i < rings.size(); ++i)
        if (point_in_ring(p, rings[i])) return false;
    return true;
}

double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
    const double de = b.e_m - a.e_m, dn = b.n_m - a.n_m;
    const double len2 = de * de + dn * dn;
    double u = len2 > 0 ? ((p.e_m - a.e_m) * de + (p.n_m - a.n_m) * dn) / len2 : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    return std::hypot(p.e_m - (a.e_m + u * de), p.n_m - (a.n_m + u * dn));
}

double distance_to_polyline(const Point2& p, const std::vector<Point2>& points) {
    if (points.size() == 1) return std::hypot(p.e_m - points[0].e_m, p.n_m - points[0].n_m);
    double d = INFINITY;
    for (size_t i = 0; i + 1 < points.size(); ++i) d = std::min(d, distance_to_segment(p, points[i], points[i + 1]));
    return d;
}

bool ring_self_intersects(const std::vector<Point2>& ring, int* edge_a, int* edge_b) {
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a point
            if (segments_intersect(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n])) {
                if (edge_a) *edge_a = i;
                if (edge_b) *edge_b = j;
                return true;
            }
        }
    }
    return false;
}

}  // namespace pednav::indoor_map

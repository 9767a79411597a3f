// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/geometry_2d.hpp"

#include <algorithm>
#include <cmath>

namespace pednav::indoor_map {

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

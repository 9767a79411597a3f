// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/zone_index.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "grid_cell.hpp"
#include "pednav_indoor_map/geometry_2d.hpp"

namespace pednav::indoor_map {

namespace {
uint32_t kind_bit(ZoneKind k) { return 1u << static_cast<int>(k); }
}  // namespace

ZoneIndex::ZoneIndex(const std::vector<Zone>& zones, double cell_m_asked) : zones_(zones) {
    if (!(cell_m_asked > 0) || !std::isfinite(cell_m_asked))
        throw std::invalid_argument("zone index cell size must be positive");
    std::map<int, std::vector<uint32_t>> by_floor;
    for (size_t i = 0; i < zones_.size(); ++i)
        if (!zones_[i].rings.empty() && !zones_[i].rings[0].empty())
            by_floor[zones_[i].floor].push_back(static_cast<uint32_t>(i));
    // Each floor's bounding box; one cell side for every floor, bounded by the widest.
    std::map<int, std::array<double, 4>> boxes;  // e_min, n_min, e_max, n_max
    double extent_e_m = 0, extent_n_m = 0;
    for (const auto& [floor, list] : by_floor) {
        double e_min = INFINITY, n_min = INFINITY, e_max = -INFINITY, n_max = -INFINITY;
        for (uint32_t z : list)
            for (const Point2& p : zones_[z].rings[0]) {
                e_min = std::min(e_min, p.e_m);
                e_max = std::max(e_max, p.e_m);
                n_min = std::min(n_min, p.n_m);
                n_max = std::max(n_max, p.n_m);
            }
        boxes[floor] = {e_min, n_min, e_max, n_max};
        extent_e_m = std::max(extent_e_m, e_max - e_min);
        extent_n_m = std::max(extent_n_m, n_max - n_min);
    }
    cell_m_ = detail::grid_cell_m(cell_m_asked, extent_e_m, extent_n_m);
    const double cell_m = cell_m_;
    for (const auto& [floor, list] : by_floor) {
        FloorGrid g;
        g.floor = floor;
        const auto [e_min, n_min, e_max, n_max] = boxes[floor];
        g.e0 = e_min;
        g.n0 = n_min;
        g.cols = std::max(1, static_cast<int>(std::ceil((e_max - e_min) / cell_m)) + 1);
        g.rows = std::max(1, static_cast<int>(std::ceil((n_max - n_min) / cell_m)) + 1);
        std::vector<std::vector<uint32_t>> cells(static_cast<size_t>(g.cols) * g.rows);
        for (uint32_t z : list) {
            g.kinds |= kind_bit(zones_[z].kind);
            double ze0 = INFINITY, zn0 = INFINITY, ze1 = -INFINITY, zn1 = -INFINITY;
            for (const Point2& p : zones_[z].rings[0]) {
                ze0 = std::min(ze0, p.e_m);
                ze1 = std::max(ze1, p.e_m);
                zn0 = std::min(zn0, p.n_m);
                zn1 = std::max(zn1, p.n_m);
            }
            const int c0 = std::clamp(static_cast<int>(std::floor((ze0 - g.e0) / cell_m)), 0, g.cols - 1);
            const int c1 = std::clamp(static_cast<int>(std::floor((ze1 - g.e0) / cell_m)), 0, g.cols - 1);
            const int r0 = std::clamp(static_cast<int>(std::floor((zn0 - g.n0) / cell_m)), 0, g.rows - 1);
            const int r1 = std::clamp(static_cast<int>(std::floor((zn1 - g.n0) / cell_m)), 0, g.rows - 1);
            for (int r = r0; r <= r1; ++r)
                for (int c = c0; c <= c1; ++c) cells[static_cast<size_t>(r) * g.cols + c].push_back(z);
        }
        g.cell_begin.resize(cells.size() + 1);
        g.cell_begin[0] = 0;
        for (size_t i = 0; i < cells.size(); ++i)
            g.cell_begin[i + 1] = g.cell_begin[i] + static_cast<uint32_t>(cells[i].size());
        for (const auto& c : cells) g.cell_zones.insert(g.cell_zones.end(), c.begin(), c.end());
        floors_.push_back(std::move(g));
    }
}

bool ZoneIndex::has_kind(int floor, ZoneKind kind) const {
    for (const FloorGrid& g : floors_)
        if (g.floor == floor) return (g.kinds & kind_bit(kind)) != 0;
    return false;
}

const Zone* ZoneIndex::zone_at(int floor, const Point2& p, ZoneKind kind) const {
    for (const FloorGrid& g : floors_) {
        if (g.floor != floor) continue;
        if ((g.kinds & kind_bit(kind)) == 0) return nullptr;
        const double c = std::floor((p.e_m - g.e0) / cell_m_), r = std::floor((p.n_m - g.n0) / cell_m_);
        if (!(c >= 0 && c < g.cols && r >= 0 && r < g.rows)) return nullptr;
        const int cell = static_cast<int>(r) * g.cols + static_cast<int>(c);
        for (uint32_t k = g.cell_begin[cell]; k < g.cell_begin[cell + 1]; ++k) {
            const Zone& z = zones_[g.cell_zones[k]];
            if (z.kind == kind && point_in_polygon(p, z.rings)) return &z;
        }
        return nullptr;
    }
    return nullptr;
}

}  // namespace pednav::indoor_map

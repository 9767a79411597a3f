// SPDX-License-Identifier: Apache-2.0
// rairyuu's MapEditor text files (core, node, link, polygon, arrow) -> pednav.map/1.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "map_writer.hpp"
#include "pednav_indoor_map/geometry_2d.hpp"
#include "pednav_indoor_map/map_convert.hpp"

namespace pednav::indoor_map {

namespace {

using detail::SourcePoint;

struct Row {
    int line;
    std::vector<std::string> cells;
};

// Comma-separated rows after the header line, blank lines skipped.
std::vector<Row> rows(const SourceFile& f) {
    std::vector<Row> out;
    std::istringstream in(f.text);
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        ++line;
        if (!text.empty() && text.back() == '\r') text.pop_back();
        if (line == 1 || text.find_first_not_of(" \t") == std::string::npos) continue;
        Row r{line, {}};
        std::istringstream cells(text);
        std::string cell;
        while (std::getline(cells, cell, ',')) r.cells.push_back(cell);
        out.push_back(std::move(r));
    }
    return out;
}

struct Reader {
    const SourceFile& file;
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw std::runtime_error(file.name + ":" + std::to_string(line) + ": " + message);
    }
    void need(const Row& r, size_t n, const char* what) const {
        if (r.cells.size() < n) fail(r.line, std::string("expected ") + what);
    }
    double number(const Row& r, size_t k) const {
        const char* s = r.cells[k].c_str();
        char* end = nullptr;
        const double v = std::strtod(s, &end);
        if (end == s || *end != '\0' || !std::isfinite(v)) fail(r.line, "column " + std::to_string(k + 1) + " is not a number: \"" + r.cells[k] + "\"");
        return v;
    }
    int integer(const Row& r, size_t k) const {
        const double v = number(r, k);
        if (v != std::floor(v) || std::fabs(v) > 1e9) fail(r.line, "column " + std::to_string(k + 1) + " is not an integer: \"" + r.cells[k] + "\"");
        return static_cast<int>(v);
    }
};

struct Core {
    int floors = 0, start_floor = 0;
    double floor_height_m = 0, scale_m_per_px = 0, dir_rad = 0;
    SourcePoint start_px{0, 0};
};

// scale_m_per_px, when given, replaces the file's scale.
Core read_core(const SourceFile& f, std::optional<double> scale_m_per_px) {
    const Reader rd{f};
    Core c;
    bool have_floor = false, have_scale = false, have_start = false;
    for (const Row& r : rows(f)) {
        const std::string& key = r.cells[0];
        if (key == "floor") {
            rd.need(r, 2, "floor,COUNT,IMAGES...");
            c.floors = rd.integer(r, 1);
            if (c.floors < 1) rd.fail(r.line, "the floor count must be at least 1");
            have_floor = true;
        } else if (key == "height") {
            rd.need(r, 2, "height,METRES");
            c.floor_height_m = rd.number(r, 1);
        } else if (key == "start") {
            rd.need(r, 2, "start,FLOOR");
            c.start_floor = rd.integer(r, 1);
        } else if (key == "start_point") {
            rd.need(r, 3, "start_point,X_PX,Y_PX");
            c.start_px = {rd.number(r, 1), rd.number(r, 2)};
            have_start = true;
        } else if (key == "dir") {
            rd.need(r, 2, "dir,RADIANS");
            c.dir_rad = rd.number(r, 1);
        } else if (key == "scale") {
            rd.need(r, 2, "scale,M_PER_PX");
            c.scale_m_per_px = rd.number(r, 1);
            if (!(c.scale_m_per_px > 0)) rd.fail(r.line, "the scale (m per pixel) must be positive");
            have_scale = true;
        }
    }
    if (!have_floor || !have_scale || !have_start)
        throw std::runtime_error(f.name + ": needs floor, scale and start_point lines");
    if (scale_m_per_px) {
        if (!(*scale_m_per_px > 0)) throw std::invalid_argument("the scale (m per pixel) must be positive");
        c.scale_m_per_px = *scale_m_per_px;
    }
    if (c.start_floor < 0 || c.start_floor >= c.floors)
        throw std::runtime_error(f.name + ": start floor " + std::to_string(c.start_floor) + " is not one of its " +
                                 std::to_string(c.floors) + " floors");
    return c;
}

struct Node {
    int layer;
    SourcePoint m;  // source metres
};

class Converter {
public:
    Converter(const RairyuuMapFiles& files, const MapConversion& conversion)
        : files_(files), core_(read_core(files.core, conversion.scale_m_per_px)),
          start_m_{core_.start_px[0] * core_.scale_m_per_px, core_.start_px[1] * core_.scale_m_per_px},
          out_(conversion, conversion.start_source_m.value_or(start_m_)) {
        read_nodes();
    }

    std::string run() {
        if (core_.floor_height_m > 0) out_.top("pednav:floor_height_m", core_.floor_height_m);
        const Reader rd{files_.link};
        for (const Row& r : rows(files_.link)) {
            rd.need(r, 4, "id,type,node0,node1");
            const Node &a = node(rd, r, 2), &b = node(rd, r, 3);
            if (a.layer != b.layer) rd.fail(r.line, "a link joins nodes of layers " + std::to_string(a.layer) + " and " + std::to_string(b.layer));
            out_.line("wall", floor(a.layer), {a.m, b.m}, {{"source", "link " + r.cells[0]}});
        }
        read_arrows();
        read_polygons();
        out_.point("landmark", 0, start_m_, {{"name", "start"}, {"rairyuu_dir_rad", core_.dir_rad}});
        return out_.dump();
    }

private:
    struct Arrow {
        int foot_layer, head_layer;
        SourcePoint foot, head;
        const char* direction;
        std::string id;
    };

    int floor(int layer) const { return layer - core_.start_floor; }

    void read_nodes() {
        const Reader rd{files_.node};
        for (const Row& r : rows(files_.node)) {
            rd.need(r, 4, "id,layer,x,y");
            const int layer = rd.integer(r, 1);
            if (layer < 0 || layer >= core_.floors)
                rd.fail(r.line, "layer " + std::to_string(layer) + " is not one of " + files_.core.name + "'s " +
                                    std::to_string(core_.floors) + " floors");
            nodes_[rd.integer(r, 0)] = {layer, {rd.number(r, 2) * core_.scale_m_per_px, rd.number(r, 3) * core_.scale_m_per_px}};
        }
    }

    const Node& node(const Reader& rd, const Row& r, size_t k) const {
        const auto it = nodes_.find(rd.integer(r, k));
        if (it == nodes_.end()) rd.fail(r.line, "node " + r.cells[k] + " is not in " + files_.node.name);
        return it->second;
    }

    // An arrow lies on the floor arrived at, from node0 where the walker was
    // on the floor left to node1: type 0 from the floor below, 1 from above,
    // 2 from either.
    void read_arrows() {
        const Reader rd{files_.arrow};
        for (const Row& r : rows(files_.arrow)) {
            rd.need(r, 4, "id,type,node0,node1");
            const int type = rd.integer(r, 1);
            if (type < 0 || type > 2) rd.fail(r.line, "arrow type " + r.cells[1] + " is not 0 (from below), 1 (from above) or 2 (either)");
            const Node &from = node(rd, r, 2), &to = node(rd, r, 3);
            for (int side : {-1, 1}) {
                if ((type == 0 && side == 1) || (type == 1 && side == -1)) continue;
                const int foot = to.layer + side;
                if (type == 2 && (foot < 0 || foot >= core_.floors)) continue;
                Arrow a{foot, to.layer, from.m, to.m, side < 0 ? "up" : "down", r.cells[0]};
                out_.line("stairs", floor(a.foot_layer), {a.foot, a.head},
                          {{"source", "arrow " + a.id}, {"pednav:floor_to", floor(a.head_layer)}, {"pednav:direction", a.direction}});
                arrows_.push_back(std::move(a));
            }
        }
    }

    // Type 0: no particles. Type 1: where the floor may change; with the ends
    // of arrows in it, a stairs area to each floor they reach; without, kept
    // as a feature map readers ignore, as is any other type.
    void read_polygons() {
        const Reader rd{files_.polygon};
        for (const Row& r : rows(files_.polygon)) {
            rd.need(r, 3, "id,type,count,nodes...");
            const int type = rd.integer(r, 1), count = rd.integer(r, 2);
            if (count < 3 || r.cells.size() != static_cast<size_t>(3 + count))
                rd.fail(r.line, "a polygon of " + r.cells[2] + " nodes needs that many node ids after its count");
            std::vector<SourcePoint> ring;
            std::vector<Point2> plane;
            int layer = -1;
            for (int k = 0; k < count; ++k) {
                const Node& n = node(rd, r, 3 + static_cast<size_t>(k));
                if (layer >= 0 && n.layer != layer) rd.fail(r.line, "a polygon's nodes are on different layers");
                layer = n.layer;
                ring.push_back(n.m);
                plane.push_back({n.m[0], n.m[1]});
            }
            const nlohmann::json source = {{"source", "polygon " + r.cells[0]}, {"rairyuu_type", type}};
            if (type == 0) {
                out_.polygon("no_particles", floor(layer), ring, source);
                continue;
            }
            std::vector<int> reached;
            for (const Arrow& a : arrows_) {
                int other = -1;
                if (a.foot_layer == layer && point_in_ring({a.foot[0], a.foot[1]}, plane)) other = a.head_layer;
                if (a.head_layer == layer && point_in_ring({a.head[0], a.head[1]}, plane)) other = a.foot_layer;
                if (other >= 0 && std::find(reached.begin(), reached.end(), other) == reached.end()) reached.push_back(other);
            }
            std::sort(reached.begin(), reached.end());
            if (type != 1 || reached.empty()) out_.polygon("", 0, ring, source);
            for (int other : reached) {
                nlohmann::json props = source;
                props["pednav:floor_to"] = floor(other);
                out_.polygon("stairs", floor(layer), ring, props);
            }
        }
    }

    const RairyuuMapFiles& files_;
    Core core_;
    SourcePoint start_m_;
    detail::MapWriter out_;
    std::map<int, Node> nodes_;
    std::vector<Arrow> arrows_;
};

}  // namespace

std::string rairyuu_to_geojson(const RairyuuMapFiles& files, const MapConversion& conversion) {
    return Converter(files, conversion).run();
}

}  // namespace pednav::indoor_map

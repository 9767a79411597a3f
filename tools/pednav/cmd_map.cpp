// SPDX-License-Identifier: Apache-2.0
#include "cmd_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/map_check.hpp>
#include <pednav_indoor_map/map_convert.hpp>

#include "cli_common.hpp"

namespace {

namespace im = pednav::indoor_map;
namespace cli = pednav::cli;

constexpr const char* kUsage =
    "usage: pednav map check MAP [--start E,N[,FLOOR]] [--clearance M] [--origin lat,lon,height]\n"
    "       pednav map convert --from humolire|biba SOURCE --out MAP [--start X,Y] [--scale M_PER_PX]\n"
    "                          [--origin lat,lon,height]\n"
    "  check      what is wrong with a pednav.map/1 map (docs/maps.md), each problem naming its feature\n"
    "             by JSON pointer; exit 1 when there is any\n"
    "    --start      a walk's start, m east and north in the map's frame (floor 0 by default): it must be\n"
    "                 clear of walls, outside no-particle zones, inside a zone when its floor has any\n"
    "    --clearance  how close to a wall the start may be, m (default 0.3)\n"
    "    --origin     the engine's origin, for a WGS-84 map (default: the map's pednav:origin)\n"
    "  convert    a floor plan drawn in image pixels to pednav.map/1, local metres (east = x, north = -y)\n"
    "    --from humolire  HuMoLiRe's MapEditor JSON (map_data.json, or the folder that holds it)\n"
    "    --from biba      rairyuu's MapEditor files (the folder of core.txt, node, link, polygon, arrow)\n"
    "    --start      the walk's start, m in the source's frame, becomes (0, 0): biba x right, y down\n"
    "                 the image (default: core.txt's start point); humolire x right, y up from the\n"
    "                 image's bottom edge, as its keypoints (default: that frame's origin)\n"
    "    --scale      metres per pixel in place of the source's own (core.txt's scale, map_data.json's);\n"
    "                 --start is then in metres of this scale\n"
    "    --origin     write WGS-84 around this origin, the geodetic position of (0, 0)\n";

pednav::geodesy::GeodeticPoint parse_origin(const std::string& text, const std::string& option) {
    const std::vector<double> v = cli::parse_numbers(text, 3, option);
    if (std::fabs(v[0]) > 90 || std::fabs(v[1]) > 180)
        throw cli::UsageError(option + " latitude must be within 90 deg and longitude within 180 deg");
    return {v[0], v[1], v[2]};
}

bool is_dir(const std::string& path) {
    std::ifstream probe(path + "/.");
    return probe.good();
}

std::string plural(size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

// What the map holds, on one line.
std::string summary(const im::Map& m) {
    std::string s = plural(m.walls.size(), "wall segment") + ", " + plural(m.zones.size(), "zone") + ", " +
                    plural(m.connectors.size(), "connector") + ", " + plural(m.landmarks.size(), "landmark");
    if (m.floors.size() == 1) s += " on floor " + std::to_string(m.floors.front());
    if (m.floors.size() > 1)
        s += " on floors " + std::to_string(m.floors.front()) + " to " + std::to_string(m.floors.back());
    return s;
}

// Prints the problems as "NAME:POINTER: LEVEL: MESSAGE" (NAME alone for the
// document as a whole); returns how many.
size_t print_problems(const std::string& name, const std::vector<im::MapProblem>& problems, const char* level) {
    for (const auto& p : problems)
        std::printf("%s%s%s: %s: %s\n", name.c_str(), p.pointer.empty() ? "" : ":", p.pointer.c_str(), level,
                    p.message.c_str());
    return problems.size();
}

int check(cli::Args& in) {
    std::string path;
    im::MapCheckOptions options{std::nullopt, 0.3};
    std::optional<pednav::geodesy::GeodeticPoint> origin;
    while (!in.done()) {
        const std::string a = in.next();
        if (a == "--start") {
            const std::string v = in.value(a);
            const size_t commas = static_cast<size_t>(std::count(v.begin(), v.end(), ','));
            const std::vector<double> n = cli::parse_numbers(v, commas == 2 ? 3 : 2, a);
            if (n.size() == 3 && (n[2] != std::floor(n[2]) || std::fabs(n[2]) > 1000))
                throw cli::UsageError("--start FLOOR must be an integer, got \"" + v + "\"");
            options.start = im::MapStart{{n[0], n[1]}, n.size() == 3 ? static_cast<int>(n[2]) : 0};
        } else if (a == "--clearance") {
            options.wall_clearance_m = cli::parse_numbers(in.value(a), 1, a)[0];
            if (options.wall_clearance_m < 0) throw cli::UsageError("--clearance must not be negative");
        } else if (a == "--origin") {
            origin = parse_origin(in.value(a), a);
        } else if (!a.empty() && a[0] == '-') {
            throw cli::UsageError("unknown option " + a);
        } else if (path.empty()) {
            path = a;
        } else {
            throw cli::UsageError("one map at a time (" + path + " and " + a + ")");
        }
    }
    if (path.empty()) throw cli::UsageError("map check needs a MAP");
    const std::string doc = cli::read_text_file(path);
    const std::vector<im::MapProblem> problems = im::check_map(doc, origin, options);
    const size_t errors = print_problems(path, problems, "error");
    im::Map m;
    try {
        m = im::read_geojson_map(doc, origin);
    } catch (const im::MapError&) {
        std::printf("%s: cannot be read\n", path.c_str());
        return 1;
    }
    std::printf("%s: %s: %s\n", path.c_str(), summary(m).c_str(), errors ? plural(errors, "error").c_str() : "ok");
    return errors ? 1 : 0;
}

// core.txt names the other files ("node,node.txt").
std::string rairyuu_file_name(const std::string& core, const std::string& key) {
    std::istringstream in(core);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.compare(0, key.size() + 1, key + ",") == 0) return line.substr(key.size() + 1);
    }
    return key + ".txt";
}

im::SourceFile source(const std::string& path) { return {path, cli::read_text_file(path)}; }

int convert(cli::Args& in) {
    std::string from, src, out;
    im::MapConversion c;
    while (!in.done()) {
        const std::string a = in.next();
        if (a == "--from") {
            from = in.value(a);
            if (from != "humolire" && from != "biba") throw cli::UsageError("--from is humolire or biba, got \"" + from + "\"");
        } else if (a == "--out") {
            out = in.value(a);
        } else if (a == "--start") {
            const std::vector<double> v = cli::parse_numbers(in.value(a), 2, a);
            c.start_source_m = {{v[0], v[1]}};
        } else if (a == "--scale") {
            const double v = cli::parse_numbers(in.value(a), 1, a)[0];
            if (!(v > 0)) throw cli::UsageError("--scale (metres per pixel) must be positive");
            c.scale_m_per_px = v;
        } else if (a == "--origin") {
            c.origin = parse_origin(in.value(a), a);
        } else if (!a.empty() && a[0] == '-') {
            throw cli::UsageError("unknown option " + a);
        } else if (src.empty()) {
            src = a;
        } else {
            throw cli::UsageError("one SOURCE at a time (" + src + " and " + a + ")");
        }
    }
    if (from.empty() || src.empty() || out.empty()) throw cli::UsageError("map convert needs --from, a SOURCE and --out");
    std::string doc;
    if (from == "humolire") {
        doc = im::humolire_to_geojson(source(is_dir(src) ? src + "/map_data.json" : src), c);
    } else {
        const std::string core_path = src + "/core.txt";
        const im::SourceFile core = source(core_path);
        auto named = [&](const char* key) { return source(src + "/" + rairyuu_file_name(core.text, key)); };
        doc = im::rairyuu_to_geojson({core, named("node"), named("link"), named("polygon"), named("arrow")}, c);
    }
    std::ofstream f(out);
    f << doc;
    f.close();
    if (!f) throw std::runtime_error("cannot write " + out);
    const im::Map m = im::read_geojson_map(doc, std::nullopt);
    const size_t warnings = print_problems(out, im::check_map(doc, std::nullopt, {std::nullopt, 0.3}), "warning");
    std::printf("%s -> %s: %s%s\n", src.c_str(), out.c_str(), summary(m).c_str(),
                warnings ? (", " + plural(warnings, "warning")).c_str() : "");
    return 0;
}

}  // namespace

const char* const pednav_cmd_map_usage = kUsage;

int pednav_cmd_map(const std::vector<std::string>& args) {
    cli::Args in(args, kUsage);
    if (in.done()) throw cli::UsageError("map needs check or convert");
    const std::string what = in.next();
    try {
        if (what == "check") return check(in);
        if (what == "convert") return convert(in);
    } catch (const cli::UsageError&) {
        throw;
    } catch (const cli::HelpRequested&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav map %s: %s\n", what.c_str(), e.what());
        return 1;
    }
    throw cli::UsageError("unknown map command " + what + " (check or convert)");
}

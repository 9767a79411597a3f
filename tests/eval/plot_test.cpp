// SPDX-License-Identifier: Apache-2.0
// SVG output: well-formed XML, coordinates where they belong, no NaN.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include <pednav_eval/truth_readers.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_plot/eval_plot.hpp>
#include <pednav_plot/floor_plot.hpp>
#include <pednav_sim/building_map.hpp>
#include <pednav_sim/simulate.hpp>
#include <pednav_plot/walk_plot.hpp>

using namespace pednav::plot;

namespace {

// Tag balance of a small XML document: every element closed in order, quotes balanced.
bool well_formed(const std::string& s, std::string& why) {
    std::vector<std::string> stack;
    size_t i = 0;
    while ((i = s.find('<', i)) != std::string::npos) {
        const size_t j = s.find('>', i);
        if (j == std::string::npos) return why = "unterminated tag", false;
        const std::string tag = s.substr(i + 1, j - i - 1);
        i = j + 1;
        if (tag.empty()) return why = "empty tag", false;
        if (tag[0] == '?' || tag[0] == '!') continue;
        size_t quotes = 0;
        for (char c : tag) quotes += c == '"';
        if (quotes % 2) return why = "odd quotes in <" + tag + ">", false;
        if (tag.back() == '/') continue;
        const std::string name =
            tag.substr(tag[0] == '/' ? 1 : 0, tag.find_first_of(" \t\n") - (tag[0] == '/' ? 1 : 0));
        if (tag[0] == '/') {
            if (stack.empty() || stack.back() != name) return why = "unexpected </" + name + ">", false;
            stack.pop_back();
        } else {
            stack.push_back(name);
        }
    }
    if (!stack.empty()) return why = "unclosed <" + stack.back() + ">", false;
    return true;
}

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t i = s.find(what); i != std::string::npos; i = s.find(what, i + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("svg: escaping, NaN breaks a polyline, document is well-formed") {
    Svg svg(100, 50);
    svg.polyline({{0, 0}, {10, 10}, {NAN, 0}, {20, 20}, {30, 30}}, Stroke{});
    svg.text({5, 5}, "a < b & \"c\"");
    const std::string s = svg.str();
    std::string why;
    CHECK_MESSAGE(well_formed(s, why), why);
    CHECK(count(s, "<polyline") == 2);
    CHECK(s.find("a &lt; b &amp; &quot;c&quot;") != std::string::npos);
    CHECK(s.find("nan") == std::string::npos);
}

TEST_CASE("nice ticks") {
    CHECK(nice_ticks(0, 10, 5) == std::vector<double>{0, 2, 4, 6, 8, 10});
    CHECK(nice_ticks(-3, 7, 2) == std::vector<double>{0, 5});
    const std::vector<double> t = nice_ticks(0.1, 0.45, 4);
    REQUIRE(t.size() == 4);
    for (size_t i = 0; i < 4; ++i) CHECK(t[i] == doctest::Approx(0.1 * (i + 1)));
    CHECK(nice_ticks(1, 1, 4).empty());
}

TEST_CASE("map panel: equal scale on both axes") {
    MapPanel m;
    Series s;
    s.points = {{0, 0}, {100, 0}, {100, 50}};
    m.series.push_back(s);
    const std::string svg = render_map(m, 900, 600);
    std::string why;
    REQUIRE_MESSAGE(well_formed(svg, why), why);
    // The series' polyline: three points; 100 m wide and 50 m tall must come out 2:1 in pixels.
    const std::regex re("points=\"([-0-9.]+),([-0-9.]+) ([-0-9.]+),([-0-9.]+) ([-0-9.]+),([-0-9.]+)\"");
    std::smatch mt;
    REQUIRE(std::regex_search(svg, mt, re));
    const double x0 = std::stod(mt[1]), y0 = std::stod(mt[2]), x1 = std::stod(mt[3]), y2 = std::stod(mt[6]);
    CHECK((x1 - x0) / (y0 - y2) == doctest::Approx(2.0).epsilon(0.01));
    CHECK(y2 < y0);  // north is up
}

TEST_CASE("walk figure from an evaluation: truth, walls, estimate and error panel") {
    const pednav::eval::Truth truth =
        pednav::eval::read_truth(std::string(PEDNAV_SHARED_DATA_DIR) + "/humolire-phone/user1_8_shape");
    pednav::eval::Track track;
    for (const auto& p : truth.points) {
        pednav::eval::TrackSample s;
        s.t_s = p.t_s;
        s.pos_m[0] = p.x_m + 0.5;
        s.pos_m[1] = p.y_m;
        track.samples.push_back(s);
    }
    const pednav::eval::Metrics m = pednav::eval::evaluate(track, truth);
    const std::string svg = render_walk(walk_plot("user1 8 shape", track, &truth, &m));
    std::string why;
    CHECK_MESSAGE(well_formed(svg, why), why);
    CHECK(count(svg, "<polyline") >= 396 + 2);  // walls + estimate + error
    CHECK(svg.find("horizontal error (mean 0.50 m") != std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
    CHECK(svg.find("inf") == std::string::npos);
}

TEST_CASE("floor plot: the simulator's three-storey walk, one panel per floor with its walls, stairs and start") {
    const pednav::sim::Route route = pednav::sim::builtin_route("building_tour");
    const std::string doc = pednav::sim::building_map(route).dump();
    const pednav::indoor_map::Map map = pednav::indoor_map::read_geojson_map(doc, std::nullopt);
    pednav::sim::SimOptions o;
    o.mount = "chest";
    o.rate_hz = 20;
    const pednav::sim::SimOutput out = pednav::sim::simulate(route, o);
    FloorSeries truth{{"truth", "#2ca02c", {}, 2.5}, {}};
    for (const auto& s : out.truth) {
        truth.series.points.push_back({s.pos_enu_m[0], s.pos_enu_m[1]});
        truth.floors.push_back(s.floor);
    }
    const std::vector<MapPanel> panels = floor_panels(map, landmark_names(doc, map), {truth});
    REQUIRE(panels.size() == 3);
    size_t walls = 0;
    for (int f = 0; f < 3; ++f) {
        CAPTURE(f);
        CHECK(panels[f].title == "floor " + std::to_string(f));
        walls += panels[f].walls.size();
        CHECK(panels[f].links.size() == (f == 1 ? 2u : 1u));  // each flight shows on the two floors it joins
        REQUIRE(panels[f].series.size() == 1);
        // The truth on this floor only: the rings are 60 m x 30 m, every panel reaches both ends.
        double e1 = -INFINITY;
        for (const auto& p : panels[f].series[0].points)
            if (std::isfinite(p[0])) e1 = std::max(e1, p[0]);
        CHECK(e1 == doctest::Approx(60.0).epsilon(0.01));
    }
    CHECK(walls == map.walls.size());
    REQUIRE(panels[0].markers.size() == 1);
    CHECK(panels[0].markers[0].label == "start");
    CHECK(panels[1].markers.empty());
    const std::string svg = render_map_panels("building tour", panels);
    std::string why;
    CHECK_MESSAGE(well_formed(svg, why), why);
    CHECK(count(svg, ">floor ") == 3);
    CHECK(count(svg, "#ff7f0e") == 4 * 3);  // four arrows, each a line and a two-stroke head
    CHECK(svg.find(">start<") != std::string::npos);
    CHECK(svg.find("nan") == std::string::npos);
}

// SPDX-License-Identifier: Apache-2.0
#include <pednav_plot/svg.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace pednav::plot {

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string stroke_attrs(const Stroke& s) {
    std::string a = " stroke=\"" + xml_escape(s.color) + "\" stroke-width=\"" + num(s.width_px) + "\"";
    if (s.dashed) a += " stroke-dasharray=\"6 4\"";
    if (s.opacity < 1.0) a += " stroke-opacity=\"" + num(s.opacity) + "\"";
    return a;
}

bool finite(Point p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }

}  // namespace

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

Svg::Svg(double width_px, double height_px) : w_(width_px), h_(height_px) {}

void Svg::polyline(const std::vector<Point>& pts, const Stroke& stroke) {
    std::string piece;
    size_t count = 0;
    auto flush = [&]() {
        if (count >= 2)
            body_ += "<polyline fill=\"none\"" + stroke_attrs(stroke) +
                     " stroke-linejoin=\"round\" points=\"" + piece + "\"/>\n";
        piece.clear();
        count = 0;
    };
    for (const Point& p : pts) {
        if (!finite(p)) {
            flush();
            continue;
        }
        if (count > 0) piece += ' ';
        piece += num(p[0]) + "," + num(p[1]);
        ++count;
    }
    flush();
}

void Svg::line(Point a, Point b, const Stroke& stroke) {
    if (!finite(a) || !finite(b)) return;
    body_ += "<line x1=\"" + num(a[0]) + "\" y1=\"" + num(a[1]) + "\" x2=\"" + num(b[0]) + "\" y2=\"" +
             num(b[1]) + "\"" + stroke_attrs(stroke) + "/>\n";
}

void Svg::rect(Point tl, double w, double h, const std::string& fill, const Stroke& stroke) {
    if (!finite(tl)) return;
    body_ += "<rect x=\"" + num(tl[0]) + "\" y=\"" + num(tl[1]) + "\" width=\"" + num(w) + "\" height=\"" +
             num(h) + "\" fill=\"" + xml_escape(fill) + "\"" + stroke_attrs(stroke) + "/>\n";
}

void Svg::circle(Point c, double r, const std::string& fill) {
    if (!finite(c)) return;
    body_ += "<circle cx=\"" + num(c[0]) + "\" cy=\"" + num(c[1]) + "\" r=\"" + num(r) + "\" fill=\"" +
             xml_escape(fill) + "\"/>\n";
}

void Svg::text(Point at, const std::string& t, double size, const std::string& anchor,
               const std::string& color, double rotate_deg) {
    if (!finite(at)) return;
    body_ += "<text x=\"" + num(at[0]) + "\" y=\"" + num(at[1]) + "\" font-size=\"" + num(size) +
             "\" font-family=\"sans-serif\" text-anchor=\"" + xml_escape(anchor) + "\" fill=\"" +
             xml_escape(color) + "\"";
    if (rotate_deg != 0.0)
        body_ += " transform=\"rotate(" + num(rotate_deg) + " " + num(at[0]) + " " + num(at[1]) + ")\"";
    body_ += ">" + xml_escape(t) + "</text>\n";
}

void Svg::clip_rect(const std::string& id, Point tl, double w, double h) {
    defs_ += "<clipPath id=\"" + xml_escape(id) + "\"><rect x=\"" + num(tl[0]) + "\" y=\"" + num(tl[1]) +
             "\" width=\"" + num(w) + "\" height=\"" + num(h) + "\"/></clipPath>\n";
}

void Svg::begin_group(const std::string& clip_id) {
    body_ += clip_id.empty() ? "<g>\n" : "<g clip-path=\"url(#" + xml_escape(clip_id) + ")\">\n";
}

void Svg::end_group() { body_ += "</g>\n"; }

std::string Svg::str() const {
    std::string s =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
        num(w_) + "\" height=\"" + num(h_) + "\" viewBox=\"0 0 " + num(w_) + " " + num(h_) + "\">\n";
    s += "<rect x=\"0\" y=\"0\" width=\"" + num(w_) + "\" height=\"" + num(h_) + "\" fill=\"#ffffff\"/>\n";
    if (!defs_.empty()) s += "<defs>\n" + defs_ + "</defs>\n";
    s += body_ + "</svg>\n";
    return s;
}

void write_text_file(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace pednav::plot

// SPDX-License-Identifier: Apache-2.0
// A minimal SVG writer: shapes in pixel coordinates, text escaped, numbers
// written with fixed precision, non-finite coordinates dropped.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace pednav::plot {

using Point = std::array<double, 2>;

struct Stroke {
    std::string color = "#000000";
    double width_px = 1.0;
    bool dashed = false;
    double opacity = 1.0;
};

class Svg {
public:
    Svg(double width_px, double height_px);
    // A polyline; a non-finite point breaks it into pieces.
    void polyline(const std::vector<Point>& points_px, const Stroke& stroke);
    void line(Point a, Point b, const Stroke& stroke);
    void rect(Point top_left, double w, double h, const std::string& fill, const Stroke& stroke);
    void circle(Point c, double r_px, const std::string& fill);
    // anchor: "start", "middle" or "end"; rotate_deg around the anchor point.
    void text(Point at, const std::string& text, double size_px = 12.0, const std::string& anchor = "start",
              const std::string& color = "#000000", double rotate_deg = 0.0);
    void begin_group(const std::string& clip_id = "");
    void end_group();
    void clip_rect(const std::string& id, Point top_left, double w, double h);
    std::string str() const;  // the whole document
    double width() const { return w_; }
    double height() const { return h_; }

private:
    double w_, h_;
    std::string body_, defs_;
};

std::string xml_escape(const std::string& s);
// Writes text to a file; throws std::runtime_error naming it.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace pednav::plot

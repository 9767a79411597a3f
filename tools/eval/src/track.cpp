// SPDX-License-Identifier: Apache-2.0
#include <pednav_eval/track.hpp>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "fields.hpp"

namespace pednav::eval {

using detail::number;
using io::find_column;

TrackSample Track::at(double t_s) const {
    if (samples.empty()) throw std::runtime_error("track: empty");
    if (t_s <= samples.front().t_s) return samples.front();
    if (t_s >= samples.back().t_s) return samples.back();
    const auto it = std::upper_bound(samples.begin(), samples.end(), t_s,
                                     [](double t, const TrackSample& s) { return t < s.t_s; });
    const TrackSample& b = *it;
    const TrackSample& a = *(it - 1);
    const double span = b.t_s - a.t_s;
    const double w = span > 0.0 ? (t_s - a.t_s) / span : 1.0;
    TrackSample r = w < 0.5 ? a : b;  // floor and flags from the nearer sample
    r.t_s = t_s;
    for (int i = 0; i < 3; ++i) r.pos_m[i] = a.pos_m[i] + w * (b.pos_m[i] - a.pos_m[i]);
    if (std::isfinite(a.heading_deg) && std::isfinite(b.heading_deg)) {
        double d = std::fmod(b.heading_deg - a.heading_deg + 540.0, 360.0) - 180.0;
        r.heading_deg = std::fmod(a.heading_deg + w * d + 360.0, 360.0);
    }
    return r;
}

double Track::length_m() const {
    double len = 0.0;
    for (size_t i = 1; i < samples.size(); ++i)
        len += std::hypot(samples[i].pos_m[0] - samples[i - 1].pos_m[0],
                          samples[i].pos_m[1] - samples[i - 1].pos_m[1]);
    return len;
}

Track read_track_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read track " + path);
    Track track;
    std::string line;
    std::vector<std::string> header;
    int ct = -1, cx = -1, cy = -1, cz = -1, ch = -1, cf = -1;
    size_t n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string_view> f = io::split(line, ',');
        if (header.empty()) {
            header = detail::to_strings(f);
            ct = find_column(header, "t"), cx = find_column(header, "x"), cy = find_column(header, "y"),
            cz = find_column(header, "z");
            ch = find_column(header, "heading_deg"), cf = find_column(header, "floor");
            if (ct < 0 || cx < 0 || cy < 0)
                throw std::runtime_error(path + ":" + std::to_string(n) +
                                         ": a track needs the columns t, x, y");
            continue;
        }
        if (f.size() < header.size())
            throw std::runtime_error(path + ":" + std::to_string(n) + ": expected " +
                                     std::to_string(header.size()) + " columns");
        TrackSample s;
        s.t_s = number(f[ct], path, n, "t");
        s.pos_m[0] = number(f[cx], path, n, "x");
        s.pos_m[1] = number(f[cy], path, n, "y");
        s.pos_m[2] = cz >= 0 ? number(f[cz], path, n, "z") : 0.0;
        if (ch >= 0 && !f[ch].empty()) s.heading_deg = number(f[ch], path, n, "heading_deg");
        if (cf >= 0 && !f[cf].empty()) {
            s.floor = static_cast<int>(number(f[cf], path, n, "floor"));
            s.has_floor = true;
        }
        if (!track.samples.empty() && s.t_s < track.samples.back().t_s)
            throw std::runtime_error(path + ":" + std::to_string(n) + ": time goes backwards");
        track.samples.push_back(s);
    }
    if (track.samples.empty()) throw std::runtime_error(path + ": no track samples");
    return track;
}

std::vector<double> read_step_times_csv(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read steps " + path);
    std::vector<double> t;
    std::string line;
    size_t n = 0;
    bool first = true;
    int col = 0;  // the time column: t_end (pednav run --steps), t, or the first
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string_view> f = io::split(line, ',');
        if (first) {
            first = false;
            double unused = 0.0;
            if (io::parse_number(f[0], &unused) != io::NumberStatus::ok) {  // a header line
                const std::vector<std::string> header = detail::to_strings(f);
                if (find_column(header, "t_end") >= 0)
                    col = find_column(header, "t_end");
                else if (find_column(header, "t") >= 0)
                    col = find_column(header, "t");
                continue;
            }
        }
        if (static_cast<size_t>(col) >= f.size())
            throw std::runtime_error(path + ":" + std::to_string(n) + ": short row");
        t.push_back(number(f[col], path, n));
    }
    return t;
}

Track track_from_positions(const std::vector<pn_position_t>& positions) {
    Track track;
    track.samples.reserve(positions.size());
    for (const pn_position_t& p : positions) {
        TrackSample s;
        s.t_s = static_cast<double>(p.header.t_ns) * 1e-9;
        for (int i = 0; i < 3; ++i) s.pos_m[i] = p.pos_enu_m[i];
        s.heading_deg = std::fmod(p.heading_rad * 180.0 / M_PI + 720.0, 360.0);
        s.has_floor = (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) != 0;
        s.floor = p.floor;
        track.samples.push_back(s);
    }
    return track;
}

std::vector<double> step_times_from_strides(const std::vector<pn_stride_t>& strides) {
    std::vector<double> t;
    t.reserve(strides.size());
    for (const pn_stride_t& s : strides) t.push_back(static_cast<double>(s.header.t_ns) * 1e-9);
    return t;
}

std::vector<double> step_times_from_steps(const std::vector<pn_step_t>& steps) {
    std::vector<double> t;
    t.reserve(steps.size());
    for (const pn_step_t& s : steps)
        if (s.motion_mode != PN_STEP_MODE_STATIC) t.push_back(static_cast<double>(s.header.t_ns) * 1e-9);
    return t;
}

}  // namespace pednav::eval

// SPDX-License-Identifier: Apache-2.0
// The engine's geodetic origin: the WGS-84 point at ENU (0, 0, 0). It is set
// at most once per segment, by the first of: the config, the app, a map
// matcher offering its map's origin, a good GNSS fix; and it remembers which,
// so a call that comes too late can say where the current one came from.
// Header-only and allocation-free: the host slots read it from plugin code.
#pragma once

#include <cmath>

#include <pednav/pn_types.h>

namespace pednav::engine {

class GeoOrigin {
public:
    enum class Source { none, config, app, plugin, gnss_fix };

    bool known() const { return source_ != Source::none; }
    Source source() const { return source_; }
    const pn_geo_point_t& point() const { return point_; }

    // Takes `p` if there is no origin yet; false otherwise (nothing changes).
    // `by` names who gave it (a plugin instance), kept for messages; it must
    // outlive the origin.
    bool set(const pn_geo_point_t& p, Source s, const char* by = nullptr) {
        if (known()) return false;
        point_ = p;
        source_ = s;
        by_ = by;
        return true;
    }
    const char* given_by() const { return by_ ? by_ : ""; }
    // A reset forgets what the data gave (a GNSS fix, a map matcher's offer,
    // which it makes again when its map is given again); the config's and the
    // app's origins describe the frame the app works in and stay.
    void forget_derived() {
        if (source_ == Source::gnss_fix || source_ == Source::plugin) source_ = Source::none;
    }

    static bool valid(const pn_geo_point_t& p) {
        return std::isfinite(p.lat_deg) && std::isfinite(p.lon_deg) && std::isfinite(p.height_m) &&
               std::fabs(p.lat_deg) <= 90.0 && std::fabs(p.lon_deg) <= 180.0 && std::fabs(p.height_m) <= 1e5;
    }
    static const char* source_name(Source s);

private:
    pn_geo_point_t point_{0.0, 0.0, 0.0};
    Source source_ = Source::none;
    const char* by_ = nullptr;
};

}  // namespace pednav::engine

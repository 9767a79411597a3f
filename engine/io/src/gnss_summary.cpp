// SPDX-License-Identifier: Apache-2.0
// What a stream of fixes holds, for `pednav inspect` and the run summary.
#include <algorithm>
#include <cstdio>
#include <ctime>

#include <nlohmann/json.hpp>

#include "pednav_io/gnss_log.hpp"

namespace pednav::io {

namespace {

const char* fix_type_name(int32_t t) {
    switch (t) {
        case PN_GNSS_FIX_AUTONOMOUS: return "autonomous";
        case PN_GNSS_FIX_DIFFERENTIAL: return "differential";
        case 3: return "pps";
        case PN_GNSS_FIX_RTK_FIXED: return "rtk_fixed";
        case PN_GNSS_FIX_RTK_FLOAT: return "rtk_float";
        case PN_GNSS_FIX_DEAD_RECKONING: return "dead_reckoning";
        default: return "unknown";
    }
}

template <typename T>
T median(std::vector<T> v) {
    if (v.empty()) return T{};
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

}  // namespace

std::string iso_utc(int64_t utc_ns) {
    const std::time_t seconds = static_cast<std::time_t>(utc_ns / 1000000000);
    const int millis = static_cast<int>((utc_ns % 1000000000) / 1000000);
    std::tm tm{};
    gmtime_r(&seconds, &tm);
    char text[96];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, millis);
    return text;
}

nlohmann::json gnss_fixes_json(const std::vector<pn_gnss_t>& fixes) {
    using nlohmann::json;
    json types = json::object();
    std::vector<int32_t> sats;
    std::vector<double> h;
    size_t with_velocity = 0;
    for (const pn_gnss_t& g : fixes) {
        const char* name = fix_type_name(g.fix_type);
        types[name] = types.value(name, 0) + 1;
        if (g.satellites > 0) sats.push_back(g.satellites);
        h.push_back(g.h_accuracy_m);
        if (g.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) ++with_velocity;
    }
    json satellites = nullptr;
    if (!sats.empty())
        satellites = {*std::min_element(sats.begin(), sats.end()), median(sats),
                      *std::max_element(sats.begin(), sats.end())};
    json h_accuracy = {{"median", h.empty() ? 0.0 : median(h)},
                       {"max", h.empty() ? 0.0 : *std::max_element(h.begin(), h.end())}};
    json utc_first = nullptr;
    if (!fixes.empty() && fixes.front().utc_ns != 0) utc_first = iso_utc(fixes.front().utc_ns);
    return {{"count", fixes.size()},
            {"fix_types", types},
            {"satellites", satellites},
            {"h_accuracy_m", h_accuracy},
            {"with_velocity", with_velocity},
            {"utc_first", utc_first}};
}

}  // namespace pednav::io

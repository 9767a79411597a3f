// SPDX-License-Identifier: Apache-2.0
// Writers for what a run produced: track and step CSVs, GeoJSON, GPX, and the
// JSON run summary. docs/formats.md describes every file and key.
#pragma once

#include <string>
#include <vector>

#include <pednav/pn_types.h>
#include <nlohmann/json.hpp>

#include "pednav_io/origin.hpp"
#include "pednav_io/sensor_log.hpp"

namespace pednav::io {

// Header t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz: t in s, metres
// ENU from the start point, heading in degrees clockwise from north, floor
// empty when the position has none. Throws std::runtime_error on I/O failure.
void write_track_csv(const std::string& path, const std::vector<pn_position_t>& positions);

// Header index,t_start,t_end,dx,dy,dz,length_m,heading_change_deg,class,cov_xx,cov_xy,cov_yy,cov_zz.
void write_steps_csv(const std::string& path, const std::vector<pn_stride_t>& strides);

// Header t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m: the
// track in WGS-84 through `origin` (the engine's: the same exact conversion as
// pn_engine_geo_from_enu), source = inertial, fused, gnss or map (the mode of
// the position filter), h_sigma_m = sqrt(cov_xx + cov_yy). Throws
// std::runtime_error when the origin is not known or on I/O failure.
void write_geo_track_csv(const std::string& path, const std::vector<pn_position_t>& positions,
                         const Origin& origin);

// What a GeoJSON may carry besides the track, its steps and floor changes.
struct GeoJsonExtras {
    bool position_points = false;               // a Point per (thinned) position with its properties
    const std::vector<pn_gnss_t>* gnss_fixes = nullptr;  // the input's fixes, a Point each
};

// FeatureCollection: a LineString of the track (per-vertex times, sources and
// floors), a Point per step (end of the stride), per floor change and per
// change of source, with times. Coordinates are WGS-84 [lon, lat, height]
// when origin.known, else local metres [x, y, z] (then the collection carries
// "crs_local_enu_m": true).
void write_geojson(const std::string& path, const std::vector<pn_position_t>& positions,
                   const std::vector<pn_stride_t>& strides, const Origin& origin,
                   const GeoJsonExtras& extras = {});

// GPX 1.1 track, each point with its source as <type> and its floor in
// <extensions>. GPX is WGS-84 only: with no known origin the track is placed
// at lat/lon 0/0 (documented; the file says so in <desc>).
void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin);

// "inertial", "fused", "gnss", "map" (PN_POSITION_SOURCE_*), "unknown" otherwise.
const char* position_source_name(int32_t source);

// Horizontal length of the track in metres: the sum of the east-north steps
// between consecutive positions (the summary's "distance_m").
double track_length_m(const std::vector<pn_position_t>& positions);

// The JSON run summary (keys in docs/formats.md): the input as detected, the
// pipeline from `describe_json` (pn_engine_describe), counts, distance, duration,
// warnings.
nlohmann::json run_summary_json(const SensorLog& input, const std::string& describe_json,
                                const std::vector<pn_position_t>& positions,
                                const std::vector<pn_stride_t>& strides,
                                const std::vector<std::string>& warnings);

// Input part of the summary and of `pednav inspect --json`.
nlohmann::json sensor_log_json(const SensorLog& log);

}  // namespace pednav::io

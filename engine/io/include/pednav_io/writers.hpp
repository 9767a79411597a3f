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

// FeatureCollection: a LineString of the track, a Point per step (end of the
// stride) and per floor change, with times. Coordinates are WGS-84
// [lon, lat, height] when origin.known, else local metres [x, y, z]
// (then the collection carries "crs_local_enu_m": true).
void write_geojson(const std::string& path, const std::vector<pn_position_t>& positions,
                   const std::vector<pn_stride_t>& strides, const Origin& origin);

// GPX 1.1 track. GPX is WGS-84 only: with no known origin the track is placed
// at lat/lon 0/0 (documented; the file says so in <desc>).
void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin);

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

// SPDX-License-Identifier: Apache-2.0
// Writers for what a run produced: track and step CSVs, GeoJSON, GPX, and the
// JSON run summary. docs/formats.md describes every file and key.
#pragma once

#include <cstdio>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <pednav/pn_types.h>
#include <nlohmann/json.hpp>

#include "pednav_io/origin.hpp"
#include "pednav_io/position_log.hpp"
#include "pednav_io/sensor_log.hpp"

namespace pednav::io {

// Header t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz: t in s, metres
// ENU from the start point, heading in degrees clockwise from north, floor
// empty when the position has none. Throws std::runtime_error on I/O failure.
void write_track_csv(const std::string& path, const std::vector<pn_position_t>& positions);

// Header index,t_start,t_end,dx,dy,dz,length_m,heading_change_deg,class,cov_xx,cov_xy,cov_yy,cov_zz.
void write_steps_csv(const std::string& path, const std::vector<pn_stride_t>& strides);

namespace detail {
class OutFile;
}

// A CSV written a row at a time, as a run makes its outputs: the same bytes as
// the write_* function of the whole vector. The constructor opens the file and
// writes the header; every call throws std::runtime_error on I/O failure.
class RowWriter {
public:
    explicit RowWriter(const std::string& path);
    virtual ~RowWriter();
    RowWriter(const RowWriter&) = delete;
    RowWriter& operator=(const RowWriter&) = delete;
    // The rows so far go to the file: they outlive a crash of the process.
    void flush();
    void close();

protected:
    detail::OutFile& out();

private:
    std::unique_ptr<detail::OutFile> out_;
};

class TrackCsvWriter : public RowWriter {  // write_track_csv
public:
    explicit TrackCsvWriter(const std::string& path);
    void add(const pn_position_t& position);
};

class StepsCsvWriter : public RowWriter {  // write_steps_csv
public:
    explicit StepsCsvWriter(const std::string& path);
    void add(const pn_stride_t& stride);
};

// Header t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m: the
// track in WGS-84 through `origin` (the engine's: the same exact conversion as
// pn_engine_geo_from_enu), source = inertial, fused, gnss or map (the mode of
// the position filter), h_sigma_m = sqrt(cov_xx + cov_yy). Throws
// std::runtime_error when the origin is not known or on I/O failure.
void write_geo_track_csv(const std::string& path, const std::vector<pn_position_t>& positions,
                         const Origin& origin);
void write_geo_track_csv(const std::string& path, const PositionLog& positions, const Origin& origin);

class GeoTrackCsvWriter : public RowWriter {  // write_geo_track_csv
public:
    GeoTrackCsvWriter(const std::string& path, const Origin& origin);
    void add(const pn_position_t& position);

private:
    static void check_origin(const std::string& path, const Origin& origin);
    Origin origin_;
};

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
// The same from positions kept in a PositionLog, read in one pass (the
// document holds the positions thinned to 0.1 s, the steps and the changes).
void write_geojson(const std::string& path, const PositionLog& positions, const std::vector<pn_stride_t>& strides,
                   const Origin& origin, const GeoJsonExtras& extras = {});

// GPX 1.1 track, each point with its source as <type> and its floor in
// <extensions>. GPX is WGS-84 only: with no known origin the track is placed
// at lat/lon 0/0 (documented; the file says so in <desc>).
void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin);
void write_gpx(const std::string& path, const PositionLog& positions, const Origin& origin);

// "inertial", "fused", "gnss", "map" (PN_POSITION_SOURCE_*), "unknown" otherwise.
const char* position_source_name(int32_t source);

// Horizontal length of the track in metres: the sum of the east-north steps
// between consecutive positions (the summary's "distance_m").
double track_length_m(const std::vector<pn_position_t>& positions);

// What the run summary says of a run's outputs, added up as they come.
struct RunTotals {
    size_t positions = 0;
    double distance_m = 0.0;  // track_length_m of the positions
    std::set<int> floors;     // of the positions that have one
    pn_position_t first{}, last{};
    size_t strides = 0;
    double stride_length_sum_m = 0.0;
    void add(const pn_position_t& position);
    void add(const pn_stride_t& stride);
};

// The JSON run summary (keys in docs/formats.md): the input as detected, the
// pipeline from `describe_json` (pn_engine_describe), counts, distance, duration,
// warnings.
nlohmann::json run_summary_json(const SensorLog& input, const std::string& describe_json,
                                const std::vector<pn_position_t>& positions,
                                const std::vector<pn_stride_t>& strides,
                                const std::vector<std::string>& warnings);
nlohmann::json run_summary_json(const SensorLog& input, const std::string& describe_json, const RunTotals& totals,
                                const std::vector<std::string>& warnings);

// Input part of the summary and of `pednav inspect --json`.
nlohmann::json sensor_log_json(const SensorLog& log);

}  // namespace pednav::io

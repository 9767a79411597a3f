// SPDX-License-Identifier: Apache-2.0
// Track, geo-track and step CSVs, a row at a time or from whole vectors.
#include <cstdio>
#include <stdexcept>

#include "pednav_io/writers.hpp"
#include "writer_fields.hpp"

namespace pednav::io {

using detail::class_name;
using detail::h_sigma_m;
using detail::has_floor;
using detail::heading_deg;
using detail::kRadToDeg;

namespace {

std::string floor_text(const pn_position_t& p) {
    char floor[16] = "";
    if (has_floor(p)) std::snprintf(floor, sizeof floor, "%d", p.floor);
    return floor;
}

}  // namespace

RowWriter::RowWriter(const std::string& path) : out_(std::make_unique<detail::OutFile>(path)) {}
RowWriter::~RowWriter() = default;
void RowWriter::flush() { out_->flush(); }
void RowWriter::close() { out_->close(); }
std::FILE* RowWriter::file() { return out_->get(); }

TrackCsvWriter::TrackCsvWriter(const std::string& path) : RowWriter(path) {
    std::fprintf(file(), "t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz\n");
}

void TrackCsvWriter::add(const pn_position_t& p) {
    std::fprintf(file(), "%.9f,%.6f,%.6f,%.6f,%.4f,%s,%.9g,%.9g,%.9g,%.9g\n",
                 static_cast<double>(p.header.t_ns) * 1e-9, p.pos_enu_m[0], p.pos_enu_m[1], p.pos_enu_m[2],
                 heading_deg(p.heading_rad), floor_text(p).c_str(), p.cov_enu_m2[0], p.cov_enu_m2[1],
                 p.cov_enu_m2[4], p.cov_enu_m2[8]);
}

GeoTrackCsvWriter::GeoTrackCsvWriter(const std::string& path, const Origin& origin)
    : RowWriter((check_origin(path, origin), path)), origin_(origin) {
    std::fprintf(file(), "t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m\n");
}

void GeoTrackCsvWriter::check_origin(const std::string& path, const Origin& origin) {
    if (!origin.known)
        throw std::runtime_error(path +
                                 ": latitude and longitude need a geodetic origin (--origin, the config's, "
                                 "a map's or a GNSS fix's); none is known");
}

void GeoTrackCsvWriter::add(const pn_position_t& p) {
    double lat = 0, lon = 0, h = 0;
    geodesy::enu_to_geodetic(origin_, p.pos_enu_m, &lat, &lon, &h);
    std::fprintf(file(), "%.9f,%.10f,%.10f,%.4f,%.4f,%s,%s,%.4g\n", static_cast<double>(p.header.t_ns) * 1e-9,
                 lat, lon, h, heading_deg(p.heading_rad), floor_text(p).c_str(),
                 position_source_name(p.source), h_sigma_m(p));
}

StepsCsvWriter::StepsCsvWriter(const std::string& path) : RowWriter(path) {
    std::fprintf(
        file(),
        "index,t_start,t_end,dx,dy,dz,length_m,heading_change_deg,class,cov_xx,cov_xy,cov_yy,cov_zz\n");
}

void StepsCsvWriter::add(const pn_stride_t& s) {
    std::fprintf(file(), "%d,%.9f,%.9f,%.6f,%.6f,%.6f,%.6f,%.4f,%s,%.9g,%.9g,%.9g,%.9g\n", s.index,
                 static_cast<double>(s.t_start_ns) * 1e-9, static_cast<double>(s.header.t_ns) * 1e-9,
                 s.displacement_enu_m[0], s.displacement_enu_m[1], s.displacement_enu_m[2], s.length_m,
                 s.heading_change_rad * kRadToDeg, class_name(s.stride_class), s.cov_displacement_m2[0],
                 s.cov_displacement_m2[1], s.cov_displacement_m2[4], s.cov_displacement_m2[8]);
}

void write_track_csv(const std::string& path, const std::vector<pn_position_t>& positions) {
    TrackCsvWriter out(path);
    for (const auto& p : positions) out.add(p);
    out.close();
}

void write_geo_track_csv(const std::string& path, const std::vector<pn_position_t>& positions,
                         const Origin& origin) {
    GeoTrackCsvWriter out(path, origin);
    for (const auto& p : positions) out.add(p);
    out.close();
}

void write_steps_csv(const std::string& path, const std::vector<pn_stride_t>& strides) {
    StepsCsvWriter out(path);
    for (const auto& s : strides) out.add(s);
    out.close();
}

}  // namespace pednav::io

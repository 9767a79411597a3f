// SPDX-License-Identifier: Apache-2.0
// Track, geo-track and step CSVs, a row at a time or from whole vectors.
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

// The floor column: the index, or nothing when the position has none.
void put_floor(detail::OutFile& out, const pn_position_t& p) {
    if (has_floor(p)) out.integer(p.floor);
}

// Seconds with nanosecond digits ("%.9f" of the time).
void put_time(detail::OutFile& out, int64_t t_ns) { out.fixed(static_cast<double>(t_ns) * 1e-9, 9); }

// ",%.6f,%.6f,%.6f" of a vector in metres.
void put_vector_m(detail::OutFile& out, const double v[3]) {
    for (int i = 0; i < 3; ++i) {
        out.put(',');
        out.fixed(v[i], 6);
    }
}

// ",%.9g,%.9g,%.9g,%.9g" of a row-major 3 x 3 covariance's xx, xy, yy and zz.
void put_covariance(detail::OutFile& out, const double c[9]) {
    for (int i : {0, 1, 4, 8}) {
        out.put(',');
        out.general(c[i], 9);
    }
}

}  // namespace

RowWriter::RowWriter(const std::string& path) : out_(std::make_unique<detail::OutFile>(path)) {}
RowWriter::~RowWriter() = default;
void RowWriter::flush() { out_->flush(); }
void RowWriter::close() { out_->close(); }
detail::OutFile& RowWriter::out() { return *out_; }

TrackCsvWriter::TrackCsvWriter(const std::string& path) : RowWriter(path) {
    out().text("t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz\n");
}

void TrackCsvWriter::add(const pn_position_t& p) {
    // "%.9f,%.6f,%.6f,%.6f,%.4f,%d,%.9g,%.9g,%.9g,%.9g\n", the floor empty when there is none.
    detail::OutFile& o = out();
    put_time(o, p.header.t_ns);
    put_vector_m(o, p.pos_enu_m);
    o.put(',');
    o.fixed(heading_deg(p.heading_rad), 4);
    o.put(',');
    put_floor(o, p);
    put_covariance(o, p.cov_enu_m2);
    o.put('\n');
}

GeoTrackCsvWriter::GeoTrackCsvWriter(const std::string& path, const Origin& origin)
    : RowWriter((check_origin(path, origin), path)), origin_(origin) {
    out().text("t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m\n");
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
    // "%.9f,%.10f,%.10f,%.4f,%.4f,%d,%s,%.4g\n", the floor empty when there is none.
    detail::OutFile& o = out();
    put_time(o, p.header.t_ns);
    o.put(',');
    o.fixed(lat, 10);
    o.put(',');
    o.fixed(lon, 10);
    o.put(',');
    o.fixed(h, 4);
    o.put(',');
    o.fixed(heading_deg(p.heading_rad), 4);
    o.put(',');
    put_floor(o, p);
    o.put(',');
    o.text(position_source_name(p.source));
    o.put(',');
    o.general(h_sigma_m(p), 4);
    o.put('\n');
}

StepsCsvWriter::StepsCsvWriter(const std::string& path) : RowWriter(path) {
    out().text(
        "index,t_start,t_end,dx,dy,dz,length_m,heading_change_deg,class,cov_xx,cov_xy,cov_yy,cov_zz\n");
}

void StepsCsvWriter::add(const pn_stride_t& s) {
    // "%d,%.9f,%.9f,%.6f,%.6f,%.6f,%.6f,%.4f,%s,%.9g,%.9g,%.9g,%.9g\n"
    detail::OutFile& o = out();
    o.integer(s.index);
    o.put(',');
    put_time(o, s.t_start_ns);
    o.put(',');
    put_time(o, s.header.t_ns);
    put_vector_m(o, s.displacement_enu_m);
    o.put(',');
    o.fixed(s.length_m, 6);
    o.put(',');
    o.fixed(s.heading_change_rad * kRadToDeg, 4);
    o.put(',');
    o.text(class_name(s.stride_class));
    put_covariance(o, s.cov_displacement_m2);
    o.put('\n');
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

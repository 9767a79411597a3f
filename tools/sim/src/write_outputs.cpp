// SPDX-License-Identifier: Apache-2.0
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <pednav_sim/building_map.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::sim {

namespace {

std::FILE* open_or_throw(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) throw std::runtime_error("sim: cannot write " + path + ": " + std::strerror(errno));
    return f;
}

void make_dirs(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("sim: cannot create " + dir + ": " + ec.message());
}

}  // namespace

void write_outputs(const SimOutput& out, const Route& route, const std::string& out_dir) {
    make_dirs(out_dir);
    // Magnetometer and barometer samples share the IMU's sample times; a row
    // without one leaves its cells empty (multi-rate canonical CSV).
    const bool mag = !out.mag.empty();
    const bool baro = !out.baro.empty();
    size_t im = 0, ib = 0;

    std::FILE* f = open_or_throw(out_dir + "/input.csv");
    std::fprintf(f, "# pednav simulated walk: route %s, mount %s, %.6g Hz\n", route.name.c_str(),
                 out.mount.c_str(), out.rate_hz);
    std::fprintf(f, "t,ax,ay,az,gx,gy,gz%s%s\n", mag ? ",mx,my,mz" : "", baro ? ",p" : "");
    for (size_t k = 0; k < out.imu.size(); ++k) {
        const pn_imu_t& m = out.imu[k];
        std::fprintf(f, "%.9f,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g", static_cast<double>(m.header.t_ns) * 1e-9,
                     m.accel_mps2[0], m.accel_mps2[1], m.accel_mps2[2], m.gyro_radps[0], m.gyro_radps[1],
                     m.gyro_radps[2]);
        if (mag) {
            if (im < out.mag.size() && out.mag[im].header.t_ns == m.header.t_ns) {
                std::fprintf(f, ",%.8g,%.8g,%.8g", out.mag[im].mag_ut[0], out.mag[im].mag_ut[1],
                             out.mag[im].mag_ut[2]);
                ++im;
            } else {
                std::fputs(",,,", f);
            }
        }
        if (baro) {
            if (ib < out.baro.size() && out.baro[ib].header.t_ns == m.header.t_ns) {
                std::fprintf(f, ",%.10g", out.baro[ib].pressure_pa);
                ++ib;
            } else {
                std::fputc(',', f);
            }
        }
        std::fputc('\n', f);
    }
    std::fclose(f);

    // Truth: one row per IMU sample; step = 1 on the sample at or just after each step event.
    f = open_or_throw(out_dir + "/truth.csv");
    std::fprintf(f,
                 "# pednav simulated truth: sensor position (ENU m), attitude q_enu_from_body (sensor axes), "
                 "velocity, stance, step event, floor, walking heading (deg clockwise from north)\n");
    std::fprintf(f, "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,stance,step,floor,heading_deg\n");
    size_t next_step = 0;
    for (const TruthSample& s : out.truth) {
        int step = 0;
        while (next_step < out.step_times_s.size() && out.step_times_s[next_step] <= s.t_s + 1e-9) {
            step = 1;
            ++next_step;
        }
        std::fprintf(f, "%.9f,%.6f,%.6f,%.6f,%.9f,%.9f,%.9f,%.9f,%.6f,%.6f,%.6f,%d,%d,%d,%.4f\n", s.t_s,
                     s.pos_enu_m[0], s.pos_enu_m[1], s.pos_enu_m[2], s.q_enu_from_body[0],
                     s.q_enu_from_body[1], s.q_enu_from_body[2], s.q_enu_from_body[3], s.vel_enu_mps[0],
                     s.vel_enu_mps[1], s.vel_enu_mps[2], s.stance, step, s.floor, s.heading_deg);
    }
    std::fclose(f);

    // GNSS: the GNSS CSV that `pednav run --gnss` reads (docs/formats.md): t on the
    // input's clock, ellipsoidal height, 1-sigma accuracies, speed and course
    // over ground (the vertical velocity is not in the format).
    f = open_or_throw(out_dir + "/gnss.csv");
    std::fprintf(f, "t,lat,lon,alt,hacc,vacc,speed,course,sats,fix\n");
    for (const pn_gnss_t& g : out.gnss) {
        const double speed = std::hypot(g.vel_enu_mps[0], g.vel_enu_mps[1]);
        double course = std::atan2(g.vel_enu_mps[0], g.vel_enu_mps[1]) * 180.0 / M_PI;
        if (course < 0.0) course += 360.0;
        std::fprintf(f, "%.9f,%.9f,%.9f,%.3f,%.3f,%.3f,%.3f,%.2f,%d,%d\n",
                     static_cast<double>(g.header.t_ns) * 1e-9, g.lat_deg, g.lon_deg, g.height_m, g.h_accuracy_m,
                     g.v_accuracy_m, speed, course, g.satellites, g.fix_type);
    }
    std::fclose(f);

    std::ofstream(out_dir + "/building.geojson") << building_map(route).dump(1) << '\n';
    std::ofstream(out_dir + "/route.json") << route_to_json(route).dump(2) << '\n';
}

}  // namespace pednav::sim

// SPDX-License-Identifier: Apache-2.0
#include <pednav_sim/simulate.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include <pednav_geodesy/atmosphere.hpp>
#include <pednav_geodesy/enu.hpp>
#include <pednav_io/sensor_log.hpp>

#include "gait_plan.hpp"
#include "rng.hpp"
#include "trajectory.hpp"
#include "truth_floor.hpp"

namespace pednav::sim {

namespace {

using detail::KinState;
using detail::Rng;

template <typename T>
T make_record(pn_record_type_t type, int64_t t_ns) {
    T r{};
    r.header.struct_size = sizeof(T);
    r.header.type = type;
    r.header.t_ns = t_ns;
    return r;
}

constexpr double kDeg = M_PI / 180.0;

// One triaxial inertial sensor's errors: meas = sat((1 + s) * true + b + b_rw + noise).
struct TriaxErrors {
    Eigen::Vector3d scale = Eigen::Vector3d::Zero();
    Eigen::Vector3d bias = Eigen::Vector3d::Zero();
    Eigen::Vector3d bias_rw = Eigen::Vector3d::Zero();
    double noise_sigma = 0.0, rw_sigma = 0.0, range = INFINITY;

    TriaxErrors(bool on, Rng& rng, double scale_sigma, double bias_sigma, double rw_density,
                double noise_density, double saturation, double rate_hz) {
        if (!on) return;
        for (int i = 0; i < 3; ++i) scale[i] = scale_sigma * rng.normal();
        for (int i = 0; i < 3; ++i) bias[i] = bias_sigma * rng.normal();
        noise_sigma = noise_density * std::sqrt(rate_hz);
        rw_sigma = rw_density / std::sqrt(rate_hz);
        range = saturation;
    }
    Eigen::Vector3d apply(const Eigen::Vector3d& truth, Rng& rng) {
        if (noise_sigma == 0.0 && rw_sigma == 0.0 && std::isinf(range) && scale.isZero() && bias.isZero())
            return truth;
        Eigen::Vector3d m;
        for (int i = 0; i < 3; ++i) {
            bias_rw[i] += rw_sigma * rng.normal();
            m[i] = (1.0 + scale[i]) * truth[i] + bias[i] + bias_rw[i] + noise_sigma * rng.normal();
            m[i] = std::clamp(m[i], -range, range);
        }
        return m;
    }
};

Eigen::Vector3d earth_field_enu(const SimOptions& o) {
    const double h = o.earth_field_ut * std::cos(o.inclination_deg * kDeg);
    return {h * std::sin(o.declination_deg * kDeg), h * std::cos(o.declination_deg * kDeg),
            -o.earth_field_ut * std::sin(o.inclination_deg * kDeg)};
}

Eigen::Vector3d disturbance_enu(const Route& route, const Eigen::Vector3d& p) {
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (const MagDisturbance& d : route.mag_disturbances) {
        const double r =
            (p - Eigen::Vector3d(d.center_enu_m[0], d.center_enu_m[1], d.center_enu_m[2])).norm();
        if (r >= d.radius_m) continue;
        const double u = r / d.radius_m;
        const double w = (1.0 - u * u) * (1.0 - u * u);
        b += w * Eigen::Vector3d(d.field_ut[0], d.field_ut[1], d.field_ut[2]);
    }
    return b;
}

}  // namespace

SimOutput simulate(const Route& route, const SimOptions& options) {
    if (!(options.rate_hz >= 10.0 && options.rate_hz <= 2000.0))
        throw std::runtime_error("sim: rate_hz must be within 10..2000");
    const detail::GaitPlan plan = detail::plan_gait(route);
    std::unique_ptr<detail::Trajectory> traj =
        detail::make_trajectory(options.mount, plan, options.heel_strike_g * options.gravity_mps2, options.surge_m);
    if (!(options.time_jitter_s >= 0.0 && options.time_jitter_s < 0.5 / options.rate_hz))
        throw std::runtime_error("sim: time_jitter_s must be within 0 and half the sample interval");
    Rng rng_jitter(options.seed, 6);

    SimOutput out;
    out.rate_hz = options.rate_hz;
    out.mount = options.mount;
    out.distance_m = plan.distance_m;
    out.step_times_s = traj->step_times_s();

    const Eigen::Matrix3d R_body_sensor =
        (Eigen::AngleAxisd(options.mounting_rpy_deg[2] * kDeg, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(options.mounting_rpy_deg[1] * kDeg, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(options.mounting_rpy_deg[0] * kDeg, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    const bool err = options.sensor_errors;
    const ImuErrorModel& im = options.imu;
    Rng rng_setup(options.seed, 0), rng_acc(options.seed, 1), rng_gyr(options.seed, 2),
        rng_mag(options.seed, 3), rng_baro(options.seed, 4), rng_gnss(options.seed, 5);
    TriaxErrors acc_err(err, rng_setup, im.accel_scale, im.accel_bias_mps2, im.accel_bias_rw_mps2_per_rts,
                        im.accel_noise_mps2_per_rthz, im.accel_range_mps2, options.rate_hz);
    TriaxErrors gyr_err(err, rng_setup, im.gyro_scale, im.gyro_bias_radps, im.gyro_bias_rw_radps_per_rts,
                        im.gyro_noise_radps_per_rthz, im.gyro_range_radps, options.rate_hz);
    Eigen::Vector3d mag_bias = Eigen::Vector3d::Zero();
    if (err)
        for (int i = 0; i < 3; ++i) mag_bias[i] = options.mag_bias_ut * rng_setup.normal();
    const double baro_drift = err ? options.baro_drift_pa_per_s * rng_setup.normal() : 0.0;
    const Eigen::Vector3d b_earth = earth_field_enu(options);
    const Eigen::Vector3d g_enu(0.0, 0.0, -options.gravity_mps2);
    const geodesy::GeodeticPoint origin{route.origin_lat_deg, route.origin_lon_deg, route.origin_height_m};

    const size_t n = static_cast<size_t>(std::floor(plan.end_s * options.rate_hz)) + 1;
    out.imu.reserve(n);
    out.truth.reserve(n);
    // Magnetometer and barometer on a subset of the IMU samples (same clock).
    auto every = [&](double hz) {
        return hz > 0.0 ? std::max<size_t>(1, static_cast<size_t>(std::llround(options.rate_hz / hz)))
                        : size_t{1};
    };
    const size_t mag_every = every(options.mag_rate_hz), baro_every = every(options.baro_rate_hz);
    if (options.with_mag) out.mag.reserve(n / mag_every + 1);
    if (options.with_baro) out.baro.reserve(n / baro_every + 1);

    // GNSS: one fix every 1/gnss_rate s where the route has reception, error = Gauss-Markov + white,
    // scaled by the segment's quality, plus the multipath jumps.
    const double gnss_period_s = 1.0 / options.gnss_rate_hz;
    double next_fix_s = 0.0;
    Eigen::Vector3d gm = Eigen::Vector3d::Zero();
    const double gm_tau_s = 60.0;
    if (err)
        gm = Eigen::Vector3d(options.gnss_sigma_h_m * rng_gnss.normal(),
                             options.gnss_sigma_h_m * rng_gnss.normal(),
                             options.gnss_sigma_v_m * rng_gnss.normal());
    double last_gm_s = 0.0;

    detail::TruthFloor truth_floor(route.floor_height_m);
    for (size_t k = 0; k < n; ++k) {
        int64_t t_ns = static_cast<int64_t>(std::llround(static_cast<double>(k) * 1e9 / options.rate_hz));
        if (options.time_jitter_s > 0.0 && k > 0)
            t_ns += static_cast<int64_t>(std::llround((2.0 * rng_jitter.uniform() - 1.0) * options.time_jitter_s * 1e9));
        const double t = static_cast<double>(t_ns) * 1e-9;
        const KinState s = traj->at(t);
        const Eigen::Matrix3d R_enu_sensor = s.R_enu_body * R_body_sensor;
        const Eigen::Vector3d f_sensor = R_enu_sensor.transpose() * (s.a_enu_mps2 - g_enu);
        const Eigen::Vector3d w_sensor = R_body_sensor.transpose() * s.w_body_radps;

        auto imu = make_record<pn_imu_t>(PN_REC_IMU, t_ns);
        const Eigen::Vector3d f_meas = acc_err.apply(f_sensor, rng_acc);
        const Eigen::Vector3d w_meas = gyr_err.apply(w_sensor, rng_gyr);
        for (int i = 0; i < 3; ++i) {
            imu.accel_mps2[i] = f_meas[i];
            imu.gyro_radps[i] = w_meas[i];
        }
        out.imu.push_back(imu);

        TruthSample ts{};
        ts.t_s = t;
        const Eigen::Quaterniond q(R_enu_sensor);
        const double qs = q.w() < 0.0 ? -1.0 : 1.0;  // w >= 0 for a unique representation
        ts.q_enu_from_body[0] = qs * q.w();
        ts.q_enu_from_body[1] = qs * q.x();
        ts.q_enu_from_body[2] = qs * q.y();
        ts.q_enu_from_body[3] = qs * q.z();
        for (int i = 0; i < 3; ++i) {
            ts.pos_enu_m[i] = s.p_enu_m[i];
            ts.vel_enu_mps[i] = s.v_enu_mps[i];
        }
        ts.stance = s.stance;
        ts.floor = truth_floor.at(s.p_enu_m.z() - traj->height_above_floor_m());
        double heading = 90.0 - s.yaw_enu_rad / kDeg;
        heading = std::fmod(heading, 360.0);
        if (heading < 0.0) heading += 360.0;
        ts.heading_deg = heading;
        out.truth.push_back(ts);

        if (options.with_mag && k % mag_every == 0) {
            auto m = make_record<pn_mag_t>(PN_REC_MAG, t_ns);
            const Eigen::Vector3d b_enu = b_earth + disturbance_enu(route, s.p_enu_m);
            Eigen::Vector3d b = R_enu_sensor.transpose() * b_enu;
            if (err)
                b += mag_bias + options.mag_noise_ut *
                                    Eigen::Vector3d(rng_mag.normal(), rng_mag.normal(), rng_mag.normal());
            for (int i = 0; i < 3; ++i) m.mag_ut[i] = b[i];
            out.mag.push_back(m);
        }
        if (options.with_baro && k % baro_every == 0) {
            auto b = make_record<pn_baro_t>(PN_REC_BARO, t_ns);
            b.pressure_pa = geodesy::standard_pressure_pa(route.origin_height_m + s.p_enu_m.z()) + baro_drift * t;
            if (err) b.pressure_pa += options.baro_noise_pa * rng_baro.normal();
            b.temperature_c = 20.0;
            out.baro.push_back(b);
        }
        // The segment's reception: the error sigmas and the reported accuracy
        // scale together (a scale of 1 leaves every number as it was).
        const GnssQuality& quality = segment_gnss(route, static_cast<size_t>(s.segment));
        if (options.with_gnss && t + 1e-12 >= next_fix_s) {
            next_fix_s += gnss_period_s;
            if (err) {
                // Gauss-Markov update since the last fix (exact discretisation).
                const double phi = std::exp(-(t - last_gm_s) / gm_tau_s);
                const double q_gm = std::sqrt(1.0 - phi * phi);
                gm = phi * gm + q_gm * Eigen::Vector3d(options.gnss_sigma_h_m * rng_gnss.normal(),
                                                       options.gnss_sigma_h_m * rng_gnss.normal(),
                                                       options.gnss_sigma_v_m * rng_gnss.normal());
                last_gm_s = t;
            }
            if (quality.fixes) {
                const double scale = quality.error_scale;
                auto g = make_record<pn_gnss_t>(PN_REC_GNSS, t_ns);
                Eigen::Vector3d p = s.p_enu_m;
                if (err)
                    p += scale * gm + scale * options.gnss_white_h_m *
                                          Eigen::Vector3d(rng_gnss.normal(), rng_gnss.normal(), 0.0);
                for (const std::vector<GnssJump>* jumps : {&route.gnss_jumps, &options.gnss_jumps})
                    for (const GnssJump& j : *jumps)
                        if (t + 1e-9 >= j.t_s && t + 1e-9 < j.t_s + j.duration_s)
                            p += Eigen::Vector3d(j.offset_enu_m[0], j.offset_enu_m[1], j.offset_enu_m[2]);
                const double pe[3] = {p.x(), p.y(), p.z()};
                geodesy::enu_to_geodetic(origin, pe, &g.lat_deg, &g.lon_deg, &g.height_m);
                g.h_accuracy_m = err ? scale * std::sqrt(2.0 * (options.gnss_sigma_h_m * options.gnss_sigma_h_m +
                                                                options.gnss_white_h_m * options.gnss_white_h_m))
                                     : 0.01;
                g.v_accuracy_m = err ? scale * options.gnss_sigma_v_m : 0.01;
                // Receiver velocity: the walking velocity over the last period (the body's, not the swinging
                // foot's).
                const size_t back =
                    std::min(k, static_cast<size_t>(std::llround(gnss_period_s * options.rate_hz)));
                const TruthSample& old = out.truth[k - back];
                const double dt = t - old.t_s;
                for (int i = 0; i < 3; ++i) {
                    g.vel_enu_mps[i] = dt > 0.0 ? (ts.pos_enu_m[i] - old.pos_enu_m[i]) / dt : 0.0;
                    if (err) g.vel_enu_mps[i] += scale * options.gnss_vel_noise_mps * rng_gnss.normal();
                }
                g.header.flags = PN_GNSS_FLAG_HAS_VELOCITY;
                g.satellites = quality.satellites;
                g.fix_type = PN_GNSS_FIX_AUTONOMOUS;
                out.gnss.push_back(g);
            }
        }
    }
    return out;
}

std::vector<const pn_record_header_t*> SimOutput::records() const {
    return io::merged_records(imu, mag, baro, gnss);
}

}  // namespace pednav::sim

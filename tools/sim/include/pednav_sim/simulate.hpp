// SPDX-License-Identifier: Apache-2.0
// Walk simulator: exact kinematics of a foot-, chest-, waist-mounted or handheld IMU
// along a route, the sensor records it would produce, and the exact truth.
//
// Specific force and angular rate are derived analytically from the same
// trajectory that is written as truth (f = R^T (a - g), omega from the attitude
// derivative), so an exact strapdown integration of the error-free IMU
// reproduces the truth. See docs/simulator.md.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <pednav/pn_types.h>
#include <pednav_sim/route.hpp>

namespace pednav::sim {

// Consumer-grade MEMS IMU errors (defaults: a typical 2020s phone/wearable IMU).
// Noise densities give the per-sample standard deviation density * sqrt(rate_hz).
struct ImuErrorModel {
    double accel_noise_mps2_per_rthz = 1.8e-3;   // white noise density
    double accel_bias_mps2 = 0.04;               // 1-sigma constant bias per axis, drawn per seed
    double accel_bias_rw_mps2_per_rts = 1.0e-4;  // bias random walk
    double accel_scale = 3.0e-3;                 // 1-sigma scale factor error per axis
    double accel_range_mps2 = 16.0 * 9.80665;    // saturation
    double gyro_noise_radps_per_rthz = 1.2e-4;   // white noise density (0.007 deg/s/sqrt(Hz))
    double gyro_bias_radps = 3.5e-3;             // 1-sigma constant bias per axis (0.2 deg/s)
    double gyro_bias_rw_radps_per_rts = 3.0e-5;  // bias random walk
    double gyro_scale = 3.0e-3;                  // 1-sigma scale factor error per axis
    double gyro_range_radps = 34.9;              // saturation (2000 deg/s)
};

struct SimOptions {
    std::string mount = "foot";  // "foot", "chest", "handheld" or "waist"
    double rate_hz = 200.0;      // IMU rate; magnetometer and barometer share it
    uint64_t seed = 1;           // same seed, same output, bit for bit
    bool sensor_errors = true;   // false: every sensor is exact (noise, biases, scale, saturation, drift off)
    // Sensor axes in the foot/body frame: R_body_sensor = Rz(yaw) Ry(pitch) Rx(roll), degrees.
    double mounting_rpy_deg[3] = {0.0, 0.0, 0.0};
    bool with_mag = true;
    bool with_baro = true;
    bool with_gnss = true;  // fixes where the route has GNSS (outdoor segments, or their `gnss` quality)
    // Magnetometer and barometer rates: 0 = with every IMU sample, otherwise on every
    // round(rate_hz / x)-th IMU sample.
    double mag_rate_hz = 0.0;
    double baro_rate_hz = 0.0;
    double gravity_mps2 = 9.80665;  // |g|, constant over the walk
    // Foot: peak vertical acceleration of a landing transient on level floors, in g (0: none).
    double heel_strike_g = 0.0;
    // Chest, handheld, waist: the trunk's forward oscillation at the step
    // frequency (fastest at each landing), m; NaN = the mount's own (handheld
    // 0.02, chest and waist 0).
    double surge_m = NAN;
    // Irregular sample times (Android sensors): each IMU sample is moved by a
    // uniform draw within +-time_jitter_s (own random stream; order kept); 0 = exact.
    double time_jitter_s = 0.0;
    double earth_field_ut = 48.0;   // total intensity of the Earth field
    double inclination_deg = 64.0;  // dip, positive: field points down
    double declination_deg = 1.5;   // magnetic north east of true north
    ImuErrorModel imu;
    double mag_noise_ut = 0.3;          // white, per axis, per sample
    double mag_bias_ut = 0.5;           // 1-sigma residual hard-iron bias per axis
    double baro_noise_pa = 1.5;         // white, per sample
    double baro_drift_pa_per_s = 0.01;  // 1-sigma weather drift rate (about 1 hPa in 3 h)
    double gnss_rate_hz = 1.0;
    double gnss_sigma_h_m = 1.5;  // per horizontal axis: slow (Gauss-Markov, 60 s) part
    double gnss_white_h_m = 0.5;  // per horizontal axis: white part
    double gnss_sigma_v_m = 3.0;  // vertical
    double gnss_vel_noise_mps = 0.1;
    // Multipath jumps besides the route's own (Route::gnss_jumps).
    std::vector<GnssJump> gnss_jumps;
};

struct TruthSample {
    double t_s;
    double pos_enu_m[3];        // the sensor's position
    double q_enu_from_body[4];  // the sensor's attitude (its own axes, after the mounting rotation), w first
    double vel_enu_mps[3];
    int stance;  // foot: 1 while the instrumented foot is flat and still; chest/waist: 1 while standing
    int floor;
    double heading_deg;  // walking direction of the foot/body (before mounting), clockwise from north
};

struct SimOutput {
    std::vector<pn_imu_t> imu;
    std::vector<pn_mag_t> mag;
    std::vector<pn_baro_t> baro;
    std::vector<pn_gnss_t> gnss;
    std::vector<TruthSample> truth;    // one per IMU sample, same times
    std::vector<double> step_times_s;  // foot: the start of each stance after a stride of the instrumented
                                       // foot; chest/waist: every step
    double distance_m = 0.0;           // horizontal distance walked
    double rate_hz = 0.0;
    std::string mount;
    // Time-ordered pointers into the vectors above (equal times: IMU, MAG, BARO, GNSS).
    std::vector<const pn_record_header_t*> records() const;
};

// Throws std::runtime_error on a bad mount or rate.
SimOutput simulate(const Route& route, const SimOptions& options);

// Writes into out_dir (created if needed):
//   input.csv      canonical engine input, header t,ax,ay,az,gx,gy,gz[,mx,my,mz][,p]
//   truth.csv      t,x,y,z,qw,qx,qy,qz,vx,vy,vz,stance,step,floor,heading_deg
//   gnss.csv       t,lat,lon,alt,hacc,vacc,speed,course,sats,fix (the GNSS CSV of docs/formats.md)
//   building.geojson  the route's map, pednav.map/1 (building_map.hpp)
//   route.json     the route document
void write_outputs(const SimOutput& out, const Route& route, const std::string& out_dir);

}  // namespace pednav::sim

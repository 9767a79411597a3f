#include "record_checks.hpp"

#include <cmath>
#include <cstdio>

namespace pednav::engine {

uint32_t min_record_size(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return PN_IMU_MIN_SIZE;
        case PN_REC_MAG: return PN_MAG_MIN_SIZE;
        case PN_REC_BARO: return PN_BARO_MIN_SIZE;
        case PN_REC_GNSS: return PN_GNSS_MIN_SIZE;
        case PN_REC_GAIT_PHASE: return PN_GAIT_PHASE_MIN_SIZE;
        case PN_REC_STEP: return PN_STEP_MIN_SIZE;
        case PN_REC_ATTITUDE: return PN_ATTITUDE_MIN_SIZE;
        case PN_REC_ATTITUDE_CORRECTION: return PN_ATTITUDE_CORRECTION_MIN_SIZE;
        case PN_REC_POSITION: return PN_POSITION_MIN_SIZE;
        case PN_REC_STRIDE: return PN_STRIDE_MIN_SIZE;
        default: return 0;
    }
}

const char* record_type_name(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return "imu";
        case PN_REC_MAG: return "mag";
        case PN_REC_BARO: return "baro";
        case PN_REC_GNSS: return "gnss";
        case PN_REC_GAIT_PHASE: return "gait_phase";
        case PN_REC_STEP: return "step";
        case PN_REC_ATTITUDE: return "attitude";
        case PN_REC_ATTITUDE_CORRECTION: return "attitude_correction";
        case PN_REC_POSITION: return "position";
        case PN_REC_STRIDE: return "stride";
        default: return "unknown";
    }
}

namespace {

std::string bad(const char* field, int index, double value) {
    char buf[96];
    if (index >= 0)
        std::snprintf(buf, sizeof buf, "%s[%d] is %g", field, index, value);
    else
        std::snprintf(buf, sizeof buf, "%s is %g", field, value);
    return buf;
}

std::string finite(const char* field, const double* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return bad(field, n > 1 ? i : -1, v[i]);
    return {};
}

std::string covariance(const char* field, const double* c) {
    if (auto e = finite(field, c, 9); !e.empty()) return e;
    for (int i = 0; i < 3; ++i)
        if (c[4 * i] < 0) return bad(field, 4 * i, c[4 * i]) + " (negative variance)";
    return {};
}

std::string unit_quaternion(const char* field, const double* q) {
    if (auto e = finite(field, q, 4); !e.empty()) return e;
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (std::fabs(n - 1.0) > 1e-3) return bad(field, -1, n) + " in norm, not a unit quaternion";
    return {};
}

#define PN_CHECK(expr)                    \
    do {                                  \
        std::string e_ = (expr);          \
        if (!e_.empty()) return e_;       \
    } while (0)

}  // namespace

namespace {

inline bool all_finite(const double* v, int n) {
    bool ok = true;
    for (int i = 0; i < n; ++i) ok &= std::isfinite(v[i]);
    return ok;
}

bool cov_ok(const double* c) { return all_finite(c, 9) && c[0] >= 0 && c[4] >= 0 && c[8] >= 0; }

}  // namespace

// The common case without building any string; check_record_values explains.
bool record_values_ok(const pn_record_header_t* h) {
    switch (h->type) {
        case PN_REC_IMU: {
            auto* r = reinterpret_cast<const pn_imu_t*>(h);
            return all_finite(r->accel_mps2, 3) && all_finite(r->gyro_radps, 3);
        }
        case PN_REC_MAG: return all_finite(reinterpret_cast<const pn_mag_t*>(h)->mag_ut, 3);
        case PN_REC_BARO: {
            const double p = reinterpret_cast<const pn_baro_t*>(h)->pressure_pa;
            return std::isfinite(p) && p > 0;
        }
        case PN_REC_GAIT_PHASE: return std::isfinite(reinterpret_cast<const pn_gait_phase_t*>(h)->statistic);
        case PN_REC_STRIDE: {
            auto* r = reinterpret_cast<const pn_stride_t*>(h);
            return all_finite(r->displacement_enu_m, 3) && std::isfinite(r->length_m) &&
                   std::isfinite(r->heading_change_rad) && cov_ok(r->cov_displacement_m2);
        }
        case PN_REC_ATTITUDE: {
            auto* r = reinterpret_cast<const pn_attitude_t*>(h);
            const double* q = r->q_enu_from_body;
            const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
            return all_finite(q, 4) && std::fabs(n2 - 1.0) < 1.9e-3 && std::isfinite(r->heading_rad) &&
                   all_finite(r->gyro_bias_radps, 3) && cov_ok(r->cov_attitude_rad2);
        }
        case PN_REC_ATTITUDE_CORRECTION: {
            auto* r = reinterpret_cast<const pn_attitude_correction_t*>(h);
            return all_finite(r->rotation_enu_rad, 3) && all_finite(r->gyro_bias_delta_radps, 3);
        }
        case PN_REC_POSITION: {
            auto* r = reinterpret_cast<const pn_position_t*>(h);
            return all_finite(r->pos_enu_m, 3) &&
                   (!(r->header.flags & PN_POSITION_FLAG_HAS_VELOCITY) || all_finite(r->vel_enu_mps, 3)) &&
                   std::isfinite(r->heading_rad) && cov_ok(r->cov_enu_m2);
        }
        default: return check_record_values(h).empty();
    }
}

std::string check_record_values(const pn_record_header_t* h) {
    switch (h->type) {
        case PN_REC_IMU: {
            auto* r = reinterpret_cast<const pn_imu_t*>(h);
            PN_CHECK(finite("accel_mps2", r->accel_mps2, 3));
            PN_CHECK(finite("gyro_radps", r->gyro_radps, 3));
            return {};
        }
        case PN_REC_MAG: return finite("mag_ut", reinterpret_cast<const pn_mag_t*>(h)->mag_ut, 3);
        case PN_REC_BARO: {
            auto* r = reinterpret_cast<const pn_baro_t*>(h);
            PN_CHECK(finite("pressure_pa", &r->pressure_pa, 1));
            if (r->pressure_pa <= 0) return bad("pressure_pa", -1, r->pressure_pa) + " (not positive)";
            return {};
        }
        case PN_REC_GNSS: {
            auto* r = reinterpret_cast<const pn_gnss_t*>(h);
            PN_CHECK(finite("lat_deg", &r->lat_deg, 1));
            PN_CHECK(finite("lon_deg", &r->lon_deg, 1));
            if (std::fabs(r->lat_deg) > 90) return bad("lat_deg", -1, r->lat_deg);
            if (std::fabs(r->lon_deg) > 180) return bad("lon_deg", -1, r->lon_deg);
            PN_CHECK(finite("h_accuracy_m", &r->h_accuracy_m, 1));
            return {};
        }
        case PN_REC_GAIT_PHASE:
            return finite("statistic", &reinterpret_cast<const pn_gait_phase_t*>(h)->statistic, 1);
        case PN_REC_STEP: {
            auto* r = reinterpret_cast<const pn_step_t*>(h);
            PN_CHECK(finite("accel_peak_to_peak_mps2", &r->accel_peak_to_peak_mps2, 1));
            return finite("frequency_hz", &r->frequency_hz, 1);
        }
        case PN_REC_ATTITUDE: {
            auto* r = reinterpret_cast<const pn_attitude_t*>(h);
            PN_CHECK(unit_quaternion("q_enu_from_body", r->q_enu_from_body));
            PN_CHECK(finite("heading_rad", &r->heading_rad, 1));
            PN_CHECK(finite("gyro_bias_radps", r->gyro_bias_radps, 3));
            return covariance("cov_attitude_rad2", r->cov_attitude_rad2);
        }
        case PN_REC_ATTITUDE_CORRECTION: {
            auto* r = reinterpret_cast<const pn_attitude_correction_t*>(h);
            PN_CHECK(finite("rotation_enu_rad", r->rotation_enu_rad, 3));
            return finite("gyro_bias_delta_radps", r->gyro_bias_delta_radps, 3);
        }
        case PN_REC_POSITION: {
            auto* r = reinterpret_cast<const pn_position_t*>(h);
            PN_CHECK(finite("pos_enu_m", r->pos_enu_m, 3));
            if (r->header.flags & PN_POSITION_FLAG_HAS_VELOCITY) PN_CHECK(finite("vel_enu_mps", r->vel_enu_mps, 3));
            PN_CHECK(finite("heading_rad", &r->heading_rad, 1));
            return covariance("cov_enu_m2", r->cov_enu_m2);
        }
        case PN_REC_STRIDE: {
            auto* r = reinterpret_cast<const pn_stride_t*>(h);
            PN_CHECK(finite("displacement_enu_m", r->displacement_enu_m, 3));
            PN_CHECK(finite("length_m", &r->length_m, 1));
            PN_CHECK(finite("heading_change_rad", &r->heading_change_rad, 1));
            return covariance("cov_displacement_m2", r->cov_displacement_m2);
        }
        default: return {};
    }
}

}  // namespace pednav::engine

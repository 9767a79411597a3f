// SPDX-License-Identifier: Apache-2.0
#include "pednav_navmath/magnetic_field_gate.hpp"

#include <algorithm>
#include <stdexcept>

namespace pednav::navmath {

namespace {

constexpr size_t kLearnCapacity = 4096;  // readings kept for the medians (a 100 Hz magnetometer: 41 s)
constexpr double kEarthMinUt = 20.0, kEarthMaxUt = 70.0;

double median(std::vector<double>& v) {
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    return v[mid];
}

}  // namespace

MagneticFieldGate::MagneticFieldGate(const MagneticFieldGateConfig& c) : c_(c) {
    if (!(c.field_ut >= 0)) throw std::invalid_argument("mag field_ut must be 0 (learn) or positive");
    if (!std::isnan(c.dip_deg) && !(std::fabs(c.dip_deg) <= 90))
        throw std::invalid_argument("mag dip_deg must be within [-90, 90] or learnt");
    if (!(c.field_tolerance_ut > 0)) throw std::invalid_argument("mag field_tolerance_ut must be positive");
    if (!(c.dip_tolerance_deg > 0)) throw std::invalid_argument("mag dip_tolerance_deg must be positive");
    if (!(c.learn_s > 0)) throw std::invalid_argument("mag learn_s must be positive");
    learn_field_.reserve(kLearnCapacity);
    learn_dip_.reserve(kLearnCapacity);
    reset();
}

void MagneticFieldGate::reset() {
    field_ut_ = c_.field_ut > 0 ? c_.field_ut : std::nan("");
    dip_deg_ = c_.dip_deg;
    learning_ = !learnt();
    set_dip_bounds();
    started_ = false;
    learn_field_.clear();
    learn_dip_.clear();
}

double MagneticFieldGate::dip_of_deg(const Vec3& m, const Vec3& up) {
    const double n = m.norm();
    if (!(n > 0)) return 0.0;
    const double s = std::clamp(-m.dot(up) / (n * up.norm()), -1.0, 1.0);
    return std::asin(s) * 180.0 / M_PI;
}

void MagneticFieldGate::finish_learning() {
    learning_ = false;
    if (learn_field_.empty()) {  // nothing plausible seen: keep learning from the next readings
        learning_ = true;
        started_ = false;
        return;
    }
    if (!(c_.field_ut > 0)) field_ut_ = median(learn_field_);
    if (std::isnan(c_.dip_deg)) dip_deg_ = median(learn_dip_);
    set_dip_bounds();
    learn_field_.clear();
    learn_dip_.clear();
}

bool MagneticFieldGate::accept(int64_t t_ns, const Vec3& mag, const Vec3& up) {
    // One square root and no arcsine per reading: the dip test compares sines
    // (the sine is monotonic over [-90, 90] deg); the dip in degrees is only
    // computed while learning and when asked for.
    const double n2 = mag.squaredNorm();
    last_field_ut_ = std::sqrt(n2);
    const double scale = std::sqrt(up.squaredNorm()) * last_field_ut_;
    last_sin_dip_ = scale > 0 ? std::clamp(-mag.dot(up) / scale, -1.0, 1.0) : 0.0;
    if (learning_) {
        if (!started_) started_ = true, t_first_ns_ = t_ns;
        const bool plausible = last_field_ut_ >= kEarthMinUt && last_field_ut_ <= kEarthMaxUt;
        if (plausible && learn_field_.size() < kLearnCapacity) {
            learn_field_.push_back(last_field_ut_);
            learn_dip_.push_back(last_dip_deg());
        }
        if (1e-9 * static_cast<double>(t_ns - t_first_ns_) >= c_.learn_s) finish_learning();
        return plausible;
    }
    return std::fabs(last_field_ut_ - field_ut_) <= c_.field_tolerance_ut && last_sin_dip_ >= sin_dip_min_ &&
           last_sin_dip_ <= sin_dip_max_;
}

double MagneticFieldGate::last_dip_deg() const { return std::asin(last_sin_dip_) * 180.0 / M_PI; }

void MagneticFieldGate::set_dip_bounds() {
    if (!std::isfinite(dip_deg_)) return;
    const double lo = std::max(-90.0, dip_deg_ - c_.dip_tolerance_deg), hi = std::min(90.0, dip_deg_ + c_.dip_tolerance_deg);
    sin_dip_min_ = std::sin(lo * M_PI / 180.0);
    sin_dip_max_ = std::sin(hi * M_PI / 180.0);
}

}  // namespace pednav::navmath

// SPDX-License-Identifier: Apache-2.0
// The step vector of chest-imu-particle-filter-map-matching sec. 3.2: the
// displacement of one step as
//
//   D = K * double integral over the step of a(t) dt dt             (eq. 1)
//
// with a(t) the world-frame horizontal acceleration (gravity removed), the
// velocity taken as 0 at the step's start. Within one step the deceleration
// after the heel strike dominates, so the double integral points backwards:
// K is negative (ERRATA.md; the paper found it in [-5, -3]) and is calibrated
// per user. The direction comes from the acceleration, not from the way the
// sensor points, so the walker may face away from it.
//
// remove_mean subtracts the step's mean acceleration first. That takes out
// the gravity a tilt error leaks into the horizontal (1 deg: 0.17 m/s^2), but
// also the step's mean deceleration, which is much of what eq. (1) measures:
// on the humolire phone walks the step vectors then lose their direction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pednav::pdr {

struct HorizontalSample {
    int64_t t_ns;
    double east_mps2, north_mps2;
};

struct PlaneVector {
    double east_m = 0.0, north_m = 0.0;
};

// Trapezoidal double integral of the samples (time order) from the first to
// the last, v = 0 at the first; without K. Fewer than two samples give 0.
PlaneVector double_integral(const HorizontalSample* samples, size_t count, bool remove_mean);

// The horizontal acceleration between steps, held until the step that covers
// it is known (a step detector reports a step after its end).
class StepVectorBuffer {
public:
    // Keeps the samples of the last max_span_s (older ones are dropped as
    // new ones come): the longest step it can integrate.
    explicit StepVectorBuffer(double max_span_s);
    void add(const HorizontalSample& s);
    // The double integral over the samples in [t_start_ns, t_end_ns]; drops
    // every sample up to t_end_ns, except the last one within the step,
    // which starts the next.
    PlaneVector close(int64_t t_start_ns, int64_t t_end_ns, bool remove_mean);
    void clear() { samples_.clear(), first_ = 0; }
    size_t size() const { return samples_.size() - first_; }

private:
    std::vector<HorizontalSample> samples_;
    size_t first_ = 0;  // samples_[first_..] are held; the prefix is dropped in bulk
    int64_t max_span_ns_;
};

}  // namespace pednav::pdr

// SPDX-License-Identifier: Apache-2.0
// The particle filter's random numbers, the same on every platform for a
// seed: std::mt19937_64 (its sequence is fixed by the C++ standard) with the
// uniform and normal transforms written out here (the standard library's
// distributions differ between implementations).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace pednav::map_matching {

class Random {
public:
    explicit Random(uint64_t seed) : engine_(seed) {}

    // Uniform in [0, 1), 53 bits.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the bias is
    // below 2^-40 for the particle counts used here).
    uint32_t index(uint32_t n) { return static_cast<uint32_t>((engine_() >> 32) * n >> 32); }
    // Standard normal (Marsaglia's polar method: no trigonometry, both values
    // of a pair used).
    double normal() {
        if (has_spare_) {
            has_spare_ = false;
            return spare_;
        }
        double x, y, r2;
        do {
            x = 2.0 * uniform() - 1.0;
            y = 2.0 * uniform() - 1.0;
            r2 = x * x + y * y;
        } while (r2 >= 1.0 || r2 == 0.0);
        const double k = std::sqrt(-2.0 * std::log(r2) / r2);
        spare_ = y * k;
        has_spare_ = true;
        return x * k;
    }
    // A point uniform in the disc of radius r around the origin.
    void in_disc(double r, double& de, double& dn) {
        const double rho = r * std::sqrt(uniform()), th = 2.0 * M_PI * uniform();
        de = rho * std::cos(th);
        dn = rho * std::sin(th);
    }

private:
    std::mt19937_64 engine_;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

}  // namespace pednav::map_matching

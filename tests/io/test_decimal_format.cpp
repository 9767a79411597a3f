// SPDX-License-Identifier: Apache-2.0
// format_fixed and format_general write what snprintf("%.*f") and
// snprintf("%.*g") write, byte for byte: on random values over every
// magnitude, on values next to the half-way points of their last digit (where
// the fast path must hand over), and on the special values.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "decimal_format.hpp"

using namespace pednav::io::detail;

namespace {

std::string fixed_text(double x, int decimals) {
    char buf[kMaxDecimalChars];
    return std::string(buf, format_fixed(buf, x, decimals));
}

std::string general_text(double x, int significant) {
    char buf[kMaxDecimalChars];
    return std::string(buf, format_general(buf, x, significant));
}

std::string printf_text(const char* format, int precision, double x) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, precision, x);
    return buf;
}

// Counts the values whose text differs from printf's, and shows the first few.
struct Mismatches {
    int count = 0;
    void check(const std::string& got, const std::string& want, const char* what, int precision, double x) {
        if (got == want) return;
        if (++count <= 5)
            MESSAGE(what << precision << " of " << printf_text("%.*e", 17, x) << ": " << got << " instead of "
                         << want);
    }
};

std::vector<double> special_values() {
    const double inf = std::numeric_limits<double>::infinity();
    return {0.0,           -0.0,
            1.0,           -1.0,
            0.5,           -0.5,
            1.5,           2.5,
            0.125,         0.375,
            1e-300,        -1e-300,
            DBL_MIN,       DBL_TRUE_MIN,
            DBL_MAX,       -DBL_MAX,
            inf,           -inf,
            std::nan(""),  -std::nan(""),
            9.9999999996,  0.99999999996,
            999999999.5,   1e15,
            1e16,          123456789012345678.0,
            1e-5,          1e-4,
            0.0001,        0.00009999999999,
            1e22,          1e23,
            5e-324,        0x1p51,
            0x1p52,        0x1p53,
            -0x1p51 + 0.5, 299792458.0,
            6.02214076e23, 1.602176634e-19};
}

}  // namespace

TEST_CASE("format_fixed and format_general: the special values as printf writes them") {
    Mismatches m;
    for (double x : special_values()) {
        for (int d = 0; d <= 17; ++d) m.check(fixed_text(x, d), printf_text("%.*f", d, x), "%.f with ", d, x);
        for (int p = 0; p <= 17; ++p)
            m.check(general_text(x, p), printf_text("%.*g", p, x), "%.g with ", p, x);
    }
    CHECK(m.count == 0);
    CHECK(fixed_text(-0.0, 6) == "-0.000000");
    CHECK(fixed_text(-1e-9, 3) == "-0.000");
    CHECK(general_text(1e-5, 9) == "1e-05");
    CHECK(general_text(0.0001, 9) == "0.0001");
    CHECK(general_text(123456789.0, 9) == "123456789");
    CHECK(general_text(1234567890.0, 9) == "1.23456789e+09");
}

TEST_CASE("format_fixed and format_general: 400 000 random values of every magnitude as printf writes them") {
    std::mt19937_64 rng(20261204);
    std::uniform_real_distribution<double> mantissa(1.0, 10.0);
    std::uniform_int_distribution<int> exponent(-30, 30), sign(0, 1), fixed_digits(0, 12),
        general_digits(1, 17);
    Mismatches m;
    for (int i = 0; i < 200000; ++i) {
        const double x = (sign(rng) ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, exponent(rng));
        const int d = fixed_digits(rng), p = general_digits(rng);
        m.check(fixed_text(x, d), printf_text("%.*f", d, x), "%.f with ", d, x);
        m.check(general_text(x, p), printf_text("%.*g", p, x), "%.g with ", p, x);
    }
    // Raw bit patterns: subnormals, huge values and everything between.
    std::uniform_int_distribution<uint64_t> bits;
    for (int i = 0; i < 100000; ++i) {
        const uint64_t b = bits(rng);
        double x;
        std::memcpy(&x, &b, sizeof x);
        const int d = fixed_digits(rng), p = general_digits(rng);
        m.check(fixed_text(x, d), printf_text("%.*f", d, x), "%.f with ", d, x);
        m.check(general_text(x, p), printf_text("%.*g", p, x), "%.g with ", p, x);
    }
    CHECK(m.count == 0);
}

TEST_CASE(
    "format_fixed and format_general: values a few ulps from a half-way point round as printf rounds them") {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int64_t> digits(0, 999999999);
    std::uniform_int_distribution<int> decimals(0, 9), steps(-4, 4), significant(1, 15);
    Mismatches m;
    int exact_ties = 0;
    for (int i = 0; i < 100000; ++i) {
        // (n + 1/2) / 10^d, then a few ulps either side: printf rounds the exact binary value.
        const int d = decimals(rng);
        double x = (static_cast<double>(digits(rng)) + 0.5) / std::pow(10.0, d);
        const int s = steps(rng);
        for (int k = 0; k < std::abs(s); ++k) x = std::nextafter(x, s > 0 ? HUGE_VAL : -HUGE_VAL);
        exact_ties += s == 0 && d == 0;
        m.check(fixed_text(x, d), printf_text("%.*f", d, x), "%.f with ", d, x);
        const int p = significant(rng);
        m.check(general_text(x, p), printf_text("%.*g", p, x), "%.g with ", p, x);
    }
    CHECK(exact_ties > 1000);  // the ties of %.0f (n + 0.5 is exact) are among them
    CHECK(m.count == 0);
}

TEST_CASE("format_fixed: the track writer's columns of a walk, compared with printf") {
    // Positions of a few kilometres, times of hours, headings and covariances as the CSVs write them.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> position(-5000.0, 5000.0), time(0.0, 86400.0), heading(0.0, 360.0),
        variance(0.0, 4.0);
    Mismatches m;
    for (int i = 0; i < 50000; ++i) {
        const double t = std::round(time(rng) * 400.0) / 400.0, x = position(rng), h = heading(rng),
                     c = variance(rng) * std::pow(10.0, -static_cast<int>(rng() % 12));
        m.check(fixed_text(t, 9), printf_text("%.*f", 9, t), "%.f with ", 9, t);
        m.check(fixed_text(x, 6), printf_text("%.*f", 6, x), "%.f with ", 6, x);
        m.check(fixed_text(h, 4), printf_text("%.*f", 4, h), "%.f with ", 4, h);
        m.check(general_text(c, 9), printf_text("%.*g", 9, c), "%.g with ", 9, c);
    }
    CHECK(m.count == 0);
}

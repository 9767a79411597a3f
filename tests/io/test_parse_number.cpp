// SPDX-License-Identifier: Apache-2.0
// parse_number gives the bits std::from_chars gives (the nearest double of
// the decimal), through its fast path and around it, and the same status for
// what is not a finite number.
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "pednav_io/text_fields.hpp"

using pednav::io::NumberStatus;
using pednav::io::parse_number;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// What parse_number gave before its fast path: std::from_chars on the trimmed field without a '+'.
double reference(const std::string& text) {
    std::string_view f = pednav::io::trim(text);
    if (!f.empty() && f.front() == '+') f.remove_prefix(1);
    double v = std::nan("");
    std::from_chars(f.data(), f.data() + f.size(), v);
    return v;
}

}  // namespace

TEST_CASE(
    "parse_number: the nearest double of a decimal, as from_chars reads it, for every way numbers are "
    "written") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> mantissa(1.0, 10.0);
    std::uniform_int_distribution<int> exponent(-30, 30), precision(1, 19);
    const char* formats[] = {"%.*g", "%.*f", "%.*e"};
    int wrong = 0, checked = 0;
    for (int i = 0; i < 200000; ++i) {
        const double x = (rng() & 1 ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, exponent(rng));
        char text[400];
        std::snprintf(text, sizeof text, formats[i % 3], precision(rng), x);
        double v = 0;
        const bool ok = parse_number(text, &v) == NumberStatus::ok;
        ++checked;
        if ((!ok || !same_bits(v, reference(text))) && ++wrong <= 5) MESSAGE(text << " read as " << v);
    }
    CHECK(checked == 200000);
    CHECK(wrong == 0);
}

TEST_CASE("parse_number: forms at the fast path's edges and the statuses of what is not a number") {
    const char* fine[] = {"0",
                          "-0",
                          "0.0",
                          "-0.000",
                          "1",
                          "+1",
                          " 2.5 ",
                          "9007199254740992",
                          "9007199254740993",
                          "12345678901234567890",
                          "1e22",
                          "1e23",
                          "1e-22",
                          "1e-23",
                          "5.",
                          ".5",
                          "-.5",
                          "1E5",
                          "1e+5",
                          "1e-5",
                          "0.0000000000000000000000001",
                          "123456789012345678901234567890",
                          "4.9406564584124654e-324",
                          "1.7976931348623157e308"};
    for (const char* t : fine) {
        double v = 0;
        CAPTURE(t);
        REQUIRE(parse_number(t, &v) == NumberStatus::ok);
        CHECK(same_bits(v, reference(t)));
    }
    double v = 0;
    CHECK(same_bits((parse_number("-0", &v), v), -0.0));
    for (const char* t : {"", "  "}) CHECK(parse_number(t, &v) == NumberStatus::empty);
    for (const char* t : {"-", ".", "1e", "1e+", "e5", "1.2.3", "12a", "0x10", "--1", "1e5x", "abc"})
        CHECK_MESSAGE(parse_number(t, &v) == NumberStatus::not_a_number, t);
    for (const char* t : {"1e400", "-1e400", "inf", "nan"})
        CHECK_MESSAGE(parse_number(t, &v) == NumberStatus::non_finite, t);
}

// SPDX-License-Identifier: Apache-2.0
#include "decimal_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace pednav::io::detail {

namespace {

// Every power of ten up to 1e22 is a double exactly (5^22 < 2^53).
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr uint64_t kPow10Int[] = {1ull,
                                  10ull,
                                  100ull,
                                  1000ull,
                                  10000ull,
                                  100000ull,
                                  1000000ull,
                                  10000000ull,
                                  100000000ull,
                                  1000000000ull,
                                  10000000000ull,
                                  100000000000ull,
                                  1000000000000ull,
                                  10000000000000ull,
                                  100000000000000ull,
                                  1000000000000000ull,
                                  10000000000000000ull,
                                  100000000000000000ull,
                                  1000000000000000000ull,
                                  10000000000000000000ull};
constexpr int kMaxFastDecimals = 19;     // kPow10Int's range
constexpr int kMaxFastSignificant = 15;  // 10^15 < 2^51
constexpr double kMaxScaled = 0x1p51;    // y 2^-52 < 1/2: only the nearest half-integer can be in reach

// The nearest integer to the exact value |x| 10^s whose double y = |x| 10^s
// carries one rounding, or false when a half-integer is too close to tell.
bool round_scaled(double y, uint64_t* k) {
    if (!(y < kMaxScaled)) return false;
    const double whole = static_cast<double>(static_cast<int64_t>(y));  // floor: y >= 0, below 2^51
    const double frac = y - whole;                                     // exact
    if (!(std::fabs(frac - 0.5) > y * 0x1p-52)) return false;
    *k = static_cast<uint64_t>(whole) + (frac > 0.5 ? 1 : 0);
    return true;
}

// "00" to "99": two digits per division.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The `count` lowest decimal digits of v, with leading zeros.
char* write_digits(char* out, uint64_t v, int count) {
    int i = count;
    while (i >= 2) {
        const char* pair = kDigitPairs + 2 * (v % 100);
        v /= 100;
        out[--i] = pair[1];
        out[--i] = pair[0];
    }
    if (i == 1) out[0] = static_cast<char>('0' + v % 10);
    return out + count;
}

// The decimal digits of v.
char* write_uint(char* out, uint64_t v) {
    int count = 1;
    for (uint64_t rest = v; rest >= 10; rest /= 10) ++count;
    return write_digits(out, v, count);
}

// floor(log2(x)) + 1 for a finite x > 0: x in [2^(e - 1), 2^e) (frexp's exponent).
int binary_exponent(double x) {
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if (biased == 0) {  // subnormal
        int e = 0;
        std::frexp(x, &e);
        return e;
    }
    return biased - 1022;
}

// Drops trailing zeros of the fraction written since `point` (the '.'), and
// the point when nothing is left after it.
char* strip_fraction(char* point, char* end) {
    while (end > point + 1 && end[-1] == '0') --end;
    return end == point + 1 ? point : end;
}

// %g's digits: k holds exactly p significant digits, the value is k 10^(e - p + 1).
char* write_general_digits(char* out, uint64_t k, int p, int e) {
    char digits[20];
    write_digits(digits, k, p);
    if (e >= -4 && e < p) {  // style f with precision p - 1 - e
        if (e >= 0) {
            for (int i = 0; i <= e; ++i) *out++ = digits[i];
            char* point = out;
            *out++ = '.';
            for (int i = e + 1; i < p; ++i) *out++ = digits[i];
            return strip_fraction(point, out);
        }
        *out++ = '0';
        char* point = out;
        *out++ = '.';
        for (int i = 0; i < -e - 1; ++i) *out++ = '0';
        for (int i = 0; i < p; ++i) *out++ = digits[i];
        return strip_fraction(point, out);
    }
    // Style e with precision p - 1.
    *out++ = digits[0];
    char* point = out;
    *out++ = '.';
    for (int i = 1; i < p; ++i) *out++ = digits[i];
    out = strip_fraction(point, out);
    *out++ = 'e';
    *out++ = e < 0 ? '-' : '+';
    const int ae = e < 0 ? -e : e;
    if (ae < 10) *out++ = '0';
    return write_uint(out, static_cast<uint64_t>(ae));
}

}  // namespace

char* format_fixed(char* out, double x, int decimals) {
    uint64_t k = 0;
    if (decimals <= kMaxFastDecimals && std::isfinite(x) &&
        round_scaled(std::fabs(x) * kPow10[decimals], &k)) {
        if (std::signbit(x)) *out++ = '-';
        const uint64_t unit = kPow10Int[decimals];
        out = write_uint(out, k / unit);
        if (decimals == 0) return out;
        *out++ = '.';
        return write_digits(out, k % unit, decimals);
    }
    return std::to_chars(out, out + kMaxDecimalChars, x, std::chars_format::fixed, decimals).ptr;
}

char* format_general(char* out, double x, int significant) {
    const int p = significant == 0 ? 1 : significant;
    if (p <= kMaxFastSignificant && std::isfinite(x)) {
        if (x == 0) {
            if (std::signbit(x)) *out++ = '-';
            *out++ = '0';
            return out;
        }
        const double ax = std::fabs(x);
        // floor(log10(ax)), or one less; corrected below from the digits.
        const int e2 = binary_exponent(ax);
        // floor((e2 - 1) log10 2) as (e2 - 1) 78913 / 2^18 rounded down: exact for |e2| < 1650.
        int e = ((e2 - 1) * 78913) >> 18;
        for (int attempt = 0; attempt < 3; ++attempt) {
            const int s = p - 1 - e;  // scale |x| so that p digits are left of the point
            double y;
            if (s >= 0 && s <= 22)
                y = ax * kPow10[s];
            else if (s < 0 && s >= -22)
                y = ax / kPow10[-s];  // correctly rounded: one rounding too
            else
                break;
            if (y >= kPow10[p]) {  // the exponent is higher (or the digits round up to 10^p)
                ++e;
                continue;
            }
            uint64_t k = 0;
            if (!round_scaled(y, &k)) break;
            if (k == kPow10Int[p]) {
                ++e;
                continue;
            }
            if (k < kPow10Int[p - 1]) {
                --e;
                continue;
            }
            if (std::signbit(x)) *out++ = '-';
            return write_general_digits(out, k, p, e);
        }
    }
    return std::to_chars(out, out + kMaxDecimalChars, x, std::chars_format::general, p).ptr;
}

}  // namespace pednav::io::detail

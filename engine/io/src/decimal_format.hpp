// SPDX-License-Identifier: Apache-2.0
// Internal: doubles as printf's "%.*f" and "%.*g" write them, byte for byte,
// at a tenth of the cost.
//
// printf converts the exact binary value; so does std::to_chars with a
// precision (the standard defines it "as if by printf in the C locale"), at
// about 600 instructions a number, glibc's printf at 2 400-2 800. The fast
// path here scales |x| by a power of ten that a double holds exactly, so the
// scaled value y carries one rounding (|y - exact| <= y 2^-53), and rounds y
// to an integer: that is the exact value's rounding unless a half-integer lies
// within y 2^-52 of y, which the path checks and then hands the number to
// std::to_chars. Also handed over: NaN, infinities, and numbers whose scaled
// value or scale is out of the fast path's range (|y| >= 2^51, a scale beyond
// 10^22, more than 9 decimals or 15 significant digits).
#pragma once

#include <cstddef>

namespace pednav::io::detail {

// The longest text either function writes: "%.9f" of -DBL_MAX is 320 characters.
constexpr size_t kMaxDecimalChars = 336;

// Writes x as printf("%.*f", decimals, x) would (decimals >= 0) at `out`,
// which holds kMaxDecimalChars; returns the end of the text (not terminated).
char* format_fixed(char* out, double x, int decimals);

// Writes x as printf("%.*g", significant, x) would (significant >= 0; 0 is
// taken as 1, as printf does).
char* format_general(char* out, double x, int significant);

}  // namespace pednav::io::detail

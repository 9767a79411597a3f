// SPDX-License-Identifier: Apache-2.0
// Fields of delimited text lines, as every pednav reader splits and parses them:
// the recording readers of pednav_io and the track and truth readers of the
// evaluation share these rules.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pednav::io {

// Without leading and trailing spaces, tabs and carriage returns.
std::string_view trim(std::string_view s);

// Splits on `delim`, each field trimmed; with delim == ' ' any run of spaces or
// tabs separates. The views point into `line`.
std::vector<std::string_view> split(std::string_view line, char delim);
void split_into(std::string_view line, char delim, std::vector<std::string_view>& out);

enum class NumberStatus { ok, empty, not_a_number, non_finite };

// Parses the whole trimmed field as a decimal double (locale-independent,
// optional leading '+'); "nan", "inf", hexadecimal and trailing text are not numbers.
NumberStatus parse_number(std::string_view field, double* value);

// "not a number: 'abc' in column Acc_X" style text for a failed parse.
std::string describe_bad_number(NumberStatus status, std::string_view field, std::string_view column);

// Column index of `name` in `names` (exact match), or -1.
int find_column(const std::vector<std::string>& names, const std::string& name);

}  // namespace pednav::io

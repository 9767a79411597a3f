// Minimal CSV helpers shared by the track and truth readers.
#pragma once

#include <string>
#include <vector>

namespace pednav::eval::detail {

std::vector<std::string> split(const std::string& line, char sep);
std::string trim(const std::string& s);
// Parses a number; throws std::runtime_error naming file and line.
double to_double(const std::string& s, const std::string& file, size_t line);
// Index of column `name` in the header, -1 when absent.
int column(const std::vector<std::string>& header, const std::string& name);

}  // namespace pednav::eval::detail

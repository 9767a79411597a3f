// JSON description of what a Loader found (libraries, plugins, rejected files).
#pragma once

#include <nlohmann/json.hpp>

#include "loader.hpp"

namespace pednav::engine {
nlohmann::json describe_loader(const Loader& loader);
}

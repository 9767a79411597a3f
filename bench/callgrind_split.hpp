// SPDX-License-Identifier: Apache-2.0
// Splits the instructions of a callgrind profile between the engine
// (libpednav.so), the plugins (libpnp_*.so) and the rest (the benchmark's own
// loop), from the inclusive costs of the calls that cross between them:
//
//   plugins = calls engine -> plugin  -  calls plugin -> engine (the sink, the host)
//   engine  = calls other -> engine   -  plugins, so the sink's work inside a
//             plugin call counts for the engine
//
// System libraries (libc, libm, libstdc++) count for whoever calls them.
#pragma once

#include <cstdint>
#include <string>

namespace pednav::bench {

struct InstructionSplit {
    bool ok = false;
    std::string error;  // why not, when !ok
    uint64_t total = 0;
    uint64_t engine = 0;
    uint64_t plugins = 0;
};

// Reads a callgrind output file (the format of valgrind's callgrind-format
// documentation, event Ir first).
InstructionSplit split_callgrind_profile(const std::string& path);

}  // namespace pednav::bench

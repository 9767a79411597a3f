// SPDX-License-Identifier: Apache-2.0
// Two output sequences equal byte for byte (each record over its struct_size).
#pragma once

#include <cstring>
#include <vector>

#include <pednav/pn_engine.h>

namespace pednav::test {

inline bool same_bytes(const std::vector<pn_output_t>& a, const std::vector<pn_output_t>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].header.struct_size != b[i].header.struct_size ||
            std::memcmp(&a[i], &b[i], a[i].header.struct_size) != 0)
            return false;
    return true;
}

}  // namespace pednav::test

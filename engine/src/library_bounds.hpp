// SPDX-License-Identifier: Apache-2.0
// The readable memory of one opened plugin library (its PT_LOAD segments), so
// the loader can check a pointer the library hands over before following it:
// a plugin_count larger than the plugins array, or a descriptor pointer into
// nowhere, is refused with a reason instead of read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pednav::engine {

class LibraryBounds {
public:
    // The segments of the object dlopen() returned `handle` for; empty (every
    // check fails) if they cannot be found.
    explicit LibraryBounds(void* handle);

    // [p, p + bytes) lies in one readable segment of the library.
    bool holds(const void* p, size_t bytes) const;
    // A NUL-terminated string starting in the library and ending in the same segment.
    bool holds_string(const char* s) const;
    bool known() const { return !segments_.empty(); }

private:
    std::vector<std::pair<uintptr_t, uintptr_t>> segments_;  // [begin, end)
};

}  // namespace pednav::engine

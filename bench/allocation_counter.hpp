// SPDX-License-Identifier: Apache-2.0
// Counts heap allocations made anywhere in the process (the engine and the
// dlopen'ed plugins resolve operator new and malloc to the executable's).
#pragma once

#include <cstdint>

namespace pednav::bench {
uint64_t allocation_count();
}

// SPDX-License-Identifier: Apache-2.0
// The positions of a run kept for the outputs written at its end (GeoJSON,
// GPX, a geo-track CSV whose origin is known only then), in memory independent
// of their number: the newest in memory, the rest in an unnamed temporary file
// (72 bytes each). They are read back in order, as often as needed.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

#include <pednav/pn_types.h>

namespace pednav::io {

class PositionLog {
public:
    PositionLog();
    ~PositionLog();
    PositionLog(const PositionLog&) = delete;
    PositionLog& operator=(const PositionLog&) = delete;

    void add(const pn_position_t& position);
    size_t size() const;
    // f for every position, in order. Each holds what the writers write: its
    // time, flags, position, heading, floor, source and cov_xx, cov_yy; the rest is 0.
    void for_each(const std::function<void(const pn_position_t&)>& f) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace pednav::io

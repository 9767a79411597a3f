// SPDX-License-Identifier: Apache-2.0
// Internal: where a LogBuilder puts the records it makes: the vectors of a
// SensorLog (a GNSS file, read whole) or a RecordMerger (a RecordStream).
#pragma once

#include <cstdint>

#include "pednav_io/record_stream.hpp"

namespace pednav::io::detail {

class RecordSink {
public:
    virtual ~RecordSink() = default;
    // False when a record of `type` at t_ns would come after records already
    // handed on that are later than it: it cannot be placed in time order.
    virtual bool placeable(pn_record_type_t type, int64_t t_ns) const = 0;
    virtual void add(const InputRecord& record) = 0;
};

// Appends to log.imu, log.mag, log.baro, log.gnss.
class VectorSink : public RecordSink {
public:
    explicit VectorSink(SensorLog& log) : log_(log) {}
    bool placeable(pn_record_type_t, int64_t) const override { return true; }
    void add(const InputRecord& record) override;

private:
    SensorLog& log_;
};

}  // namespace pednav::io::detail

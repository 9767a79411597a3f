// SPDX-License-Identifier: Apache-2.0
// Internal: the records of a file's streams, each stream in its own time
// order, handed on as one sequence in time order, at equal t_ns IMU, MAG,
// BARO, GNSS: the order of merged_records' stable sort, without the file.
// A record is handed on once every other stream that may still give records
// has given one at or after its time. A stream that stays silent (a column
// whose sensor stopped) holds the others back, at most `window` records; then
// the earliest is handed on anyway, and a record of the silent stream from
// before it can no longer be placed (placeable() says so).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "record_sink.hpp"

namespace pednav::io::detail {

class RecordMerger : public RecordSink {
public:
    explicit RecordMerger(size_t window_records) : window_(window_records) {}

    void set_window(size_t window_records) { window_ = window_records; }
    // Whether records of `type` may still come (all may at first).
    void set_open(pn_record_type_t type, bool open);
    void close_all();

    bool placeable(pn_record_type_t type, int64_t t_ns) const override;
    void add(const InputRecord& record) override;

    // Appends to `out` the records whose place is known, at most `max`; returns how many.
    size_t release(std::vector<InputRecord>& out, size_t max);
    size_t queued() const { return queued_; }

private:
    static constexpr int kSlots = 4;  // IMU, MAG, BARO, GNSS: the order at equal times
    static int slot_of(pn_record_type_t type);

    size_t window_;
    std::deque<InputRecord> queue_[kSlots];
    bool open_[kSlots] = {true, true, true, true};
    bool seen_[kSlots] = {false, false, false, false};
    int64_t last_t_ns_[kSlots] = {0, 0, 0, 0};  // of the last record added to each slot
    size_t queued_ = 0;
    bool released_any_ = false;
    int64_t released_t_ns_ = 0;  // the last record handed on
    int released_slot_ = 0;
};

}  // namespace pednav::io::detail

// SPDX-License-Identifier: Apache-2.0
// The engine's output queue: single producer (the pushing thread) and single
// consumer (the polling thread), fixed capacity allocated at create. When it is
// full new outputs are dropped and counted; the newest output of each type is
// also kept for get_latest.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <vector>

#include <pednav/pn_engine.h>

#include "record_copy.hpp"

namespace pednav::engine {

class OutputQueue {
public:
    explicit OutputQueue(size_t capacity) : slots_(capacity ? capacity : 8192) {}

    // Copies the record, stamping its header's source_id; false when the
    // queue is full and the record was dropped (counted in dropped()).
    bool push(const pn_record_header_t* r, uint32_t source_id) {
        if (r->type < PN_REC_TYPE_COUNT) {
            copy_record(latest_[r->type].bytes, r);
            latest_[r->type].header.source_id = source_id;
            has_latest_[r->type] = true;
        }
        const uint64_t tail = tail_.load(std::memory_order_relaxed);
        if (tail - head_.load(std::memory_order_acquire) >= slots_.size()) {
            ++dropped_;
            return false;
        }
        pn_output_t& slot = slots_[tail % slots_.size()];
        copy_record(slot.bytes, r);
        slot.header.source_id = source_id;
        tail_.store(tail + 1, std::memory_order_release);
        return true;
    }
    bool pop(pn_output_t* out) {
        const uint64_t head = head_.load(std::memory_order_relaxed);
        if (head == tail_.load(std::memory_order_acquire)) return false;
        const pn_output_t& s = slots_[head % slots_.size()];
        std::memcpy(out, &s, s.header.struct_size);
        head_.store(head + 1, std::memory_order_release);
        return true;
    }
    bool latest(pn_record_type_t type, pn_output_t* out) const {
        if (type >= PN_REC_TYPE_COUNT || !has_latest_[type]) return false;
        std::memcpy(out, &latest_[type], latest_[type].header.struct_size);
        return true;
    }
    void clear() {
        head_.store(tail_.load());
        for (bool& h : has_latest_) h = false;
    }
    uint64_t dropped() const { return dropped_; }
    size_t size() const { return tail_.load() - head_.load(); }
    size_t capacity() const { return slots_.size(); }

private:
    std::vector<pn_output_t> slots_;
    pn_output_t latest_[PN_REC_TYPE_COUNT] = {};
    bool has_latest_[PN_REC_TYPE_COUNT] = {};
    std::atomic<uint64_t> head_{0}, tail_{0};
    uint64_t dropped_ = 0;
};

}  // namespace pednav::engine

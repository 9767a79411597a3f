// SPDX-License-Identifier: Apache-2.0
// The engine's output queue: single producer (the pushing thread) and single
// consumer (the polling thread), fixed capacity allocated at create. When it is
// full new outputs are dropped and counted.
//
// The newest output of each type (get_latest, a [producer] call) is not copied
// aside per record: it is the queue's slot that holds it, named by its
// sequence number, for as long as the slot does. Only when the producer is
// about to reuse that slot, or drops the record for a full queue, is the
// record copied into the type's own cell. The consumer never writes a slot,
// and the producer reuses one only after the consumer has released it, so
// both may read the same slot at once.
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
    explicit OutputQueue(size_t capacity) : slots_(capacity ? capacity : 8192) {
        for (auto& s : latest_seq_) s = kNone;
    }

    // Copies the record, stamping its header's source_id; false when the
    // queue is full and the record was dropped (counted in dropped()).
    bool push(const pn_record_header_t* r, uint32_t source_id) {
        const uint64_t tail = tail_.load(std::memory_order_relaxed);
        if (tail - head_.load(std::memory_order_acquire) >= slots_.size()) {
            keep_latest(r, source_id);
            ++dropped_;
            return false;
        }
        pn_output_t& slot = slots_[tail_index_];
        if (tail >= slots_.size()) keep_if_latest(slot, tail - slots_.size());
        copy_record(slot.bytes, r);
        slot.header.source_id = source_id;
        if (r->type < PN_REC_TYPE_COUNT) latest_seq_[r->type] = tail;
        if (++tail_index_ == slots_.size()) tail_index_ = 0;
        tail_.store(tail + 1, std::memory_order_release);
        return true;
    }
    bool pop(pn_output_t* out) {
        const uint64_t head = head_.load(std::memory_order_relaxed);
        if (head == tail_.load(std::memory_order_acquire)) return false;
        copy_record(out, &slots_[head_index_].header);
        if (++head_index_ == slots_.size()) head_index_ = 0;
        head_.store(head + 1, std::memory_order_release);
        return true;
    }
    // [producer] The newest record of `type` pushed (queued or dropped).
    bool latest(pn_record_type_t type, pn_output_t* out) const {
        if (type >= PN_REC_TYPE_COUNT || latest_seq_[type] == kNone) return false;
        const pn_output_t& from =
            latest_seq_[type] == kKept ? kept_[type] : slots_[latest_seq_[type] % slots_.size()];
        std::memcpy(out, &from, from.header.struct_size);
        return true;
    }
    void clear() {
        head_.store(tail_.load());
        head_index_ = tail_index_;
        for (auto& s : latest_seq_) s = kNone;
    }
    uint64_t dropped() const { return dropped_; }
    size_t size() const { return tail_.load() - head_.load(); }
    size_t capacity() const { return slots_.size(); }

private:
    static constexpr uint64_t kNone = ~uint64_t{0};      // no record of the type yet
    static constexpr uint64_t kKept = ~uint64_t{0} - 1;  // in kept_, not in a slot

    void keep_latest(const pn_record_header_t* r, uint32_t source_id) {
        if (r->type >= PN_REC_TYPE_COUNT) return;
        copy_record(kept_[r->type].bytes, r);
        kept_[r->type].header.source_id = source_id;
        latest_seq_[r->type] = kKept;
    }
    // The slot of sequence number `seq` is about to be reused.
    void keep_if_latest(const pn_output_t& slot, uint64_t seq) {
        const pn_record_type_t type = slot.header.type;
        if (type < PN_REC_TYPE_COUNT && latest_seq_[type] == seq) {
            std::memcpy(&kept_[type], &slot, slot.header.struct_size);
            latest_seq_[type] = kKept;
        }
    }

    std::vector<pn_output_t> slots_;
    size_t tail_index_ = 0;  // tail_ % capacity, the producer's
    size_t head_index_ = 0;  // head_ % capacity, the consumer's
    uint64_t latest_seq_[PN_REC_TYPE_COUNT];
    pn_output_t kept_[PN_REC_TYPE_COUNT] = {};
    std::atomic<uint64_t> head_{0}, tail_{0};
    uint64_t dropped_ = 0;
};

}  // namespace pednav::engine

// SPDX-License-Identifier: Apache-2.0
// A time-ordered FIFO of records read by several consumers (the edges that
// carry them, edge_fifo.hpp), each record named by a sequence number. Slots
// are fixed 512-byte cells in a power-of-two ring that doubles when full and
// is reused otherwise, so steady-state streaming allocates nothing.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include <pednav/pn_types.h>

#include "record_copy.hpp"

namespace pednav::engine {

class RecordQueue {
public:
    using Seq = uint64_t;

    explicit RecordQueue(size_t initial_capacity = 64) {
        size_t c = 1;
        while (c < initial_capacity) c <<= 1;
        slots_.resize(c);
        mask_ = c - 1;
    }

    // Copies the record in; returns its sequence number. Grows when full.
    Seq push(const pn_record_header_t* r) {
        if (full()) grow();
        copy_record(slots_[end_ & mask_].bytes, r);
        return end_++;
    }
    // The slot of the next record (needs !full()); append() then counts it in.
    pn_record_header_t* next_slot() {
        return reinterpret_cast<pn_record_header_t*>(slots_[end_ & mask_].bytes);
    }
    Seq append() { return end_++; }

    bool full() const { return end_ - begin_ > mask_; }
    // Doubles the ring (may throw std::bad_alloc, then nothing moved): the
    // records move, each from where(r) to at(seq_of(r)) as seq_of was before.
    void grow() {
        const size_t bigger_mask = 2 * mask_ + 1;
        std::vector<Slot> bigger(bigger_mask + 1);
        for (Seq s = begin_; s < end_; ++s) bigger[s & bigger_mask] = slots_[s & mask_];
        slots_.swap(bigger);
        mask_ = bigger_mask;
    }
    // The sequence number of a record in the queue, from its address: its
    // slot's index, and the one live sequence number with that index.
    Seq seq_of(const pn_record_header_t* r) const { return seq_of(reinterpret_cast<uintptr_t>(r), where()); }
    struct Where {
        uintptr_t base;
        size_t mask;
        Seq begin;
    };
    Where where() const { return Where{reinterpret_cast<uintptr_t>(slots_.data()), mask_, begin_}; }
    static Seq seq_of(uintptr_t address, const Where& w) {
        const Seq index = (address - w.base) / sizeof(Slot);
        return w.begin + ((index - w.begin) & w.mask);
    }

    Seq begin() const { return begin_; }
    Seq end() const { return end_; }
    const pn_record_header_t* at(Seq seq) const {
        return reinterpret_cast<const pn_record_header_t*>(slots_[seq & mask_].bytes);
    }
    pn_record_header_t* at(Seq seq) {
        return reinterpret_cast<pn_record_header_t*>(slots_[seq & mask_].bytes);
    }
    // Frees every slot before `seq` (all consumers are past it).
    void release_until(Seq seq) {
        if (seq > begin_) begin_ = seq < end_ ? seq : end_;
    }
    size_t capacity() const { return slots_.size(); }

private:
    struct alignas(64) Slot {  // a cache line apart: a record starts a line
        unsigned char bytes[PN_RECORD_MAX_SIZE];
    };

    std::vector<Slot> slots_;
    size_t mask_ = 0;  // slots_.size() - 1 (the size is a power of two); the one index rule
    Seq begin_ = 0, end_ = 0;
};

}  // namespace pednav::engine

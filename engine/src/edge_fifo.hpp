// SPDX-License-Identifier: Apache-2.0
// One edge of a pipeline: the records one stage reads from one queue (of the
// types it consumes from that queue's producer), oldest first, each as its
// time and its sequence number in the queue. The record stays in its queue;
// the edge tells its reader the time of its next record, and where it is,
// without looking at records of other types or at other readers' records.
// A power-of-two ring that doubles when full and is reused otherwise, so
// steady-state streaming allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "record_queue.hpp"

namespace pednav::engine {

class EdgeFifo {
public:
    struct Entry {
        int64_t t_ns;
        RecordQueue::Seq seq;
    };

    explicit EdgeFifo(size_t initial_capacity = 64) {
        size_t c = 1;
        while (c < initial_capacity) c <<= 1;
        ring_.resize(c);
        mask_ = c - 1;
    }

    bool empty() const { return head_ == tail_; }
    size_t size() const { return static_cast<size_t>(tail_ - head_); }
    const Entry& front() const { return ring_[head_ & mask_]; }
    void pop() { ++head_; }
    // Grows if full (may throw std::bad_alloc): then push() cannot fail.
    void make_room() {
        if (tail_ - head_ > mask_) grow();
    }
    void push(int64_t t_ns, RecordQueue::Seq seq) { ring_[tail_++ & mask_] = Entry{t_ns, seq}; }
    void clear() { head_ = tail_ = 0; }

private:
    void grow() {
        const size_t bigger_mask = 2 * mask_ + 1;
        std::vector<Entry> bigger(bigger_mask + 1);
        for (uint64_t i = head_; i < tail_; ++i) bigger[i & bigger_mask] = ring_[i & mask_];
        ring_.swap(bigger);
        mask_ = bigger_mask;
    }

    std::vector<Entry> ring_;
    uint64_t mask_ = 0;
    uint64_t head_ = 0, tail_ = 0;
};

}  // namespace pednav::engine

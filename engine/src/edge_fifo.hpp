// SPDX-License-Identifier: Apache-2.0
// One edge of a pipeline: the records one stage reads from one queue (of the
// types it consumes from that queue's producer), oldest first, as pointers
// into the queue's slots. The record stays in its queue; the edge hands its
// reader the next one, and its time, without looking at records of other
// types or at other readers' records. When the queue grows its records move:
// the queue then re-points its edges (RecordQueue::grow).
// A power-of-two ring, kept at least as large as its queue (it never holds
// more records than the queue), reused otherwise, so steady-state streaming
// allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include <pednav/pn_types.h>

namespace pednav::engine {

class EdgeFifo {
public:
    using Record = const pn_record_header_t*;

    explicit EdgeFifo(size_t initial_capacity = 64) {
        size_t c = 1;
        while (c < initial_capacity) c <<= 1;
        ring_.resize(c);
        mask_ = c - 1;
    }

    bool empty() const { return head_ == tail_; }
    size_t size() const { return static_cast<size_t>(tail_ - head_); }
    Record front() const { return ring_[head_ & mask_]; }
    // The time of the oldest record, INT64_MAX when empty.
    int64_t front_t_ns() const { return head_ == tail_ ? INT64_MAX : ring_[head_ & mask_]->t_ns; }
    // Needs room: see the class comment.
    void push(Record record) { ring_[tail_++ & mask_] = record; }

    // Appends to batch[count ..] the records at the front whose time is
    // t_ns, while count < max; returns the new count, and lowers `next` to
    // the time of the record then at the front, if any.
    uint32_t take_at(int64_t t_ns, Record* batch, uint32_t count, uint32_t max, int64_t& next) {
        uint64_t h = head_;
        const uint64_t end = tail_;
        const Record* ring = ring_.data();
        for (; h != end; ++h) {
            const Record r = ring[h & mask_];
            if (r->t_ns != t_ns || count == max) {
                if (r->t_ns < next) next = r->t_ns;
                break;
            }
            batch[count++] = r;
        }
        head_ = h;
        return count;
    }
    // Appends up to max records from the front to batch; returns how many.
    uint32_t take(Record* batch, uint32_t max) {
        uint32_t count = 0;
        const Record* ring = ring_.data();
        while (head_ != tail_ && count < max) batch[count++] = ring[head_++ & mask_];
        return count;
    }

    size_t capacity() const { return ring_.size(); }
    // Grows the ring to at least `capacity` entries (may throw std::bad_alloc).
    void reserve(size_t capacity) {
        size_t c = ring_.size();
        while (c < capacity) c <<= 1;
        if (c == ring_.size()) return;
        std::vector<Record> bigger(c);
        for (uint64_t i = head_; i < tail_; ++i) bigger[i & (c - 1)] = ring_[i & mask_];
        ring_.swap(bigger);
        mask_ = c - 1;
    }
    // Every record r becomes moved(r).
    template <class F>
    void repoint(F moved) {
        for (uint64_t i = head_; i < tail_; ++i) ring_[i & mask_] = moved(ring_[i & mask_]);
    }
    void clear() { head_ = tail_ = 0; }

private:
    std::vector<Record> ring_;
    uint64_t mask_ = 0;
    uint64_t head_ = 0, tail_ = 0;
};

}  // namespace pednav::engine

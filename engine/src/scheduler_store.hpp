// SPDX-License-Identifier: Apache-2.0
// Storing a record: copied into its queue (stamped with the queue's number
// unless it is the app's), then entered on every edge that reads its type,
// each reader's next forward time or pending feedback updated. Inline in the
// two places that store: the app's push (queue 0, Scheduler::push, inline in
// Engine::push) and the sink (queue k+1).
#pragma once

#include "scheduler.hpp"

namespace pednav::engine {

PEDNAV_ALWAYS_INLINE void Scheduler::store(RecordQueue& queue, const Route& route,
                                           const pn_record_header_t* r, uint32_t q) {
    if (queue.full()) grow_queue(static_cast<int>(q));  // the edges grow with it: none can be full
    pn_record_header_t* slot = queue.next_slot();
    copy_record(slot, r);
    if (q) slot->source_id = q;  // app records keep the app's
    queue.append();
    const int64_t t = r->t_ns;
    for (const Route::Forward *e = route.forward, *end = e + route.forward_count; e != end; ++e) {
        e->fifo->push(slot);
        if (t < *e->next_forward_t_ns) *e->next_forward_t_ns = t;
    }
    for (const Route::Feedback *e = route.feedback, *end = e + route.feedback_count; e != end; ++e) {
        e->fifo->push(slot);
        ++*e->feedback_pending;
    }
}

inline void Scheduler::push(const pn_record_header_t* r) {
    if (stopped_) return;
    if (flushed_) {
        for (auto& s : stages_) s->flushed = false;
        flushed_ = false;
    }
    ++records_in_;
    if (queue_wanted_[0] & PN_REC_MASK(r->type)) store(queues_[0], routes_[0][r->type], r, 0);
    // Release app records strictly before the newest time (see header); a
    // record at the same time as the previous one releases nothing new.
    if (r->t_ns > last_app_t_ns_) {
        app_limit_ns_ = r->t_ns - 1;
        last_app_t_ns_ = r->t_ns;
        drain();
    }
}

}  // namespace pednav::engine

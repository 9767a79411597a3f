// SPDX-License-Identifier: Apache-2.0
// The sink: what the engine does with each record a plugin emits. It checks
// the record (declared type, size, values, time order per type and over the
// stage's queue), copies it into the stage's queue and onto the edges of the
// stages that read its type, and into the output queue when the stage is the
// type's last producer and the app's mask selects it. Every refusal writes its
// reason into fixed storage: nothing here allocates but a queue or an edge
// that grows (which sink_emit catches).
#include <cstdio>
#include <new>

#include "record_checks.hpp"
#include "scheduler.hpp"
#include "scheduler_store.hpp"

namespace pednav::engine {

namespace {

double seconds(int64_t t_ns) { return static_cast<double>(t_ns) * 1e-9; }

}  // namespace

PEDNAV_ALWAYS_INLINE pn_status_t Scheduler::accept(Stage& s, const pn_record_header_t* r) {
    if (!r || r->type >= PN_REC_TYPE_COUNT) return refuse_record(s, r);
    const Stage::Emission& e = s.emits[r->type];
    // An undeclared type has min_size kUndeclared: refused by the first comparison.
    if (r->struct_size < e.min_size || r->struct_size > PN_RECORD_MAX_SIZE || !e.values_ok(r))
        return refuse_record(s, r);
    // Time order per type, whoever reads the type (a later stage or only the
    // app); and over every type the stage's queue holds, which later stages
    // merge by time.
    const int64_t t = r->t_ns;
    int64_t& last_of_type = s.last_emitted_t_ns[r->type];
    if (t < last_of_type || (e.queue && t < s.last_stored_t_ns)) return refuse_record(s, r);
    const uint32_t q = static_cast<uint32_t>(s.index + 1);
    if (e.queue) {
        s.last_stored_t_ns = t;
        store(*e.queue, *e.route, r, q);
    }
    last_of_type = t;
    if (e.to_output && (output_mask() & PN_REC_MASK(r->type)) && !outputs_.push(r, q)) warn_outputs_dropped();
    ++s.records_out;
    return PN_OK;
}

pn_status_t Scheduler::sink_emit(const pnp_sink_t* sink, const pn_record_header_t* record) noexcept {
    Stage* s = static_cast<Stage*>(sink->sink_data);
    try {
        return s->scheduler->accept(*s, record);
    } catch (const std::bad_alloc&) {  // a queue could not grow
        std::snprintf(s->sink_problem, sizeof s->sink_problem, "no memory to queue its output");
        return PN_E_OUT_OF_MEMORY;
    }
}

// Why accept() refused the record, in the order it checks: described in the
// stage's sink_problem and logged as misbehaviour.
pn_status_t Scheduler::refuse_record(Stage& s, const pn_record_header_t* r) {
    char* why = s.sink_problem;
    const size_t n = sizeof s.sink_problem;
    if (!r) {
        std::snprintf(why, n, "emitted a NULL record");
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    const Stage::Emission e = r->type < PN_REC_TYPE_COUNT ? s.emits[r->type] : Stage::Emission{};
    if (e.min_size == Stage::kUndeclared) {
        std::snprintf(why, n,
                      "emitted a record of type %u (%s) that its descriptor does not declare in produces",
                      r->type, record_type_name(r->type));
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    if (r->struct_size < e.min_size || r->struct_size > PN_RECORD_MAX_SIZE) {
        std::snprintf(why, n, "emitted a %s record with struct_size %u", record_type_name(r->type),
                      r->struct_size);
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    if (!e.values_ok(r)) {
        char value[128];
        format_value_problem(find_value_problem(r), value, sizeof value);
        std::snprintf(why, n, "emitted a %s record at t=%.6f s whose %s", record_type_name(r->type),
                      seconds(r->t_ns), value);
        return refuse(s, PN_E_NUMERIC);
    }
    const int64_t last_of_type = s.last_emitted_t_ns[r->type];
    if (r->t_ns < last_of_type) {
        std::snprintf(why, n, "emitted a %s record at t=%.6f s, before its previous %s at t=%.6f s",
                      record_type_name(r->type), seconds(r->t_ns), record_type_name(r->type),
                      seconds(last_of_type));
        return refuse(s, PN_E_OUT_OF_ORDER);
    }
    std::snprintf(why, n, "emitted a %s record at t=%.6f s, before its previous output at t=%.6f s",
                  record_type_name(r->type), seconds(r->t_ns), seconds(s.last_stored_t_ns));
    return refuse(s, PN_E_OUT_OF_ORDER);
}

pn_status_t Scheduler::refuse(Stage& s, pn_status_t status) {
    char line[320];
    std::snprintf(line, sizeof line, "misbehaving: %s", s.sink_problem);
    diagnostics_.warn(s.instance_name.c_str(), line);
    return status;
}

// An edge never holds more records than its queue, so edges as large as the
// queue never overflow. Room is made before anything moves: running out of
// memory leaves everything as it was.
void Scheduler::grow_queue(int q) {
    RecordQueue& queue = queues_[q];
    for (EdgeFifo* edge : readers_[q]) edge->reserve(2 * queue.capacity());
    const RecordQueue::Where before = queue.where();
    queue.grow();
    for (EdgeFifo* edge : readers_[q])
        edge->repoint([&](EdgeFifo::Record r) {
            return queue.at(RecordQueue::seq_of(reinterpret_cast<uintptr_t>(r), before));
        });
}

// A full output queue loses outputs the app has not polled: said at the 1st,
// 2nd, 4th, 8th ... drop so that a consumer that keeps falling behind is heard
// without one line per record.
void Scheduler::warn_outputs_dropped() noexcept {
    const uint64_t n = outputs_.dropped();
    if ((n & (n - 1)) != 0) return;
    char line[200];
    std::snprintf(line, sizeof line,
                  "the output queue is full (%zu records): %llu output%s dropped so far; poll more often or "
                  "raise output_queue_capacity",
                  outputs_.capacity(), static_cast<unsigned long long>(n), n == 1 ? "" : "s");
    diagnostics_.warn("engine", line);
}

}  // namespace pednav::engine

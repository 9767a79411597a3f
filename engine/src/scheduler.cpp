// SPDX-License-Identifier: Apache-2.0
#include "scheduler.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <new>

#include "record_checks.hpp"

namespace pednav::engine {

namespace {

constexpr int64_t kInf = INT64_MAX;
constexpr uint32_t kMaxBatch = 32;

int64_t saturating_sub(int64_t a, int64_t b) {
    if (a == kInf) return kInf;
    if (a == INT64_MIN) return INT64_MIN;
    return (b > 0 && a < INT64_MIN + b) ? INT64_MIN : a - b;
}

pn_status_t sink_emit(const pnp_sink_t* sink, const pn_record_header_t* record) noexcept {
    Stage* s = static_cast<Stage*>(sink->sink_data);
    try {
        return s->scheduler->accept(*s, record);
    } catch (const std::bad_alloc&) {  // a queue could not grow
        std::snprintf(s->sink_problem, sizeof s->sink_problem, "no memory to queue its output");
        return PN_E_OUT_OF_MEMORY;
    }
}

double seconds(int64_t t_ns) { return static_cast<double>(t_ns) * 1e-9; }

int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

void Stage::clear_segment() {
    flushed = false;
    last_stored_t_ns = INT64_MIN;
    last_input_t_ns = INT64_MIN;
    for (auto& t : last_emitted_t_ns) t = INT64_MIN;
    for (auto& in : forward) in.fifo.clear();
    for (auto& in : feedback) in.fifo.clear();
    next_forward_t_ns = kInf;
    feedback_pending = 0;
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

Scheduler::Scheduler(std::vector<std::unique_ptr<Stage>> stages, size_t output_capacity, Diagnostics& diagnostics)
    : stages_(std::move(stages)),
      outputs_(output_capacity),
      output_mask_(PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP)),
      diagnostics_(diagnostics) {
    for (size_t k = 0; k < stages_.size(); ++k) {
        Stage& s = *stages_[k];
        s.scheduler = this;
        s.index = static_cast<int>(k);
        s.sink.sink_data = &s;
        s.sink.emit = &sink_emit;
        s.clear_segment();
    }
    wire();
}

int64_t Scheduler::checked_latency(const Stage& s) const {
    if (!PNP_HAS_SLOT(s.ops, pnp_node_ops_t, latency_ns)) return 0;
    const int64_t l = s.ops->latency_ns(s.self);
    if (l < 0 || l > kMaxLatencyNs) {
        char msg[200];
        std::snprintf(msg, sizeof msg, "%s (%s) declares a look-ahead of %.9g s, outside [0, %.0f] s",
                      s.instance_name.c_str(), s.plugin_id.c_str(), static_cast<double>(l) * 1e-9,
                      static_cast<double>(kMaxLatencyNs) * 1e-9);
        throw ConfigProblem{PN_E_INVALID_CONFIG, s.pointer, msg};
    }
    return l;
}

void Scheduler::wire() {
    const size_t n = stages_.size();
    queues_.assign(n + 1, RecordQueue(64));
    queue_wanted_.assign(n + 1, 0);
    routes_.assign(n + 1, {});
    readers_.assign(n + 1, {});
    for (size_t k = 0; k < n; ++k) {
        Stage& s = *stages_[k];
        const uint64_t consumes = s.descriptor->consumes;
        if (uint64_t m = consumes & kInputTypes) s.forward.push_back({0, m, EdgeFifo()});
        for (size_t i = 0; i < n; ++i) {
            if (i == k) continue;
            const uint64_t m = consumes & stages_[i]->descriptor->produces;
            if (!m) continue;
            (i < k ? s.forward : s.feedback).push_back({static_cast<int>(i + 1), m, EdgeFifo()});
        }
    }
    // The edges are in place (the vectors no longer move): route each type of
    // each queue to the edges that read it, in stage order.
    for (size_t k = 0; k < n; ++k) {
        Stage& s = *stages_[k];
        for (int feedback = 0; feedback < 2; ++feedback) {
            for (auto& in : feedback ? s.feedback : s.forward) {
                queue_wanted_[in.queue] |= in.mask;
                readers_[in.queue].push_back(&in.fifo);
                for (pn_record_type_t t = 0; t < PN_REC_TYPE_COUNT; ++t) {
                    if (!(in.mask & PN_REC_MASK(t))) continue;
                    Route& route = routes_[in.queue][t];
                    route.readers[route.count++] = Route::Reader{&in.fifo, &s, feedback == 1};
                }
            }
        }
    }
    // The last producer of each type feeds the output queue.
    uint64_t seen = 0;
    for (size_t k = n; k-- > 0;) {
        const uint64_t p = stages_[k]->descriptor->produces;
        final_producer_mask_[k] = p & ~seen;
        seen |= p;
    }
    for (size_t k = 0; k < n; ++k) {
        Stage& s = *stages_[k];
        for (pn_record_type_t t = 0; t < PN_REC_TYPE_COUNT; ++t) {
            const uint64_t bit = PN_REC_MASK(t);
            if (!(s.descriptor->produces & bit)) continue;
            s.emits[t] = Stage::Emission{min_record_size(t), (queue_wanted_[k + 1] & bit) != 0,
                                         (final_producer_mask_[k] & bit) != 0};
        }
    }
    for (auto& s : stages_) s->latency_ns = checked_latency(*s);
}

void Scheduler::store(int q, const pn_record_header_t* r) {
    RecordQueue& queue = queues_[q];
    const Route& route = routes_[q][r->type];
    // Room first, so that nothing is stored halfway when memory runs out.
    queue.make_room();
    for (uint32_t i = 0; i < route.count; ++i) route.readers[i].fifo->make_room();
    const RecordQueue::Seq seq = queue.push(r);
    if (q) queue.at(seq)->source_id = static_cast<uint32_t>(q);  // app records keep the app's
    const int64_t t = r->t_ns;
    for (uint32_t i = 0; i < route.count; ++i) {
        const Route::Reader& reader = route.readers[i];
        reader.fifo->push(t, seq);
        if (reader.feedback) {
            ++reader.stage->feedback_pending;
        } else if (t < reader.stage->next_forward_t_ns) {
            reader.stage->next_forward_t_ns = t;
        }
    }
}

int64_t Scheduler::latency_ns() const {
    int64_t sum = 0;
    for (const auto& s : stages_) sum += s->latency_ns;
    return sum;
}

pn_status_t Scheduler::refuse(Stage& s, pn_status_t status) {
    char line[320];
    std::snprintf(line, sizeof line, "misbehaving: %s", s.sink_problem);
    diagnostics_.warn(s.instance_name.c_str(), line);
    return status;
}

// The sink. Every check writes its reason into fixed storage: nothing here
// allocates but a queue that grows (which sink_emit catches).
pn_status_t Scheduler::accept(Stage& s, const pn_record_header_t* r) {
    char* why = s.sink_problem;
    const size_t n = sizeof s.sink_problem;
    if (!r) {
        std::snprintf(why, n, "emitted a NULL record");
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    const Stage::Emission e = r->type < PN_REC_TYPE_COUNT ? s.emits[r->type] : Stage::Emission{};
    if (e.min_size == 0) {
        std::snprintf(why, n, "emitted a record of type %u (%s) that its descriptor does not declare in produces",
                      r->type, record_type_name(r->type));
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    if (r->struct_size < e.min_size || r->struct_size > PN_RECORD_MAX_SIZE) {
        std::snprintf(why, n, "emitted a %s record with struct_size %u", record_type_name(r->type), r->struct_size);
        return refuse(s, PN_E_INVALID_ARGUMENT);
    }
    if (!record_values_ok(r)) {
        char value[128];
        format_value_problem(find_value_problem(r), value, sizeof value);
        std::snprintf(why, n, "emitted a %s record at t=%.6f s whose %s", record_type_name(r->type), seconds(r->t_ns),
                      value);
        return refuse(s, PN_E_NUMERIC);
    }
    // Time order per type, whoever reads the type (a later stage or only the
    // app); and over every type the stage's queue holds, which later stages
    // merge by time.
    int64_t& last_of_type = s.last_emitted_t_ns[r->type];
    if (r->t_ns < last_of_type) {
        std::snprintf(why, n, "emitted a %s record at t=%.6f s, before its previous %s at t=%.6f s",
                      record_type_name(r->type), seconds(r->t_ns), record_type_name(r->type), seconds(last_of_type));
        return refuse(s, PN_E_OUT_OF_ORDER);
    }
    const int q = s.index + 1;
    if (e.stored) {
        if (r->t_ns < s.last_stored_t_ns) {
            std::snprintf(why, n, "emitted a %s record at t=%.6f s, before its previous output at t=%.6f s",
                          record_type_name(r->type), seconds(r->t_ns), seconds(s.last_stored_t_ns));
            return refuse(s, PN_E_OUT_OF_ORDER);
        }
        s.last_stored_t_ns = r->t_ns;
        store(q, r);
    }
    last_of_type = r->t_ns;
    if (e.to_output && (output_mask() & PN_REC_MASK(r->type)) && !outputs_.push(r, static_cast<uint32_t>(q)))
        warn_outputs_dropped();
    ++s.records_out;
    return PN_OK;
}

void Scheduler::push(const pn_record_header_t* r) {
    if (stopped_) return;
    if (flushed_) {
        for (auto& s : stages_) s->flushed = false;
        flushed_ = false;
    }
    ++records_in_;
    if (queue_wanted_[0] & PN_REC_MASK(r->type)) store(0, r);
    // Release app records strictly before the newest time (see header); a
    // record at the same time as the previous one releases nothing new.
    if (r->t_ns > last_app_t_ns_) {
        app_limit_ns_ = r->t_ns - 1;
        last_app_t_ns_ = r->t_ns;
        drain();
    }
}

void Scheduler::flush() {
    app_limit_ns_ = kInf;
    drain();
    for (auto& s : stages_) {
        if (stopped_) break;
        if (PNP_HAS_SLOT(s->ops, pnp_node_ops_t, flush)) call_flush(*s);
        s->flushed = true;
        flushed_ = true;
        drain();
    }
    app_limit_ns_ = last_app_t_ns_;  // later pushes must come after the flushed data
}

pn_status_t Scheduler::reset(pn_error_t* err) {
    for (auto& s : stages_) {
        const pn_status_t st = s->ops->reset(s->self, err);
        if (PN_FAILED(st)) return st;
        s->clear_segment();
    }
    for (auto& q : queues_) q = RecordQueue(q.capacity());
    for (auto& s : stages_) {
        const int64_t l = PNP_HAS_SLOT(s->ops, pnp_node_ops_t, latency_ns) ? s->ops->latency_ns(s->self) : 0;
        if (l != s->latency_ns) {  // the contract: fixed from create to destroy
            char msg[160];
            std::snprintf(msg, sizeof msg, "misbehaving: its look-ahead changed across reset (%.9g s to %.9g s); kept %.9g s",
                          static_cast<double>(s->latency_ns) * 1e-9, static_cast<double>(l) * 1e-9,
                          static_cast<double>(s->latency_ns) * 1e-9);
            diagnostics_.warn(s->instance_name.c_str(), msg);
        }
    }
    outputs_.clear();
    flushed_ = false;
    app_limit_ns_ = INT64_MIN;
    last_app_t_ns_ = INT64_MIN;
    failure_ = StageFailure{};
    stopped_ = false;
    stop_reason_ = StageFailure{};
    return PN_OK;
}

StageFailure Scheduler::take_failure() {
    StageFailure f = failure_;
    failure_ = StageFailure{};
    return f;
}

bool Scheduler::deliver_feedback(Stage& s) {
    for (auto& in : s.feedback) {
        if (in.fifo.empty()) continue;
        const RecordQueue& q = queues_[in.queue];
        const pn_record_header_t* batch[kMaxBatch];
        uint32_t count = 0;
        while (!in.fifo.empty() && count < kMaxBatch) {
            batch[count++] = q.at(in.fifo.front().seq);
            in.fifo.pop();
        }
        s.feedback_pending -= count;
        call_process(s, batch, count);
        return true;
    }
    return false;
}

void Scheduler::deliver_forward(Stage& s, int64_t t_ns) {
    // Every record at t_ns, app inputs first, then earlier stages in order.
    const pn_record_header_t* batch[kMaxBatch];
    uint32_t count = 0;
    int64_t next = kInf;
    for (auto& in : s.forward) {
        const RecordQueue& q = queues_[in.queue];
        while (count < kMaxBatch && !in.fifo.empty() && in.fifo.front().t_ns == t_ns) {
            batch[count++] = q.at(in.fifo.front().seq);
            in.fifo.pop();
        }
        if (!in.fifo.empty()) next = std::min(next, in.fifo.front().t_ns);
    }
    s.next_forward_t_ns = next;
    s.last_input_t_ns = t_ns;
    call_process(s, batch, count);
}

void Scheduler::call_process(Stage& s, const pn_record_header_t* const* records, uint32_t count) {
    s.records_in += count;
    pn_error_t err;
    err.struct_size = sizeof err;
    err.code = PN_OK;
    err.where[0] = err.message[0] = '\0';
    pn_status_t st;
    if (s.call_budget_ns) {
        const int64_t t0 = now_ns();
        st = s.ops->process(s.self, records, count, &s.sink, &err);
        check_budget(s, now_ns() - t0, "process");
    } else {
        st = s.ops->process(s.self, records, count, &s.sink, &err);
    }
    if (PN_FAILED(st)) report_failure(s, st, err, "process");
}

void Scheduler::call_flush(Stage& s) {
    pn_error_t err{};
    err.struct_size = sizeof err;
    const int64_t t0 = s.call_budget_ns ? now_ns() : 0;
    const pn_status_t st = s.ops->flush(s.self, &s.sink, &err);
    if (s.call_budget_ns) check_budget(s, now_ns() - t0, "flush");
    if (PN_FAILED(st)) report_failure(s, st, err, "flush");
}

// A call slower than the stage's call_budget_ms: a warning (the first, then
// at the 2nd, 4th, 8th, ... overrun, so a slow plugin cannot flood the log),
// or, with over_budget "stop", a failure that stops the pipeline.
void Scheduler::check_budget(Stage& s, int64_t took_ns, const char* during) {
    s.slowest_call_ns = std::max(s.slowest_call_ns, took_ns);
    if (took_ns <= s.call_budget_ns) return;
    const uint64_t n = ++s.calls_over_budget;
    char msg[256];
    std::snprintf(msg, sizeof msg, "(%s) took %.3f ms in %s, over its call_budget_ms of %.3f ms (%llu call%s over budget)",
                  s.plugin_id.c_str(), static_cast<double>(took_ns) * 1e-6, during,
                  static_cast<double>(s.call_budget_ns) * 1e-6, static_cast<unsigned long long>(n), n == 1 ? "" : "s");
    if (s.over_budget == OverBudget::stop) {
        if (stopped_) return;
        ++s.failures;
        const std::string text = s.instance_name + " " + msg + "; over_budget is \"stop\": the pipeline is stopped";
        diagnostics_.note(PNP_LOG_ERROR, s.instance_name.c_str(), text.c_str() + s.instance_name.size() + 1);
        if (failure_.status == PN_OK) failure_ = StageFailure{PN_E_BAD_STATE, s.instance_name, text};
        stop(s, PN_E_BAD_STATE, text);
    } else if ((n & (n - 1)) == 0) {
        diagnostics_.warn(s.instance_name.c_str(), msg);
    }
}

void Scheduler::stop(const Stage& s, pn_status_t status, const std::string& message) {
    stopped_ = true;
    stop_reason_ = StageFailure{status, s.instance_name, message};
}

void Scheduler::report_failure(Stage& s, pn_status_t status, const pn_error_t& err, const char* during) {
    ++s.failures;
    std::string msg = "(" + s.plugin_id + ") failed in " + during + ": ";
    msg += err.message[0] ? err.message : "no message";
    if (s.sink_problem[0]) msg += std::string("; the engine refused its output: ") + s.sink_problem;
    s.sink_problem[0] = '\0';
    bool stop_now = s.on_failure == OnFailure::stop;
    if (stop_now) {
        msg += "; on_failure is \"stop\": the pipeline is stopped until pn_engine_reset";
    } else if (status == PN_E_NUMERIC || status == PN_E_INTERNAL) {
        pn_error_t reset_err{};
        reset_err.struct_size = sizeof reset_err;
        if (!PN_FAILED(s.ops->reset(s.self, &reset_err))) {
            ++s.resets;
            msg += " (the instance was reset)";
        } else {
            msg += std::string("; its reset failed too (") + (reset_err.message[0] ? reset_err.message : "no message") +
                   "): the pipeline is stopped";
            stop_now = true;  // an instance that cannot be reset is not called again
        }
    }
    diagnostics_.note(PNP_LOG_ERROR, s.instance_name.c_str(), msg.c_str());
    const std::string text = s.instance_name + " " + msg;
    if (failure_.status == PN_OK) failure_ = StageFailure{status, s.instance_name, text};
    if (stop_now && !stopped_) stop(s, status, text);
}

void Scheduler::drain() {
    if (!stages_.empty()) drain_from(0, app_limit_ns_);
    if ((++drains_ & 63) == 0 || app_limit_ns_ == kInf) release_consumed();
}

// Depth first: before stage k takes its next record, every stage below it
// consumes what has become available to it. So a stage consumes sample n
// before any zero-latency stage above it sees sample n+1, and feedback sent
// up while processing sample n is delivered before the receiver's next record.
// A stage below with nothing to do is not entered (has_work): the calls made
// are those of the full recursion.
void Scheduler::drain_from(size_t k, int64_t limit) {
    Stage& s = *stages_[k];
    const bool last = k + 1 == stages_.size();
    for (;;) {
        if (stopped_) return;
        const bool had_feedback = s.feedback_pending && deliver_feedback(s);
        const int64_t t = s.next_forward_t_ns <= limit ? s.next_forward_t_ns : kInf;
        if (!last) {
            // A zero-latency (or flushed) stage has emitted everything about
            // the times before its next input; a stage with look-ahead L only
            // what is about its newest consumed input time minus L.
            const int64_t below = (s.flushed || s.latency_ns == 0) ? (t == kInf ? limit : t - 1)
                                                                   : saturating_sub(s.last_input_t_ns, s.latency_ns);
            if (has_work(k + 1, below)) drain_from(k + 1, below);
        }
        if (t == kInf) {
            if (had_feedback || s.feedback_pending) continue;
            return;
        }
        deliver_forward(s, t);
    }
}

bool Scheduler::has_work(size_t k, int64_t limit) const {
    for (; k < stages_.size(); ++k) {
        const Stage& s = *stages_[k];
        if (s.feedback_pending || s.next_forward_t_ns <= limit) return true;
        // Nothing within the limit: what the stage passes on, as drain_from would.
        if (!s.flushed && s.latency_ns != 0) limit = saturating_sub(s.last_input_t_ns, s.latency_ns);
    }
    return false;
}

void Scheduler::release_consumed() {
    for (size_t q = 0; q < queues_.size(); ++q) {
        RecordQueue::Seq oldest_unread = queues_[q].end();
        for (const EdgeFifo* edge : readers_[q])
            if (!edge->empty()) oldest_unread = std::min(oldest_unread, edge->front().seq);
        queues_[q].release_until(oldest_unread);
    }
}

}  // namespace pednav::engine

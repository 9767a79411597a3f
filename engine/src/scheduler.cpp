// SPDX-License-Identifier: Apache-2.0
#include "scheduler.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "record_checks.hpp"
#include "scheduler_store.hpp"

namespace pednav::engine {

namespace {

constexpr int64_t kInf = INT64_MAX;
constexpr uint32_t kMaxBatch = 32;

int64_t saturating_sub(int64_t a, int64_t b) {
    if (a == kInf) return kInf;
    if (a == INT64_MIN) return INT64_MIN;
    return (b > 0 && a < INT64_MIN + b) ? INT64_MIN : a - b;
}

int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

void Stage::clear_segment() {
    flushed = false;
    last_stored_t_ns = INT64_MIN;
    last_input_t_ns = INT64_MIN;
    decided_until_t_ns = INT64_MIN;
    for (auto& t : last_emitted_t_ns) t = INT64_MIN;
    for (auto& in : forward) in.fifo.clear();
    for (auto& in : feedback) in.fifo.clear();
    next_forward_t_ns = kInf;
    feedback_pending = 0;
}

Scheduler::Scheduler(std::vector<std::unique_ptr<Stage>> stages, size_t output_capacity, Diagnostics& diagnostics)
    : stages_(std::move(stages)),
      outputs_(output_capacity),
      output_mask_(PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP)),
      diagnostics_(diagnostics) {
    if (stages_.size() > static_cast<size_t>(kRoleCount))  // one per role, by the config's construction
        throw ConfigProblem{PN_E_INTERNAL, "pipeline", "more stages than roles"};
    for (size_t k = 0; k < stages_.size(); ++k) {
        Stage& s = *stages_[k];
        s.scheduler = this;
        s.index = static_cast<int>(k);
        s.sink.sink_data = &s;
        s.sink.emit = &Scheduler::sink_emit;
        s.process = s.ops->process;
        s.clear_segment();
        stage_at_[k] = &s;
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
                    if (feedback)
                        route.feedback[route.feedback_count++] =
                            Route::Feedback{&in.fifo, &s.feedback_pending};
                    else
                        route.forward[route.forward_count++] = Route::Forward{&in.fifo, &s.next_forward_t_ns};
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
            if (!(s.descriptor->produces & bit) || !min_record_size(t)) continue;
            Stage::Emission& e = s.emits[t];
            e.min_size = min_record_size(t);
            e.to_output = (final_producer_mask_[k] & bit) != 0;
            e.values_ok = values_check_for(t);
            if (queue_wanted_[k + 1] & bit) {
                e.queue = &queues_[k + 1];
                e.route = &routes_[k + 1][t];
            }
        }
    }
    for (auto& s : stages_) s->latency_ns = checked_latency(*s);
}

int64_t Scheduler::latency_ns() const {
    int64_t sum = 0;
    for (const auto& s : stages_) sum += s->latency_ns;
    return sum;
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

// One batch of feedback, from the first feedback edge that has any.
PEDNAV_ALWAYS_INLINE void Scheduler::deliver_feedback(Stage& s) {
    const pn_record_header_t* batch[kMaxBatch];
    for (auto& in : s.feedback) {
        if (in.fifo.empty()) continue;
        const uint32_t count = in.fifo.take(batch, kMaxBatch);
        s.feedback_pending -= count;
        call_process(s, batch, count);
        return;
    }
}

// Every record at t_ns, app inputs first, then earlier stages in order.
PEDNAV_ALWAYS_INLINE void Scheduler::deliver_forward(Stage& s, int64_t t_ns) {
    const pn_record_header_t* batch[kMaxBatch];
    uint32_t count = 0;
    int64_t next = kInf;
    for (Stage::Input* in = s.forward.data(), *end = in + s.forward.size(); in != end; ++in)
        count = in->fifo.take_at(t_ns, batch, count, kMaxBatch, next);
    s.next_forward_t_ns = next;
    s.last_input_t_ns = t_ns;
    if (s.latency_ns) s.decided_until_t_ns = saturating_sub(t_ns, s.latency_ns);  // else never read
    call_process(s, batch, count);
}

PEDNAV_ALWAYS_INLINE void Scheduler::call_process(Stage& s, const pn_record_header_t* const* records,
                                                  uint32_t count) {
    s.records_in += count;
    pn_error_t err;
    err.struct_size = sizeof err;
    err.code = PN_OK;
    err.where[0] = err.message[0] = '\0';
    if (s.call_budget_ns) return call_process_timed(s, records, count, err);
    const pn_status_t st = s.process(s.self, records, count, &s.sink, &err);
    if (PN_FAILED(st)) report_failure(s, st, err, "process");
}

void Scheduler::call_process_timed(Stage& s, const pn_record_header_t* const* records, uint32_t count,
                                   pn_error_t& err) {
    const int64_t t0 = now_ns();
    const pn_status_t st = s.process(s.self, records, count, &s.sink, &err);
    check_budget(s, now_ns() - t0, "process");
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
    switch (stages_.size()) {  // the depth is fixed at create: each one compiled with its levels unrolled
        case 1: drain_level<0, 1>(app_limit_ns_); break;
        case 2: drain_level<0, 2>(app_limit_ns_); break;
        case 3: drain_level<0, 3>(app_limit_ns_); break;
        case 4: drain_level<0, 4>(app_limit_ns_); break;
        default: break;
    }
    if ((++drains_ & 63) == 0 || app_limit_ns_ == kInf) release_consumed();
}

// Depth first: before stage K takes its next record, every stage below it
// consumes what has become available to it. So a stage consumes sample n
// before any zero-latency stage above it sees sample n+1, and feedback sent
// up while processing sample n is delivered before the receiver's next record.
// A stage below with nothing to do is not entered (has_work): the calls made
// are those of the full recursion, in its order.
template <int K, int N>
PEDNAV_ALWAYS_INLINE void Scheduler::drain_level(int64_t limit) {
    Stage& s = *stage_at_[K];
    // A zero-latency (or flushed) stage has emitted everything about the
    // times before its next input; a stage with look-ahead L only what is
    // about its newest consumed input time minus L. (Neither changes while
    // the pipeline drains.)
    const bool passes_limit = s.flushed || s.latency_ns == 0;
    for (;;) {
        if (stopped_) return;
        if (s.feedback_pending) deliver_feedback(s);  // then some feedback edge has records
        const int64_t t = s.next_forward_t_ns <= limit ? s.next_forward_t_ns : kInf;
        if constexpr (K + 1 < N) {
            const int64_t below = passes_limit ? (t == kInf ? limit : t - 1) : s.decided_until_t_ns;
            if (has_work<K + 1, N>(below)) drain_level<K + 1, N>(below);
        }
        if (t == kInf) {
            // The full recursion also goes round once more after delivering
            // feedback; that round calls nothing: no forward record can have
            // come (only earlier stages feed this one), and the stages below
            // are as the round before left them.
            if (s.feedback_pending) continue;
            return;
        }
        deliver_forward(s, t);
    }
}

// Whether drain_level<K, N>(limit) would call a plugin: stage K or one below
// it has feedback, or a forward record within the limit its upstream passes on.
template <int K, int N>
bool Scheduler::has_work(int64_t limit) const {
    const Stage& s = *stage_at_[K];
    if (s.feedback_pending || s.next_forward_t_ns <= limit) return true;
    if constexpr (K + 1 < N) {
        // Nothing within the limit: what the stage passes on, as drain_level would.
        if (!s.flushed && s.latency_ns != 0) limit = s.decided_until_t_ns;
        return has_work<K + 1, N>(limit);
    }
    return false;
}

void Scheduler::release_consumed() {
    for (size_t q = 0; q < queues_.size(); ++q) {
        RecordQueue::Seq oldest_unread = queues_[q].end();
        for (const EdgeFifo* edge : readers_[q])
            if (!edge->empty()) oldest_unread = std::min(oldest_unread, queues_[q].seq_of(edge->front()));
        queues_[q].release_until(oldest_unread);
    }
}

}  // namespace pednav::engine

// SPDX-License-Identifier: Apache-2.0
// Streams records through the stages of one pipeline, sample by sample, in
// timestamp order. See docs/scheduler.md for the rules; in short:
//
//   - Queue 0 holds the app's inputs, queue k+1 the outputs of stage k. Stage k
//     reads, merged by time, queue 0 and the queues of earlier stages,
//     restricted to the record types it consumes (forward edges), and the
//     queues of later stages for the types it consumes from them (feedback
//     edges, delivered before its next forward record).
//   - Look-ahead: a stage declaring latency L has emitted every output about
//     time t once it has consumed an input at t + L. Stage k+1 may only read
//     records up to limit(k+1) = newest input of stage k - L(k), so downstream
//     stages see a sample and the decisions about it together; a stage without
//     look-ahead passes on the limit of the stage above it, up to its next
//     pending input. Output latency = sum of L.
//   - Lock-step: the deepest stage with work goes first, so a stage consumes
//     sample n before any zero-latency stage upstream of it sees sample n+1;
//     feedback emitted at sample n therefore applies from sample n+1.
//   - Every edge (a stage reading some types of one queue) has its own FIFO
//     of the records it carries, filled when a record is stored; each stage
//     keeps the time of its next forward record and a count of its pending
//     feedback, so finding work never scans records.
//   - App inputs at the newest pushed time are held back until a later time is
//     pushed (or flush), so equal-time records are ordered the same however
//     the app batches its pushes: the output is bit-identical for the same input.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pednav/pn_plugin.h>

#include "config.hpp"
#include "diagnostics.hpp"
#include "edge_fifo.hpp"
#include "output_queue.hpp"
#include "record_checks.hpp"
#include "record_queue.hpp"

// The per-record path is a few calls deep; these are inlined into it.
#if defined(__GNUC__)
#define PEDNAV_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define PEDNAV_ALWAYS_INLINE inline
#endif

namespace pednav::engine {

class Scheduler;

// Where a record of one type from one queue goes: the edges that carry it,
// forward ones (whose reader's next forward time it may advance) and feedback
// ones (whose reader's pending count it raises).
struct Route {
    struct Forward {
        EdgeFifo* fifo;
        int64_t* next_forward_t_ns;  // the reader's
    };
    struct Feedback {
        EdgeFifo* fifo;
        uint32_t* feedback_pending;  // the reader's
    };
    Forward forward[kRoleCount];
    Feedback feedback[kRoleCount];
    uint32_t forward_count = 0, feedback_count = 0;
};

// One plugin instance in the pipeline. It owns the instance: destroying the
// Stage destroys it, so no path (a constructor that throws halfway included)
// can leak one.
struct Stage {
    Stage() = default;
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;
    ~Stage() {
        if (self) ops->destroy(self);
    }

    Role role;
    std::string instance_name;  // "foot/step_detector"
    std::string plugin_id;
    std::string pointer;        // its place in the config: "/pipelines/foot/step_detector"
    const pnp_descriptor_t* descriptor = nullptr;
    const pnp_node_ops_t* ops = nullptr;
    void* self = nullptr;
    decltype(pnp_node_ops_t::process) process = nullptr;  // ops->process
    int64_t latency_ns = 0;

    // What the config says to do when it fails or is slow (config.hpp).
    OnFailure on_failure = OnFailure::reset;
    int64_t call_budget_ns = 0;  // 0 = no budget
    OverBudget over_budget = OverBudget::warn;

    // Wiring, filled by Scheduler::wire(): the edges into this stage.
    struct Input {
        int queue;
        uint64_t mask;
        EdgeFifo fifo;  // the records of `mask` from `queue` not yet delivered
    };
    std::vector<Input> forward;
    std::vector<Input> feedback;
    // What the sink does with each record type the stage produces.
    static constexpr uint32_t kUndeclared = UINT32_MAX;  // min_size of a type the stage does not produce
    struct Emission {
        uint32_t min_size = kUndeclared;  // smallest struct_size accepted
        bool to_output =
            false;  // the stage is the type's last producer: to the output queue (if in the mask)
        ValuesCheck values_ok = nullptr;  // record_values_ok for the type
        RecordQueue* queue = nullptr;     // the stage's queue, when some stage reads the type; else nullptr
        const Route* route = nullptr;     // then the edges of the type in that queue
    };
    Emission emits[PN_REC_TYPE_COUNT];

    // State of the current segment.
    bool flushed = false;
    int64_t next_forward_t_ns = INT64_MAX;  // oldest record in the forward edges
    uint32_t feedback_pending = 0;          // records in the feedback edges
    int64_t last_stored_t_ns = INT64_MIN;  // newest record put into its queue
    int64_t last_emitted_t_ns[PN_REC_TYPE_COUNT];  // newest accepted record per type
    int64_t last_input_t_ns = INT64_MIN;  // newest forward record consumed
    int64_t decided_until_t_ns =
        INT64_MIN;  // last_input_t_ns - latency_ns: everything about times to here is out
    // Why the sink last refused a record. Fixed storage: the sink runs inside
    // noexcept plugin calls and must not allocate to describe a refusal.
    char sink_problem[256] = {};

    // Counters.
    uint64_t records_in = 0, records_out = 0, failures = 0, resets = 0;
    uint64_t calls_over_budget = 0;
    int64_t slowest_call_ns = 0;  // measured only with a budget

    // What the plugin gets: host.host_data points at the context, sink_data
    // back here.
    HostContext host_context;
    pnp_sink_t sink{};
    Scheduler* scheduler = nullptr;
    int index = 0;

    void clear_segment();  // back to the state of a new segment
};

struct StageFailure {
    pn_status_t status = PN_OK;
    std::string where;    // instance name
    std::string message;
};

class Scheduler {
public:
    // Takes the created stages in role order (at most one per role) and the
    // output queue's capacity (0 = the default). set_output_mask selects the
    // types copied to the output queue, from the last stage producing each type.
    // Throws ConfigProblem when a stage declares a look-ahead outside
    // [0, kMaxLatencyNs]; the stages (and so the instances) are destroyed then.
    Scheduler(std::vector<std::unique_ptr<Stage>> stages, size_t output_capacity, Diagnostics& diagnostics);

    static constexpr int64_t kMaxLatencyNs = 60'000'000'000;  // 60 s per stage

    // Appends one validated app record and processes whatever became ready.
    void push(const pn_record_header_t* record);
    // Drains every stage's look-ahead (end of stream).
    void flush();
    // Resets every plugin and empties the queues.
    pn_status_t reset(pn_error_t* err);

    // The first stage failure since the last call, and clears it.
    StageFailure take_failure();
    bool has_failure() const { return failure_.status != PN_OK; }
    // A stage whose policy is "stop" failed (or overran its budget): nothing
    // is processed until reset(). stop_reason() says who and why.
    bool stopped() const { return stopped_; }
    const StageFailure& stop_reason() const { return stop_reason_; }

    // Atomic: the mask may be set from any thread while records flow.
    void set_output_mask(uint64_t mask) { output_mask_.store(mask, std::memory_order_relaxed); }
    uint64_t output_mask() const { return output_mask_.load(std::memory_order_relaxed); }
    OutputQueue& outputs() { return outputs_; }
    const OutputQueue& outputs() const { return outputs_; }
    int64_t latency_ns() const;
    const std::vector<std::unique_ptr<Stage>>& stages() const { return stages_; }
    uint64_t records_in() const { return records_in_; }

    // The sink (stage_sink.cpp): checks a plugin's record and stores it.
    pn_status_t accept(Stage& stage, const pn_record_header_t* record);

private:
    static pn_status_t sink_emit(const pnp_sink_t* sink, const pn_record_header_t* record) noexcept;
    pn_status_t refuse_record(Stage& s, const pn_record_header_t* r);  // says why accept() refused r
    pn_status_t refuse(Stage& s, pn_status_t status);                  // logs s.sink_problem as misbehaviour
    void warn_outputs_dropped() noexcept;

    void wire();
    // Copies a record into queue number q and onto the edges that read its
    // type there (route).
    void store(RecordQueue& queue, const Route& route, const pn_record_header_t* r, uint32_t q);
    void grow_queue(int q);  // and re-points the edges into it
    void drain();
    template <int K, int N>
    void drain_level(int64_t limit);
    template <int K, int N>
    bool has_work(int64_t limit) const;
    void deliver_feedback(Stage& s);
    void deliver_forward(Stage& s, int64_t t_ns);
    void call_process(Stage& s, const pn_record_header_t* const* records, uint32_t count);
    void call_process_timed(Stage& s, const pn_record_header_t* const* records, uint32_t count,
                            pn_error_t& err);
    void call_flush(Stage& s);
    void report_failure(Stage& s, pn_status_t status, const pn_error_t& err, const char* during);
    void check_budget(Stage& s, int64_t took_ns, const char* during);
    void stop(const Stage& s, pn_status_t status, const std::string& message);
    void release_consumed();
    int64_t checked_latency(const Stage& s) const;

    std::vector<std::unique_ptr<Stage>> stages_;
    Stage* stage_at_[kRoleCount] = {};     // stages_[k].get()
    std::vector<RecordQueue> queues_;      // 0 = app, k+1 = stage k
    std::vector<uint64_t> queue_wanted_;   // union of reader masks per queue
    std::vector<std::array<Route, PN_REC_TYPE_COUNT>> routes_;  // per queue, per type
    std::vector<std::vector<EdgeFifo*>> readers_;               // per queue: every edge reading it
    bool flushed_ = false;                                      // some stage has flushed since the last push
    uint64_t final_producer_mask_[kRoleCount] = {};  // per stage: types it is the last producer of
    OutputQueue outputs_;
    std::atomic<uint64_t> output_mask_;
    int64_t app_limit_ns_ = INT64_MIN;     // app records up to here are released
    int64_t last_app_t_ns_ = INT64_MIN;
    uint64_t records_in_ = 0;
    uint64_t drains_ = 0;
    StageFailure failure_;
    bool stopped_ = false;
    StageFailure stop_reason_;
    Diagnostics& diagnostics_;
};

}  // namespace pednav::engine

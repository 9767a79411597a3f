// SPDX-License-Identifier: Apache-2.0
// TimeJoin<Records...>: gathers the records of several types that describe
// the same sample time, and hands them to the plugin together.
//
// A position filter that consumes IMU, GAIT_PHASE and ATTITUDE records needs
// all three about one IMU sample before it can step. The scheduler delivers
// the records of one time together, in time order (docs/scheduler.md), but a
// stream may be absent (a pipeline without a step detector has no gait
// phase) or may not cover every sample (an attitude estimator still
// aligning). Feed every record of the joined types to add() and the join
// calls on_sample(const Sample&) once per sample time:
//
//   - as soon as a record of every type is in for that time, from the add()
//     of the last one (any order of arrival within the time);
//   - otherwise, with what has arrived, when a record of a later time
//     arrives (before that record is taken in), or when a second record of
//     a type already held arrives for the same time, or at flush().
//
// So a sample waits for a missing stream only until the stream has had its
// chance: the next sample's first record, or the end of the stream. Records
// older than the latest sample (pending or released), which the scheduler
// never delivers, are dropped and counted (late_records()). A released
// sample is consumed even when on_sample throws: the exception leaves add()
// or flush(), and the record being added is dropped with it. on_sample must
// not add to the join it was called from.
//
//   class MyFilter : public pednav::sdk::PositionFilter {
//       using Join = pednav::sdk::TimeJoin<pn_imu_t, pn_gait_phase_t, pn_attitude_t>;
//   public:
//       static constexpr uint64_t kConsumes = Join::kRecordMask;
//       void on_imu(const pn_imu_t& r) override { join_.add(r, step()); }
//       void on_gait_phase(const pn_gait_phase_t& r) override { join_.add(r, step()); }
//       void on_attitude(const pn_attitude_t& r) override { join_.add(r, step()); }
//       void on_flush() override { join_.flush(step()); }
//   private:
//       auto step() {
//           return [this](const Join::Sample& s) {
//               const pn_attitude_t* att = s.get<pn_attitude_t>();  // nullptr when absent
//               ...
//           };
//       }
//       Join join_;
//   };
//
// No allocation: the join holds one record of each type. Not thread-safe
// (one instance per node, as every node is).
#pragma once

#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>

#include <pednav/pn_types.h>

#include "node.hpp"

namespace pednav::sdk {

template <class... Records>
class TimeJoin {
    static_assert(sizeof...(Records) >= 1 && sizeof...(Records) <= 32, "join 1 to 32 record types");
    template <class R>
    static constexpr size_t count_of = (size_t{std::is_same_v<R, Records>} + ...);
    static_assert(((count_of<Records> == 1) && ...), "each record type is joined once");

    template <class R, size_t I, class First, class... Rest>
    static constexpr size_t index_in() {
        if constexpr (std::is_same_v<R, First>)
            return I;
        else {
            static_assert(sizeof...(Rest) > 0, "the record type is not one of the joined types");
            return index_in<R, I + 1, Rest...>();
        }
    }

public:
    static constexpr size_t kTypes = sizeof...(Records);
    // The joined types as a consumes mask (PN_REC_MASK of each).
    static constexpr uint64_t kRecordMask = (PN_REC_MASK(RecordTypeOf<Records>::value) | ...);

    // Index of record type R among Records.
    template <class R>
    static constexpr size_t index_of() {
        return index_in<R, 0, Records...>();
    }

    // The records of one sample time. Valid only during the on_sample call.
    class Sample {
    public:
        int64_t t_ns() const { return t_ns_; }
        // The record of type R about this time, or nullptr when none arrived.
        template <class R>
        const R* get() const {
            return static_cast<const R*>(records_[index_of<R>()]);
        }
        // Whether a record of every joined type is in.
        bool complete() const {
            for (const void* r : records_)
                if (!r) return false;
            return true;
        }

    private:
        friend class TimeJoin;
        Sample() = default;
        int64_t t_ns_ = 0;
        const void* records_[kTypes];
    };

    // Takes in one record of a joined type; calls on_sample when this
    // releases a sample (at most one: the pending sample that this record is
    // not part of, or the sample this record completes).
    template <class R, class OnSample>
    void add(const R& record, OnSample&& on_sample) {
        constexpr size_t i = index_of<R>();
        constexpr uint32_t bit = 1u << i;
        const int64_t t = record.header.t_ns;
        if (t == t_ns_) {
            if (held_ & bit) release_pending(on_sample);  // a repeat: the held sample is over
        } else if (t > t_ns_) {
            if (held_) release_pending(on_sample);
            t_ns_ = t;
        } else {
            ++late_records_;
            return;
        }
        if ((held_ | bit) == kAll) {
            release_complete<i>(on_sample, record);
            return;
        }
        std::get<i>(records_) = record;
        held_ |= bit;
    }

    // End of stream: releases the pending sample, if any.
    template <class OnSample>
    void flush(OnSample&& on_sample) {
        if (held_) release_pending(on_sample);
    }

    // Drops the pending sample without releasing it.
    void clear() { held_ = 0; }

    // Whether a sample is waiting, and its time.
    bool pending() const { return held_ != 0; }
    int64_t pending_t_ns() const { return t_ns_; }
    // Records dropped because they were older than the latest sample.
    uint64_t late_records() const { return late_records_; }

private:
    static constexpr uint32_t kAll = static_cast<uint32_t>((uint64_t{1} << kTypes) - 1);

    // Hands the held records to on_sample; the join is empty before the call.
    template <class OnSample>
    void release_pending(OnSample& on_sample) {
        Sample s;
        s.t_ns_ = t_ns_;
        fill_held(s, std::index_sequence_for<Records...>{});
        held_ = 0;
        on_sample(static_cast<const Sample&>(s));
    }
    template <size_t... I>
    void fill_held(Sample& s, std::index_sequence<I...>) const {
        ((s.records_[I] = (held_ >> I) & 1u ? static_cast<const void*>(&std::get<I>(records_)) : nullptr),
         ...);
    }
    // The held records and `last`, the record of type index L that completes
    // the sample (handed over in place, not stored).
    template <size_t L, class OnSample, class R>
    void release_complete(OnSample& on_sample, const R& last) {
        Sample s;
        s.t_ns_ = t_ns_;
        fill_complete<L>(s, &last, std::index_sequence_for<Records...>{});
        held_ = 0;
        on_sample(static_cast<const Sample&>(s));
    }
    template <size_t L, size_t... I>
    void fill_complete(Sample& s, const void* last, std::index_sequence<I...>) const {
        ((s.records_[I] = I == L ? last : static_cast<const void*>(&std::get<I>(records_))), ...);
    }

    std::tuple<Records...> records_{};
    uint32_t held_ = 0;         // bit i: a record of type i is held for t_ns_
    int64_t t_ns_ = INT64_MIN;  // time of the latest sample, pending or released
    uint64_t late_records_ = 0;
};

}  // namespace pednav::sdk

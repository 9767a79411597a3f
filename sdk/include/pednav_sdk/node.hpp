// SPDX-License-Identifier: Apache-2.0
// C++17 base classes for pednav plugin authors.
//
// Derive from the base class of your kind, override the typed hooks for the
// records you consume, call emit() for the records you produce, and list the
// class in PEDNAV_PLUGIN_LIBRARY (library.hpp). Exceptions thrown from a hook
// never cross the C boundary: the SDK's trampolines turn them into statuses.
//
// A plugin class provides these static members:
//   static constexpr const char* kId;           reverse-DNS id, fixed forever
//   static constexpr const char* kName;
//   static constexpr const char* kVersion;      semver
//   static constexpr const char* kDescription;
//   static constexpr uint64_t kConsumes;        PN_REC_MASK(...) | ...
//   static constexpr uint64_t kProduces;
//   static constexpr const char* kVendor           (optional)
//   static constexpr const char* const* kFeatures  (optional, NULL-terminated)
//   static constexpr const char* kParamsSchema     (optional JSON Schema)
// and a constructor (Params& params, const CreateContext& context) that reads
// every parameter it knows; the SDK then rejects unknown keys.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include <pednav/pn_plugin.h>

#include "params.hpp"

namespace pednav::sdk {

// Thrown by a hook when the data made the computation fail (non-finite state,
// diverged filter). Turned into PN_E_NUMERIC; the engine then resets the node.
class NumericError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Thrown by a hook when its input breaks the contract (wrong units, missing
// stream, a map feature that is wrong). Turned into PN_E_BAD_INPUT; where(),
// when given, is a JSON pointer into the input document (for a map: the
// feature at fault, "/features/12/geometry").
class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& what) : std::runtime_error(what) {}
    InputError(std::string where, const std::string& what) : std::runtime_error(what), where_(std::move(where)) {}
    const std::string& where() const { return where_; }

private:
    std::string where_;
};

// Thrown by emit() when the engine refuses a record.
class EmitError : public std::runtime_error {
public:
    EmitError(pn_status_t status, const std::string& what) : std::runtime_error(what), status(status) {}
    pn_status_t status;
};

struct CreateContext {
    std::string instance_name;
    std::string mount;
    double imu_rate_hz = 0.0;
};

template <class Record>
struct RecordTypeOf;
#define PEDNAV_SDK_RECORD_TYPE(R, ID) \
    template <>                       \
    struct RecordTypeOf<R> {          \
        static constexpr pn_record_type_t value = ID; \
    }
PEDNAV_SDK_RECORD_TYPE(pn_imu_t, PN_REC_IMU);
PEDNAV_SDK_RECORD_TYPE(pn_mag_t, PN_REC_MAG);
PEDNAV_SDK_RECORD_TYPE(pn_baro_t, PN_REC_BARO);
PEDNAV_SDK_RECORD_TYPE(pn_gnss_t, PN_REC_GNSS);
PEDNAV_SDK_RECORD_TYPE(pn_gait_phase_t, PN_REC_GAIT_PHASE);
PEDNAV_SDK_RECORD_TYPE(pn_step_t, PN_REC_STEP);
PEDNAV_SDK_RECORD_TYPE(pn_attitude_t, PN_REC_ATTITUDE);
PEDNAV_SDK_RECORD_TYPE(pn_attitude_correction_t, PN_REC_ATTITUDE_CORRECTION);
PEDNAV_SDK_RECORD_TYPE(pn_position_t, PN_REC_POSITION);
PEDNAV_SDK_RECORD_TYPE(pn_stride_t, PN_REC_STRIDE);
#undef PEDNAV_SDK_RECORD_TYPE

namespace detail {
#if defined(__GNUC__)
// Zeroes a record with one 16-byte store per 16 bytes: GCC turns std::memset
// of these sizes into `rep stos`, which costs a microcoded start-up per record.
typedef double zero16_t __attribute__((vector_size(16), aligned(1), may_alias));
template <size_t... I>
inline void zero_chunks(unsigned char* p, std::index_sequence<I...>) {
    ((*reinterpret_cast<zero16_t*>(p + 16 * I) = zero16_t{0, 0}), ...);
}
template <class Record>
inline void zero_record(Record& r) {
    unsigned char* p = reinterpret_cast<unsigned char*>(&r);
    zero_chunks(p, std::make_index_sequence<sizeof(Record) / 16>{});
    if (sizeof(Record) % 16) std::memset(p + sizeof(Record) / 16 * 16, 0, sizeof(Record) % 16);
}
#else
template <class Record>
inline void zero_record(Record& r) {
    std::memset(&r, 0, sizeof r);
}
#endif
}  // namespace detail

// A zero-initialised record with its header's type and size set.
template <class Record>
Record make_record(int64_t t_ns) {
    Record r;
    detail::zero_record(r);
    r.header.struct_size = sizeof(Record);
    r.header.type = RecordTypeOf<Record>::value;
    r.header.t_ns = t_ns;
    return r;
}

// Base of every node. Use the kind bases below.
class Node {
public:
    virtual ~Node() = default;

    // Typed hooks, one per record type. Default: ignore.
    virtual void on_imu(const pn_imu_t&) {}
    virtual void on_mag(const pn_mag_t&) {}
    virtual void on_baro(const pn_baro_t&) {}
    virtual void on_gnss(const pn_gnss_t&) {}
    virtual void on_gait_phase(const pn_gait_phase_t&) {}
    virtual void on_step(const pn_step_t&) {}
    virtual void on_attitude(const pn_attitude_t&) {}
    virtual void on_attitude_correction(const pn_attitude_correction_t&) {}
    virtual void on_position(const pn_position_t&) {}
    virtual void on_stride(const pn_stride_t&) {}
    // End of stream: emit what is pending.
    virtual void on_flush() {}
    // Fixed look-ahead in ns (see pnp_node_ops_t.latency_ns).
    virtual int64_t latency_ns() const { return 0; }
    // New params without losing state; default: unsupported.
    virtual bool reconfigure(Params&) { return false; }

    // Control slots of the position filter and map matcher kinds; return
    // false when unsupported.
    virtual bool set_start(const double /*pos_enu_m*/[3], double /*heading_rad*/) { return false; }
    virtual bool set_attitude(int64_t /*t_ns*/, const double /*q_enu_from_body*/[4]) { return false; }
    virtual bool load_map(const std::string& /*format*/, const void* /*bytes*/, size_t /*size*/) {
        return false;
    }

    // Set by the SDK before each call into the node.
    void bind_(const pnp_host_t* host, const pnp_sink_t* sink) {
        host_ = host;
        sink_ = sink;
    }
    void bind_sink_(const pnp_sink_t* sink) { sink_ = sink; }

protected:
    template <class Record>
    void emit(const Record& r) {
        static_assert(sizeof(Record) <= PN_RECORD_MAX_SIZE, "record too large");
        if (!sink_) throw EmitError(PN_E_BAD_STATE, "emit() called outside process/flush");
        const pn_status_t s = sink_->emit(sink_, &r.header);
        if (PN_FAILED(s)) throw EmitError(s, "the engine refused an emitted record");
    }
    void log(pnp_log_level_t level, const std::string& msg) const {
        if (host_ && host_->log) host_->log(host_, level, msg.c_str());
    }
    // The engine's geodetic origin (the WGS-84 point at ENU 0, 0, 0), if it
    // has one; an engine older than ABI 1.1 never has.
    bool origin(pn_geo_point_t& out) const {
        return PNP_HAS_SLOT(host_, pnp_host_t, get_origin) && host_->get_origin(host_, &out) == PN_OK;
    }
    // Offers an origin (e.g. the one a map declares); true when the engine
    // had none and took it. Either way origin() then gives the one in force.
    bool offer_origin(const pn_geo_point_t& p) const {
        return PNP_HAS_SLOT(host_, pnp_host_t, offer_origin) && host_->offer_origin(host_, &p) == PN_OK;
    }

private:
    const pnp_host_t* host_ = nullptr;
    const pnp_sink_t* sink_ = nullptr;
};

class StepDetector : public Node {
public:
    static constexpr pnp_kind_t kKind = PNP_KIND_STEP_DETECTOR;
};
class AttitudeEstimator : public Node {
public:
    static constexpr pnp_kind_t kKind = PNP_KIND_ATTITUDE_ESTIMATOR;
};
class PositionFilter : public Node {
public:
    static constexpr pnp_kind_t kKind = PNP_KIND_POSITION_FILTER;
};
class MapMatcher : public Node {
public:
    static constexpr pnp_kind_t kKind = PNP_KIND_MAP_MATCHER;
};

}  // namespace pednav::sdk

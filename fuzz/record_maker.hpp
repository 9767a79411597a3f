// SPDX-License-Identifier: Apache-2.0
// Input records for the push-path fuzz target, decoded from the fuzz input:
// mostly plausible values (a walker's specific force and rates, a field of
// ~50 uT, sea-level pressure, fixes around one place) so that the pipelines
// get past their alignment and emit, and now and then any bit pattern, a
// struct_size other than the record's or a type that is not an input.
#pragma once

#include <cstdint>

#include <pednav/pn_engine.h>

#include "byte_reader.hpp"

namespace pednav::fuzz {

// One record in a slot of PN_RECORD_MAX_SIZE bytes, so that a struct_size up
// to that bound claims only memory the slot holds.
union RecordSlot {
    pn_record_header_t header;
    pn_imu_t imu;
    pn_mag_t mag;
    pn_baro_t baro;
    pn_gnss_t gnss;
    unsigned char bytes[PN_RECORD_MAX_SIZE];
};

class RecordMaker {
public:
    explicit RecordMaker(ByteReader& in) : in_(in) {}

    // A record of input type `type` (PN_REC_IMU .. PN_REC_GNSS) at the next time.
    void make(pn_record_type_t type, RecordSlot& slot);
    // The i-th sample of a synthetic walk at 100 Hz (2 steps per second; `still`:
    // standing, gravity only), no input bytes used.
    void make_walk_imu(uint32_t i, bool still, pn_imu_t& imu);
    // Moves the clock by a signed amount (back in time, repeats, long gaps).
    void jump(int64_t dt_ns) {
        if (__builtin_add_overflow(t_ns_, dt_ns, &t_ns_)) t_ns_ = dt_ns < 0 ? INT64_MIN : INT64_MAX;
    }
    int64_t t_ns() const { return t_ns_; }

private:
    void advance();
    double value(double scale, double offset);
    void header(pn_record_type_t type, uint32_t size, RecordSlot& slot);

    ByteReader& in_;
    int64_t t_ns_ = 0;
    uint8_t flags_ = 0;  // the current record's: 1 raw values, 2 odd struct_size, 4 odd type
};

}  // namespace pednav::fuzz

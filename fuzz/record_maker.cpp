// SPDX-License-Identifier: Apache-2.0
#include "record_maker.hpp"

#include <cmath>
#include <cstring>

namespace pednav::fuzz {

void RecordMaker::advance() {
    // 0.1 ms .. 6.5 s; a zero byte pair repeats the time.
    jump(static_cast<int64_t>(in_.u16()) * 100000);
}

double RecordMaker::value(double scale, double offset) {
    if ((flags_ & 1) != 0) return in_.raw_double();
    return offset + scale * static_cast<double>(in_.i16()) / 32768.0;
}

void RecordMaker::header(pn_record_type_t type, uint32_t size, RecordSlot& slot) {
    std::memset(&slot, 0, sizeof slot);
    slot.header.struct_size = size;
    slot.header.type = type;
    slot.header.t_ns = t_ns_;
    if ((flags_ & 2) != 0) slot.header.struct_size = in_.u16() % (PN_RECORD_MAX_SIZE + 1);
    if ((flags_ & 4) != 0) slot.header.type = in_.u8();
    if ((flags_ & 8) != 0) slot.header.source_id = in_.u8();
    if ((flags_ & 16) != 0) slot.header.flags = in_.u8();
}

void RecordMaker::make(pn_record_type_t type, RecordSlot& slot) {
    flags_ = in_.u8();
    // Rare on purpose: most records are plausible so that the pipelines run.
    if ((flags_ & 0xe0) != 0xe0) flags_ &= 0x10;
    advance();
    switch (type) {
        case PN_REC_IMU:
            header(type, sizeof(pn_imu_t), slot);
            for (int k = 0; k < 3; ++k) slot.imu.accel_mps2[k] = value(30.0, k == 2 ? 9.81 : 0.0);
            for (int k = 0; k < 3; ++k) slot.imu.gyro_radps[k] = value(8.0, 0.0);
            break;
        case PN_REC_MAG:
            header(type, sizeof(pn_mag_t), slot);
            for (int k = 0; k < 3; ++k) slot.mag.mag_ut[k] = value(80.0, k == 0 ? 20.0 : 0.0);
            break;
        case PN_REC_BARO:
            header(type, sizeof(pn_baro_t), slot);
            slot.baro.pressure_pa = value(5000.0, 101325.0);
            slot.baro.temperature_c = (in_.u8() & 1) != 0 ? NAN : value(40.0, 20.0);
            break;
        default:
            header(PN_REC_GNSS, sizeof(pn_gnss_t), slot);
            slot.gnss.lat_deg = value(0.01, 53.1);
            slot.gnss.lon_deg = value(0.01, 8.85);
            slot.gnss.height_m = value(100.0, 10.0);
            slot.gnss.h_accuracy_m = value(30.0, 30.0);
            slot.gnss.v_accuracy_m = value(30.0, 30.0);
            for (int k = 0; k < 3; ++k) slot.gnss.vel_enu_mps[k] = value(3.0, 0.0);
            slot.gnss.header.flags |= in_.u8() & PN_GNSS_FLAG_HAS_VELOCITY;
            slot.gnss.utc_ns = (in_.u8() & 1) != 0 ? 1714557600000000000LL + t_ns_ : 0;
            slot.gnss.satellites = in_.u8() % 40;
            slot.gnss.fix_type = in_.u8() % 8;
            break;
    }
}

void RecordMaker::make_walk_imu(uint32_t i, bool still, pn_imu_t& imu) {
    std::memset(&imu, 0, sizeof imu);
    jump(10000000);  // 100 Hz
    const double phase = 2.0 * M_PI * 2.0 * static_cast<double>(i) / 100.0;
    imu.header.struct_size = sizeof imu;
    imu.header.type = PN_REC_IMU;
    imu.header.t_ns = t_ns_;
    if (still) {
        imu.accel_mps2[2] = 9.81;
        return;
    }
    imu.accel_mps2[0] = 1.5 * std::sin(phase);
    imu.accel_mps2[1] = 0.3 * std::cos(0.5 * phase);
    imu.accel_mps2[2] = 9.81 + 2.5 * std::cos(phase);
    imu.gyro_radps[0] = 0.2 * std::sin(0.5 * phase);
    imu.gyro_radps[1] = 1.5 * std::sin(phase);
    imu.gyro_radps[2] = 0.05;
}

}  // namespace pednav::fuzz

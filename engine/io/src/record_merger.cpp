// SPDX-License-Identifier: Apache-2.0
#include "record_merger.hpp"

namespace pednav::io::detail {

void VectorSink::add(const InputRecord& record) {
    switch (record.header.type) {
        case PN_REC_IMU: log_.imu.push_back(record.imu); break;
        case PN_REC_MAG: log_.mag.push_back(record.mag); break;
        case PN_REC_BARO: log_.baro.push_back(record.baro); break;
        case PN_REC_GNSS: log_.gnss.push_back(record.gnss); break;
        default: break;
    }
}

int RecordMerger::slot_of(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return 0;
        case PN_REC_MAG: return 1;
        case PN_REC_BARO: return 2;
        default: return 3;
    }
}

void RecordMerger::set_open(pn_record_type_t type, bool open) { open_[slot_of(type)] = open; }

void RecordMerger::close_all() {
    for (bool& o : open_) o = false;
}

bool RecordMerger::placeable(pn_record_type_t type, int64_t t_ns) const {
    if (!released_any_) return true;
    return t_ns > released_t_ns_ || (t_ns == released_t_ns_ && slot_of(type) > released_slot_);
}

void RecordMerger::add(const InputRecord& record) {
    const int s = slot_of(record.header.type);
    queue_[s].push_back(record);
    seen_[s] = true;
    last_t_ns_[s] = record.header.t_ns;
    ++queued_;
}

size_t RecordMerger::release(std::vector<InputRecord>& out, size_t max) {
    size_t given = 0;
    while (given < max) {
        int best = -1;
        for (int s = 0; s < kSlots; ++s) {
            if (queue_[s].empty()) continue;
            if (best < 0 || queue_[s].front().header.t_ns < queue_[best].front().header.t_ns) best = s;
        }
        if (best < 0) break;
        const int64_t t_ns = queue_[best].front().header.t_ns;
        // Every silent stream that may still give records must have reached t_ns:
        // its next record comes strictly later than its last.
        bool known = true;
        for (int s = 0; s < kSlots && known; ++s) {
            if (s == best || !queue_[s].empty() || !open_[s]) continue;
            known = seen_[s] && t_ns <= last_t_ns_[s];
        }
        if (!known && (window_ == 0 || queued_ <= window_)) break;
        out.push_back(queue_[best].front());
        queue_[best].pop_front();
        --queued_;
        ++given;
        released_any_ = true;
        released_t_ns_ = t_ns;
        released_slot_ = best;
    }
    return given;
}

}  // namespace pednav::io::detail

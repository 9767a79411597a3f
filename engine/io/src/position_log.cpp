// SPDX-License-Identifier: Apache-2.0
#include "pednav_io/position_log.hpp"

#include "spill_vector.hpp"

namespace pednav::io {

namespace {

// The fields of a position the writers of GeoJSON, GPX and geo-track CSV read.
struct KeptPosition {
    int64_t t_ns;
    uint32_t flags;
    int32_t floor;
    double pos_enu_m[3];
    double heading_rad;
    double cov_xx_m2, cov_yy_m2;
    int32_t source;
};

}  // namespace

struct PositionLog::Impl {
    detail::SpillVector<KeptPosition> kept;
};

PositionLog::PositionLog() : impl_(std::make_unique<Impl>()) {}
PositionLog::~PositionLog() = default;

void PositionLog::add(const pn_position_t& p) {
    impl_->kept.push_back({p.header.t_ns,
                           p.header.flags,
                           p.floor,
                           {p.pos_enu_m[0], p.pos_enu_m[1], p.pos_enu_m[2]},
                           p.heading_rad,
                           p.cov_enu_m2[0],
                           p.cov_enu_m2[4],
                           p.source});
}

size_t PositionLog::size() const { return impl_->kept.size(); }

void PositionLog::for_each(const std::function<void(const pn_position_t&)>& f) const {
    pn_position_t p{};
    p.header.struct_size = sizeof p;
    p.header.type = PN_REC_POSITION;
    impl_->kept.for_each([&](const KeptPosition& k) {
        p.header.t_ns = k.t_ns;
        p.header.flags = k.flags;
        p.floor = k.floor;
        for (int i = 0; i < 3; ++i) p.pos_enu_m[i] = k.pos_enu_m[i];
        p.heading_rad = k.heading_rad;
        p.cov_enu_m2[0] = k.cov_xx_m2;
        p.cov_enu_m2[4] = k.cov_yy_m2;
        p.source = k.source;
        f(p);
    });
}

}  // namespace pednav::io

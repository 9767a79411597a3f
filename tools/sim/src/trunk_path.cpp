// SPDX-License-Identifier: Apache-2.0
#include "trunk_path.hpp"

namespace pednav::sim::detail {

std::vector<Eigen::Vector3d> trunk_knots(const std::vector<Eigen::Vector3d>& landings_enu_m) {
    const std::vector<Eigen::Vector3d>& p = landings_enu_m;
    std::vector<Eigen::Vector3d> q = p;
    for (size_t k = 1; k + 1 < p.size(); ++k)
        q[k].head<2>() = 0.25 * (p[k - 1].head<2>() + 2.0 * p[k].head<2>() + p[k + 1].head<2>());
    return q;
}

}  // namespace pednav::sim::detail

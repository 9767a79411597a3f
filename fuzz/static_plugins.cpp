// SPDX-License-Identifier: Apache-2.0
#include "static_plugins.hpp"

extern "C" {
const pnp_library_t* pnp_entry_v1_foot_stance(void);
const pnp_library_t* pnp_entry_v1_foot_strapdown(void);
const pnp_library_t* pnp_entry_v1_foot_ekf(void);
const pnp_library_t* pnp_entry_v1_peak_steps(void);
const pnp_library_t* pnp_entry_v1_madgwick(void);
const pnp_library_t* pnp_entry_v1_pdr_steps(void);
const pnp_library_t* pnp_entry_v1_map_particle_filter(void);
const pnp_library_t* pnp_entry_v1_waist_peak(void);
const pnp_library_t* pnp_entry_v1_waist_attitude(void);
const pnp_library_t* pnp_entry_v1_waist_fusion(void);
}

namespace pednav::fuzz {

const pnp_library_t* const* static_plugin_libraries(uint32_t* count) {
    static const pnp_library_t* const libraries[] = {
        pnp_entry_v1_foot_stance(),   pnp_entry_v1_foot_strapdown(),     pnp_entry_v1_foot_ekf(),
        pnp_entry_v1_peak_steps(),    pnp_entry_v1_madgwick(),           pnp_entry_v1_pdr_steps(),
        pnp_entry_v1_map_particle_filter(), pnp_entry_v1_waist_peak(), pnp_entry_v1_waist_attitude(),
        pnp_entry_v1_waist_fusion()};
    *count = static_cast<uint32_t>(sizeof libraries / sizeof libraries[0]);
    return libraries;
}

pn_engine_t* create_engine(const char* config_json, size_t size, pn_status_t* status) {
    pn_engine_create_info_t info{};
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config_json;
    info.config_len = size;
    info.static_libraries = static_plugin_libraries(&info.static_library_count);
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_engine_t* engine = nullptr;
    *status = pn_engine_create(&info, &engine, &err);
    return PN_FAILED(*status) ? nullptr : engine;
}

}  // namespace pednav::fuzz

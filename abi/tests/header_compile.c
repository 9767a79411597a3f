/* SPDX-License-Identifier: Apache-2.0 */
/* Header compile test: abi/tests/CMakeLists.txt compiles this file once per
 * public ABI header (PN_TEST_HEADER) and per language standard, as C and as
 * C++, with -Wall -Wextra -pedantic -Wpadded -Werror. Each header must be
 * self-contained and warning-free on its own, and so must its macros once
 * expanded in user code. */
#include PN_TEST_HEADER

int pn_header_compile_probe(const pn_record_header_t *record);
int pn_header_compile_probe(const pn_record_header_t *record) {
    const uint32_t version = PN_ABI_VERSION;
    const uint64_t mask = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_TYPE_COUNT - 1);
    const pn_status_t status = PN_E_INTERNAL;
    int n = (int)PN_ABI_VERSION_MAJOR(version) + (int)PN_ABI_VERSION_MINOR(version) + PN_FAILED(status);
    n += (mask & PN_REC_MASK(record->type)) != 0;
#ifdef PEDNAV_PN_PLUGIN_H
    {
        const pnp_descriptor_t *desc = (const pnp_descriptor_t *)0;
        const pnp_library_t *lib = (const pnp_library_t *)0;
        n += PNP_HAS_SLOT(lib, pnp_library_t, init);
        if (desc && desc->ops) {
            const pnp_map_matcher_ops_t *mm = (const pnp_map_matcher_ops_t *)(const void *)desc->ops;
            n += PNP_HAS_SLOT(desc->ops, pnp_node_ops_t, latency_ns);
            n += PNP_HAS_KIND_SLOT(mm, pnp_map_matcher_ops_t, set_start);
        }
        n += (int)sizeof(PNP_ENTRY_SYMBOL) + (int)PNP_NODE_OPS_MIN_SIZE + (int)PNP_DESCRIPTOR_MIN_SIZE +
             (int)PNP_LIBRARY_MIN_SIZE;
    }
#endif
#ifdef PEDNAV_PN_ENGINE_H
    {
        pn_output_t out;
        out.header = *record;
        n += (int)sizeof out.bytes + (int)out.header.struct_size;
    }
#endif
    return n;
}

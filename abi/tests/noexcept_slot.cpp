// SPDX-License-Identifier: Apache-2.0
// Negative compile test (C++17): every slot of the plugin ABI is a noexcept
// function type, so a plugin function that may throw does not even convert to
// it. abi/tests/CMakeLists.txt compiles this file once per PN_TEST_CASE with
// PN_TEST_NOEXCEPT=noexcept (must compile: the control) and once with it
// empty (must fail with a conversion error that names noexcept).
#include <pednav/pn_plugin.h>

#ifndef PN_TEST_NOEXCEPT
#error "define PN_TEST_NOEXCEPT as noexcept or as nothing"
#endif

int pn_noexcept_slot_probe();

#if PN_TEST_CASE == 1
static pn_status_t reset_impl(void*, pn_error_t*) PN_TEST_NOEXCEPT { return PN_OK; }
int pn_noexcept_slot_probe() {
    pnp_node_ops_t ops{};
    ops.reset = &reset_impl;
    return ops.reset != nullptr;
}
#elif PN_TEST_CASE == 2
static pn_status_t emit_impl(const pnp_sink_t*, const pn_record_header_t*) PN_TEST_NOEXCEPT { return PN_OK; }
int pn_noexcept_slot_probe() {
    pnp_sink_t sink{};
    sink.emit = &emit_impl;
    return sink.emit != nullptr;
}
#elif PN_TEST_CASE == 3
static pn_status_t create_impl(const pnp_descriptor_t*, const pnp_host_t*, const pnp_create_info_t*, void**,
                               pn_error_t*) PN_TEST_NOEXCEPT {
    return PN_OK;
}
int pn_noexcept_slot_probe() {
    pnp_descriptor_t desc{};
    desc.create = &create_impl;
    return desc.create != nullptr;
}
#else
#error "PN_TEST_CASE must be 1, 2 or 3"
#endif

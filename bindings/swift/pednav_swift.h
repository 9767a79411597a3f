/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The umbrella header of the CPednav module (module.modulemap): the C API
 * headers from abi/include, and the entry functions of the first-party foot
 * plugins built as static libraries (pednav_add_plugin's <target>_static,
 * entry pnp_entry_v1_<NAME>), to pass in
 * pn_engine_create_info_t.static_libraries where code cannot be loaded at
 * run time (iOS).
 */
#ifndef PEDNAV_SWIFT_H
#define PEDNAV_SWIFT_H

#include "../../abi/include/pednav/pn_engine.h"
#include "../../abi/include/pednav/pn_io.h"

#ifdef __cplusplus
extern "C" {
#endif

const pnp_library_t *pnp_entry_v1_foot_stance(void);
const pnp_library_t *pnp_entry_v1_foot_strapdown(void);
const pnp_library_t *pnp_entry_v1_foot_ekf(void);

#ifdef __cplusplus
}
#endif

#endif /* PEDNAV_SWIFT_H */

# SPDX-License-Identifier: Apache-2.0
# cmake -DFIXTURE_DIR=<test-plugins/lazy_a> -DOUT=<dir> -P spoil_manifest.cmake
# Two plugin directories for the `pednav plugins` checks: OUT/disagrees holds
# libpnp_lazy_a1.so with a manifest whose step detector is called a position
# filter; OUT/no_manifest holds the same library without its manifest.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/disagrees" "${OUT}/no_manifest")
file(COPY "${FIXTURE_DIR}/libpnp_lazy_a1.so" DESTINATION "${OUT}/disagrees")
file(COPY "${FIXTURE_DIR}/libpnp_lazy_a1.so" DESTINATION "${OUT}/no_manifest")
file(READ "${FIXTURE_DIR}/libpnp_lazy_a1.json" manifest)
string(JSON kind GET "${manifest}" plugins 0 kind)
if(NOT kind STREQUAL "step_detector")
  message(FATAL_ERROR "lazy_a1's first plugin is a ${kind}, expected its step detector")
endif()
string(JSON manifest SET "${manifest}" plugins 0 kind "\"position_filter\"")
file(WRITE "${OUT}/disagrees/libpnp_lazy_a1.json" "${manifest}")

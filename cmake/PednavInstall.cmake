# SPDX-License-Identifier: Apache-2.0
# Installs the CMake package (find_package(pednav)) and the pkg-config file.
# Included at the end of the top-level CMakeLists.txt, once every exported
# target exists.
include(CMakePackageConfigHelpers)

set(PEDNAV_CMAKE_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/pednav")

# pednav_abi -> pednav::abi, pednav_sdk -> pednav::sdk, pednav -> pednav::pednav,
# pednav_manifest -> pednav::manifest, pednav_core -> pednav::pednav_static.
set_target_properties(pednav_abi PROPERTIES EXPORT_NAME abi)
set_target_properties(pednav_sdk PROPERTIES EXPORT_NAME sdk)

# Two export sets: everything a C app needs, and the C++ SDK, which alone
# needs nlohmann_json (pednavConfig.cmake loads it only where that is found).
install(EXPORT pednavTargets
  NAMESPACE pednav::
  DESTINATION "${PEDNAV_CMAKE_INSTALL_DIR}")
install(EXPORT pednavSdkTargets
  NAMESPACE pednav::
  DESTINATION "${PEDNAV_CMAKE_INSTALL_DIR}")

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/pednavConfig.cmake.in"
  "${CMAKE_CURRENT_BINARY_DIR}/pednavConfig.cmake"
  INSTALL_DESTINATION "${PEDNAV_CMAKE_INSTALL_DIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR PEDNAV_PLUGIN_INSTALL_DIR)
write_basic_package_version_file(
  "${CMAKE_CURRENT_BINARY_DIR}/pednavConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion)
install(FILES
  "${CMAKE_CURRENT_BINARY_DIR}/pednavConfig.cmake"
  "${CMAKE_CURRENT_BINARY_DIR}/pednavConfigVersion.cmake"
  DESTINATION "${PEDNAV_CMAKE_INSTALL_DIR}")

# pkg-config, relocatable: the prefix is found from the .pc file's own place.
file(RELATIVE_PATH PEDNAV_PC_PREFIX_FROM_PCDIR "/root/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/root")
string(REGEX REPLACE "/$" "" PEDNAV_PC_PREFIX_FROM_PCDIR "${PEDNAV_PC_PREFIX_FROM_PCDIR}")
configure_file("${CMAKE_CURRENT_LIST_DIR}/pednav.pc.in" "${CMAKE_CURRENT_BINARY_DIR}/pednav.pc" @ONLY)
install(FILES "${CMAKE_CURRENT_BINARY_DIR}/pednav.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")

# The licence travels with the installed files.
install(FILES "${PROJECT_SOURCE_DIR}/LICENSE" "${PROJECT_SOURCE_DIR}/NOTICE" DESTINATION "${CMAKE_INSTALL_DOCDIR}")

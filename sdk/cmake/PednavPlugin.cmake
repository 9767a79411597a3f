# pednav_add_plugin(<target> NAME <name> SOURCES <files...> [LIBRARIES <libs...>]
#                   [OUTPUT_DIRECTORY <dir>] [NO_INSTALL])
#
# Builds a pednav plugin library the way the engine expects it:
#   - a MODULE library named libpnp_<name>.so;
#   - hidden visibility for C and C++, inline functions hidden;
#   - a linker version script that exports only the entry symbol pnp_entry_v1;
#   - -Wl,--no-undefined so a missing symbol fails the build, not the dlopen.
# First-party plugins are built with exactly this function.
set(_PEDNAV_PLUGIN_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(pednav_add_plugin target)
  cmake_parse_arguments(ARG "NO_INSTALL" "NAME;OUTPUT_DIRECTORY" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  add_library(${target} MODULE ${ARG_SOURCES})
  if(TARGET pednav::sdk)
    target_link_libraries(${target} PRIVATE pednav::sdk)
  endif()
  if(ARG_LIBRARIES)
    target_link_libraries(${target} PRIVATE ${ARG_LIBRARIES})
  endif()
  set(_script "${_PEDNAV_PLUGIN_CMAKE_DIR}/pednav_plugin.map")
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    OUTPUT_NAME "pnp_${ARG_NAME}"
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    LINK_DEPENDS "${_script}")
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}")
  elseif(DEFINED PEDNAV_PLUGIN_OUTPUT_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${PEDNAV_PLUGIN_OUTPUT_DIR}")
  endif()
  # The sanitizer runtime is provided by the host executable, not the plugin.
  get_property(_opts DIRECTORY PROPERTY LINK_OPTIONS)
  if(NOT "${_opts}" MATCHES "sanitize")
    target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  endif()
  target_link_options(${target} PRIVATE "LINKER:--version-script=${_script}")
  if(NOT ARG_NO_INSTALL)
    set_property(GLOBAL APPEND PROPERTY PEDNAV_PLUGIN_TARGETS ${target})
    if(DEFINED PEDNAV_PLUGIN_INSTALL_DIR)
      install(TARGETS ${target} LIBRARY DESTINATION ${PEDNAV_PLUGIN_INSTALL_DIR})
    else()
      install(TARGETS ${target} LIBRARY DESTINATION lib/pednav/plugins)
    endif()
  endif()
endfunction()

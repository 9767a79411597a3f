# SPDX-License-Identifier: Apache-2.0
# pednav_add_plugin(<target> NAME <name> SOURCES <files...> [LIBRARIES <libs...>]
#                   [OUTPUT_DIRECTORY <dir>] [INSTALL_DESTINATION <dir>] [NO_INSTALL])
#
# Builds a pednav plugin library the way the engine expects it:
#   - a MODULE library named libpnp_<name>.so;
#   - hidden visibility for C and C++, inline functions hidden;
#   - only the entry symbol pnp_entry_v1 exported: a version script for GNU ld
#     and lld, an exported-symbols list for Apple's ld; MSVC and MinGW get no
#     linker flag (the SDK marks the entry __declspec(dllexport));
#   - undefined symbols fail the link, not the dlopen (--no-undefined,
#     -undefined,error on Apple; PE links fail on them anyway);
#   - its manifest libpnp_<name>.json written beside it after every link by
#     pednav-manifest (pednav::manifest), which opens the library with the
#     engine's loader: a library the engine would refuse fails the build;
#   - installed with its manifest into the pednav plugin directory: the
#     relative one pednav itself was installed with (pednav_PLUGIN_INSTALL_DIR),
#     so that under the same prefix the installed `pednav plugins` finds it;
#   - with PEDNAV_BUILD_STATIC on, also a static library <target>_static whose
#     entry function is pnp_entry_v1_<name> (<name> must then be a C
#     identifier), for apps that link their plugins in (iOS): they pass
#     pnp_entry_v1_<name>() in pn_engine_create_info_t.static_libraries.
# First-party plugins are built with exactly this function. Only the GNU
# flags are exercised by the project's tests (docs/loading.md).
#
# PEDNAV_MANIFEST_TOOL (a path) replaces pednav::manifest, for example a host
# build of it when cross-compiling; without either, no manifest is written and
# the engine finds the library with a warning.
set(_PEDNAV_PLUGIN_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(_pednav_plugin_link_rules target)
  get_property(_opts DIRECTORY PROPERTY LINK_OPTIONS)
  set(_sanitized FALSE)
  if("${_opts}" MATCHES "sanitize")
    set(_sanitized TRUE)  # the sanitizer runtime is provided by the host executable, not the plugin
  endif()
  if(APPLE)
    set(_exports "${_PEDNAV_PLUGIN_CMAKE_DIR}/pednav_plugin.exports")
    target_link_options(${target} PRIVATE "LINKER:-exported_symbols_list,${_exports}")
    if(NOT _sanitized)
      target_link_options(${target} PRIVATE "LINKER:-undefined,error")
    endif()
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${_exports}")
  elseif(WIN32)
    # MSVC and MinGW: the entry is __declspec(dllexport), nothing else is exported.
  else()
    set(_script "${_PEDNAV_PLUGIN_CMAKE_DIR}/pednav_plugin.map")
    target_link_options(${target} PRIVATE "LINKER:--version-script=${_script}")
    if(NOT _sanitized)
      target_link_options(${target} PRIVATE "LINKER:--no-undefined")
    endif()
    set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${_script}")
  endif()
endfunction()

# The manifest tool to run after each link, or "" when there is none.
function(_pednav_manifest_tool out)
  if(PEDNAV_MANIFEST_TOOL)
    set(${out} "${PEDNAV_MANIFEST_TOOL}" PARENT_SCOPE)
  elseif(TARGET pednav::manifest AND NOT CMAKE_CROSSCOMPILING)
    set(${out} pednav::manifest PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

function(_pednav_plugin_install_dir out)
  if(DEFINED PEDNAV_PLUGIN_INSTALL_DIR)      # building pednav itself
    set(${out} "${PEDNAV_PLUGIN_INSTALL_DIR}" PARENT_SCOPE)
  elseif(DEFINED pednav_PLUGIN_INSTALL_DIR)  # from find_package(pednav)
    set(${out} "${pednav_PLUGIN_INSTALL_DIR}" PARENT_SCOPE)
  else()
    include(GNUInstallDirs)
    set(${out} "${CMAKE_INSTALL_LIBDIR}/pednav/plugins" PARENT_SCOPE)
  endif()
endfunction()

function(pednav_add_plugin target)
  cmake_parse_arguments(ARG "NO_INSTALL" "NAME;OUTPUT_DIRECTORY;INSTALL_DESTINATION" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  if(TARGET pednav::sdk)
    set(_sdk pednav::sdk)
  else()
    set(_sdk pednav::abi)  # a package found without nlohmann_json: plugins written in C only
  endif()
  add_library(${target} MODULE ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${_sdk} ${ARG_LIBRARIES})
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    OUTPUT_NAME "pnp_${ARG_NAME}"
    C_VISIBILITY_PRESET hidden
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${ARG_OUTPUT_DIRECTORY}")
  elseif(DEFINED PEDNAV_PLUGIN_OUTPUT_DIR)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY "${PEDNAV_PLUGIN_OUTPUT_DIR}")
  endif()
  _pednav_plugin_link_rules(${target})

  _pednav_manifest_tool(_tool)
  set(_manifest "$<TARGET_FILE_DIR:${target}>/$<TARGET_FILE_PREFIX:${target}>$<TARGET_FILE_BASE_NAME:${target}>.json")
  if(_tool)
    add_custom_command(TARGET ${target} POST_BUILD
      COMMAND ${_tool} "$<TARGET_FILE:${target}>" --output "${_manifest}"
      COMMENT "Writing the plugin manifest of ${target}"
      VERBATIM)
    if(TARGET ${_tool})
      get_target_property(_real ${_tool} ALIASED_TARGET)
      if(_real)
        add_dependencies(${target} ${_real})
      endif()
    endif()
  else()
    message(STATUS "pednav_add_plugin(${target}): no manifest tool (pednav::manifest or PEDNAV_MANIFEST_TOOL); "
                   "the library is installed without a manifest")
  endif()

  if(PEDNAV_BUILD_STATIC)
    if(NOT ARG_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
      message(FATAL_ERROR "pednav_add_plugin(${target}): NAME ${ARG_NAME} is not a C identifier, "
                          "so pnp_entry_v1_${ARG_NAME} cannot name the static entry function")
    endif()
    add_library(${target}_static STATIC ${ARG_SOURCES})
    target_link_libraries(${target}_static PRIVATE ${_sdk} ${ARG_LIBRARIES})
    target_compile_definitions(${target}_static PRIVATE PEDNAV_PLUGIN_STATIC_NAME=${ARG_NAME}
                               $<TARGET_PROPERTY:${target},COMPILE_DEFINITIONS>)
    target_compile_options(${target}_static PRIVATE $<TARGET_PROPERTY:${target},COMPILE_OPTIONS>)
    set_target_properties(${target}_static PROPERTIES
      OUTPUT_NAME "pnp_${ARG_NAME}"
      C_VISIBILITY_PRESET hidden
      CXX_VISIBILITY_PRESET hidden
      VISIBILITY_INLINES_HIDDEN ON)
  endif()

  if(NOT ARG_NO_INSTALL)
    set_property(GLOBAL APPEND PROPERTY PEDNAV_PLUGIN_TARGETS ${target})
    if(ARG_INSTALL_DESTINATION)
      set(_dest "${ARG_INSTALL_DESTINATION}")
    else()
      _pednav_plugin_install_dir(_dest)
    endif()
    install(TARGETS ${target} LIBRARY DESTINATION "${_dest}")
    if(_tool)
      install(FILES "${_manifest}" DESTINATION "${_dest}")
    endif()
  endif()
endfunction()

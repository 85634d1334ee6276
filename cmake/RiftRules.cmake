# rift_add_rule_pack(<target> RULES <file.rules>...)
#
# Runs riftc on the rule files at build time and compiles the generated C++
# into the static library <target>, which links rift_runtime and exposes the
# generated header <pack>.hpp (namespace rift::packs::<pack>), <pack> being
# the name the first file declares with `pack NAME dimension N;`. The header
# declares `void rift_register_pack_<pack>(rift::PackRegistry&)` in the global
# namespace; the target's properties RIFT_PACK_NAME (<pack>) and
# RIFT_PACK_HEADER (the header's path) let a simulator generate the call.
#
# riftc writes a dependency file, so editing a .rules file (or a file it
# includes) regenerates and rebuilds only this pack.
include_guard(GLOBAL)

function(_rift_riftc_command out_var)
  if(TARGET riftc)
    set(${out_var} "$<TARGET_FILE:riftc>" PARENT_SCOPE)
  else()
    find_program(RIFT_RIFTC_EXECUTABLE riftc REQUIRED)
    set(${out_var} "${RIFT_RIFTC_EXECUTABLE}" PARENT_SCOPE)
  endif()
endfunction()

#
# PACK <pack> names the pack instead of reading it from the first file: for a
# rule file that another build step generates (it does not exist yet when
# CMake configures).
function(rift_add_rule_pack target)
  cmake_parse_arguments(ARG "" "PACK" "RULES" ${ARGN})
  if(NOT ARG_RULES)
    message(FATAL_ERROR "rift_add_rule_pack(${target}): no RULES given")
  endif()
  set(rules "")
  foreach(file IN LISTS ARG_RULES)
    get_filename_component(abs "${file}" ABSOLUTE)
    list(APPEND rules "${abs}")
  endforeach()
  list(GET rules 0 first)
  if(ARG_PACK)
    set(pack "${ARG_PACK}")
  else()
    # The output names come from the pack header; re-run CMake when it changes.
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${first}")
    file(STRINGS "${first}" header REGEX "^[ \t]*pack[ \t]+[A-Za-z_][A-Za-z0-9_]*" LIMIT_COUNT 1)
    if(NOT header MATCHES "pack[ \t]+([A-Za-z_][A-Za-z0-9_]*)")
      message(FATAL_ERROR "rift_add_rule_pack(${target}): ${first} has no 'pack NAME dimension N;' line")
    endif()
    set(pack "${CMAKE_MATCH_1}")
  endif()
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}_generated")
  _rift_riftc_command(riftc)
  set(riftc_target "")
  if(TARGET riftc)
    set(riftc_target riftc)
  endif()
  # Included rule files are looked up next to the including file, then in
  # RIFT_RULES_INCLUDE_DIRS (find_package(rift) points it at the installed
  # standard packs, so a pack can `include "common2d.rules";`).
  set(include_flags "")
  foreach(dir IN LISTS RIFT_RULES_INCLUDE_DIRS)
    list(APPEND include_flags "-I" "${dir}")
  endforeach()
  add_custom_command(
    OUTPUT "${out_dir}/${pack}.hpp" "${out_dir}/${pack}.cpp"
    COMMAND "${riftc}" ${rules} ${include_flags} -o "${out_dir}" --depfile "${out_dir}/${pack}.d"
    DEPENDS ${rules} ${riftc_target}
    DEPFILE "${out_dir}/${pack}.d"
    COMMENT "riftc: generating rule pack '${pack}'"
    VERBATIM)
  add_library(${target} STATIC "${out_dir}/${pack}.cpp")
  target_include_directories(${target} PUBLIC "${out_dir}")
  target_link_libraries(${target} PUBLIC rift_runtime)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES RIFT_PACK_NAME "${pack}"
                                             RIFT_PACK_HEADER "${out_dir}/${pack}.hpp")
  if(COMMAND rift_set_warnings)
    rift_set_warnings(${target})
  endif()
endfunction()

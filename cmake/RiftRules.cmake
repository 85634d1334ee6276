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
#
# A pack that imports another (`import "topology2d.rules";`) calls that pack's
# generated code: its library links the imported pack's library, found by the
# pack name of the imported file's header, at the end of the directory that
# made it: a target made by rift_add_rule_pack for that pack (in any order),
# else rift's installed rift::pack_<name>, else a library of its own made from
# the imported file (rift_imported_pack_<name>). Registering the pack
# registers the packs it imports, so a simulator needs only list it.
include_guard(GLOBAL)

# The name a rule file declares with `pack NAME dimension N;`, or "" when it has none.
function(_rift_rules_pack_name file out_var)
  file(STRINGS "${file}" header REGEX "^[ \t]*pack[ \t]+[A-Za-z_][A-Za-z0-9_]*" LIMIT_COUNT 1)
  if(header MATCHES "pack[ \t]+([A-Za-z_][A-Za-z0-9_]*)")
    set(${out_var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
  else()
    set(${out_var} "" PARENT_SCOPE)
  endif()
endfunction()

# Links the pack library `target` with the library of the pack `pack`
# (imported from `file`): deferred to the end of the directory, so that the
# imported pack may be made after the importing one.
function(_rift_link_imported_pack target pack file)
  get_property(imported GLOBAL PROPERTY RIFT_PACK_TARGET_${pack})
  if(NOT imported)
    if(TARGET rift::pack_${pack})
      set(imported rift::pack_${pack})
    else()
      set(imported rift_imported_pack_${pack})
      rift_add_rule_pack(${imported} RULES "${file}")
    endif()
  endif()
  target_link_libraries(${target} PUBLIC ${imported})
endfunction()

# Every `import "FILE";` of `rules_file`, resolved as riftc resolves it (next
# to the file, then in RIFT_RULES_INCLUDE_DIRS): links `target` with each
# imported pack's library.
function(_rift_link_imports target rules_file)
  file(STRINGS "${rules_file}" lines REGEX "^[ \t]*import[ \t]+\"[^\"]+\"")
  get_filename_component(dir "${rules_file}" DIRECTORY)
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "import[ \t]+\"([^\"]+)\"")
      continue()
    endif()
    set(name "${CMAKE_MATCH_1}")
    set(found "")
    foreach(candidate_dir IN ITEMS "${dir}" ${RIFT_RULES_INCLUDE_DIRS})
      if(EXISTS "${candidate_dir}/${name}")
        get_filename_component(found "${candidate_dir}/${name}" ABSOLUTE)
        break()
      endif()
    endforeach()
    if(NOT found)
      continue()  # riftc reports it, at the import
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${found}")
    _rift_rules_pack_name("${found}" pack)
    if(NOT pack)
      continue()  # not a pack: riftc reports it
    endif()
    cmake_language(EVAL CODE
      "cmake_language(DEFER CALL _rift_link_imported_pack [[${target}]] [[${pack}]] [[${found}]])")
  endforeach()
endfunction()

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
  get_property(known GLOBAL PROPERTY RIFT_PACK_TARGET_${pack})
  if(NOT known)
    set_property(GLOBAL PROPERTY RIFT_PACK_TARGET_${pack} ${target})
  endif()
  foreach(file IN LISTS rules)
    if(EXISTS "${file}")
      _rift_link_imports(${target} "${file}")
    endif()
  endforeach()
  if(COMMAND rift_set_warnings)
    rift_set_warnings(${target})
  endif()
endfunction()

# cmake --install: riftc, rift, the runtime and command-line libraries with
# their headers, the standard rule packs, and a CMake package so that another
# project can find_package(rift) and call rift_add_rule_pack and
# rift_add_simulator.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(RIFT_INSTALL_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/rift")
set(RIFT_INSTALL_RULES_DIR "${CMAKE_INSTALL_DATADIR}/rift/rules")
set(RIFT_INSTALL_BIN_DIR "${CMAKE_INSTALL_BINDIR}")

set(_rift_export_targets rift_runtime rift_cli)
if(TARGET riftc)
  list(APPEND _rift_export_targets riftc)
endif()
if(TARGET rift_standard_packs)
  get_target_property(_rift_pack_targets rift_standard_packs RIFT_PACK_TARGETS)
  list(APPEND _rift_export_targets rift_standard_packs ${_rift_pack_targets})
endif()
set_target_properties(rift_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(rift_cli PROPERTIES EXPORT_NAME cli)
if(TARGET riftc)
  set_target_properties(riftc PROPERTIES EXPORT_NAME riftc)
endif()
if(TARGET rift_standard_packs)
  set_target_properties(rift_standard_packs PROPERTIES EXPORT_NAME standard_packs
                                                       EXPORT_PROPERTIES RIFT_PACK_NAMES)
endif()

install(TARGETS ${_rift_export_targets} EXPORT riftTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS rift RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/runtime/rift" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES "${PROJECT_SOURCE_DIR}/cli/app.hpp" "${PROJECT_SOURCE_DIR}/cli/register_packs.hpp"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/rift-cli/cli")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/rules/" DESTINATION "${RIFT_INSTALL_RULES_DIR}"
        FILES_MATCHING PATTERN "*.rules")
install(FILES "${PROJECT_SOURCE_DIR}/cmake/RiftRules.cmake"
              "${PROJECT_SOURCE_DIR}/cmake/RiftSimulator.cmake"
              "${PROJECT_SOURCE_DIR}/cmake/RiftWarnings.cmake"
        DESTINATION "${RIFT_INSTALL_CMAKE_DIR}")
install(EXPORT riftTargets NAMESPACE rift:: DESTINATION "${RIFT_INSTALL_CMAKE_DIR}")

configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/riftConfig.cmake.in" "${PROJECT_BINARY_DIR}/riftConfig.cmake"
  INSTALL_DESTINATION "${RIFT_INSTALL_CMAKE_DIR}"
  PATH_VARS RIFT_INSTALL_RULES_DIR RIFT_INSTALL_BIN_DIR)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/riftConfigVersion.cmake"
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES "${PROJECT_BINARY_DIR}/riftConfig.cmake" "${PROJECT_BINARY_DIR}/riftConfigVersion.cmake"
        DESTINATION "${RIFT_INSTALL_CMAKE_DIR}")

# Defines the INTERFACE target rift_cgal_headers when CGAL's Generalized_map
# and the Boost headers it needs are installed; sets RIFT_CGAL_FOUND.
# CGAL is used header-only and without a geometric kernel, so neither GMP nor
# MPFR (nor find_package(CGAL), which would change compile flags) is needed.
# The headers are SYSTEM includes: their warnings must not fail -Werror builds.
if(TARGET rift_cgal_headers)
  set(RIFT_CGAL_FOUND TRUE)
  return()
endif()
find_path(RIFT_CGAL_INCLUDE_DIR CGAL/Generalized_map.h)
find_package(Boost 1.66 QUIET CONFIG COMPONENTS headers)
if(RIFT_CGAL_INCLUDE_DIR AND Boost_FOUND)
  add_library(rift_cgal_headers INTERFACE)
  target_include_directories(rift_cgal_headers SYSTEM INTERFACE "${RIFT_CGAL_INCLUDE_DIR}")
  target_link_libraries(rift_cgal_headers INTERFACE Boost::headers)
  set(RIFT_CGAL_FOUND TRUE)
else()
  set(RIFT_CGAL_FOUND FALSE)
endif()

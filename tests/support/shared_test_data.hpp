// The shared test meshes (RIFT_SHARED_MESHES, next to the repository). A test
// that needs them and does not find them FAILS by default: CI has them, and a
// lost folder must not pass as a green run. Configuring with
// -DRIFT_REQUIRE_TEST_DATA=OFF turns that into a skip for a checkout without them.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

/// Ends the current test (fail or skip, see above) unless `present`.
#define RIFT_EXPECT_SHARED_MESHES(present)                                        \
  do {                                                                            \
    if (!(present)) {                                                             \
      if (RIFT_REQUIRE_TEST_DATA) {                                               \
        FAIL() << "shared test meshes not found at " << RIFT_SHARED_MESHES        \
               << " (configure with -DRIFT_SHARED_MESHES=<folder>, or "           \
                  "-DRIFT_REQUIRE_TEST_DATA=OFF to skip these tests)";            \
      } else {                                                                    \
        GTEST_SKIP() << "shared test meshes not found at " << RIFT_SHARED_MESHES; \
      }                                                                           \
    }                                                                             \
  } while (false)

// The libFuzzer entry point of one target; CMake builds it once per target
// with RIFT_FUZZ_RUN naming the harness function (see fuzz_harness.hpp).
#include <cstddef>
#include <cstdint>

#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rift::fuzz::RIFT_FUZZ_RUN(rift::fuzz::as_text(data, size));
  return 0;
}

// riftc on a pack of N rules and N interactions (tests/compiler/unit/big_pack.hpp):
// the front end and checks alone (`riftc --check`), and the whole compile with
// the generated files written. Reported as time per pack; the counter
// `per_rule` is that time over N. This replaces a wall-clock assertion that
// once sat in the unit suite: speed is measured here, side by side, not asserted.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../compiler/unit/big_pack.hpp"
#include "driver/compile.hpp"

namespace {

void BM_RiftcCheck(benchmark::State& state) {
  const int rules = static_cast<int>(state.range(0));
  const std::string text = rift::test::big_pack(rules);
  for (auto _ : state) {
    const auto result = rift::driver::compile_text("big.rules", text, {});
    if (result.exit_code != 0) {
      state.SkipWithError(result.diagnostics.c_str());
      break;
    }
    benchmark::DoNotOptimize(result.diagnostics.data());
  }
  state.counters["per_rule"] =
      benchmark::Counter(static_cast<double>(rules), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}
BENCHMARK(BM_RiftcCheck)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond);

void BM_RiftcCompile(benchmark::State& state) {
  const int rules = static_cast<int>(state.range(0));
  const auto dir = std::filesystem::temp_directory_path() / "riftc_bench";
  std::filesystem::create_directories(dir);
  const auto file = dir / "big.rules";
  std::ofstream(file) << rift::test::big_pack(rules);
  rift::driver::Options options;
  options.inputs = {file.string()};
  options.out_dir = (dir / "out").string();
  for (auto _ : state) {
    // Unchanged outputs are not rewritten (the build system's timestamps):
    // remove them so that every iteration writes its files.
    state.PauseTiming();
    std::filesystem::remove_all(dir / "out");
    state.ResumeTiming();
    const auto result = rift::driver::compile(options);
    if (result.exit_code != 0) {
      state.SkipWithError(result.diagnostics.c_str());
      break;
    }
  }
  state.counters["per_rule"] =
      benchmark::Counter(static_cast<double>(rules), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_RiftcCompile)->Arg(10)->Arg(50)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

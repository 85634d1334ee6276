// The subcommands of the rift command line. Each add_* declares its options
// on the CLI11 app; each run_* returns the process exit code.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}
namespace rift {
class PackRegistry;
}

namespace rift::cli {

struct RunOptions {
  std::string scene;
  std::optional<std::int64_t> steps;
  std::string out;
  bool check = false;
  bool quiet = false;
  int threads = 0;  ///< 0: every core
};
CLI::App* add_run_command(CLI::App& app, RunOptions& options);
int run_run(const RunOptions& options, const PackRegistry& packs);

struct BenchOptions {
  std::string scene;
  std::optional<std::int64_t> steps;
  bool json = false;
  int threads = 0;  ///< 0: every core
};
/// Declares --threads on a subcommand (run, bench): a whole number of threads >= 1.
void add_threads_option(CLI::App& cmd, int& threads);
CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench(const BenchOptions& options, const PackRegistry& packs);

CLI::App* add_list_command(CLI::App& app);
int run_list(const PackRegistry& packs);

}  // namespace rift::cli

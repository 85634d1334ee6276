// `rift bench SCENE`: runs a scene without outputs and reports step times.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <vector>

#include "cli/commands.hpp"
#include "rift/core/parallel.hpp"
#include "rift/scene/scene_setup.hpp"

namespace rift::cli {

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run a scene without output and print step statistics (median ns per step)");
  cmd->add_option("SCENE", options.scene, "The scene file (TOML)")->required();
  cmd->add_option("--steps", options.steps, "Number of steps (default: the scene's)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag(
      "--json", options.json,
      "Print one JSON object: ns_per_step (median), steps, tears, vertices, threads, ...");
  add_threads_option(*cmd, options.threads);
  return cmd;
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads,
                 "Threads of the parallel passes (default: every core); the results are the "
                 "same for any number")
      ->check(CLI::Range(1, 4096));
}

int run_bench(const BenchOptions& options, const PackRegistry& packs) {
  set_thread_count(options.threads);
  const Scene scene = read_scene(options.scene, packs.catalog());
  std::unique_ptr<Simulation> sim = build_simulation(scene, packs);
  const std::int64_t steps = options.steps.value_or(scene.steps);
  std::vector<double> ns(static_cast<std::size_t>(steps));
  for (std::int64_t s = 0; s < steps; ++s) {
    const auto t0 = std::chrono::steady_clock::now();
    sim->step();
    ns[static_cast<std::size_t>(s)] =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
  }
  std::vector<double> sorted = ns;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  double mean = 0;
  for (double v : ns)
    mean += v;
  mean /= static_cast<double>(ns.size());
  const std::size_t vertices = sim->map().count_cells_of_dimension(0);
  const std::size_t elements = sim->map().count_cells(Orbit::all(sim->map().dimension() - 1));
  if (options.json) {
    fmt::print(
        "{{\"scene\": \"{}\", \"ns_per_step\": {:.0f}, \"mean_ns_per_step\": {:.0f}, "
        "\"min_ns_per_step\": {:.0f}, \"steps\": {}, \"tears\": {}, \"vertices\": {}, "
        "\"elements\": {}, \"threads\": {}}}\n",
        scene.name, median, mean, sorted.front(), steps, sim->tears(), vertices, elements,
        thread_count());
  } else {
    fmt::print(
        "{}: {} steps, median {:.3f} ms/step (mean {:.3f}, min {:.3f}), {} tears, {} "
        "vertices, {} elements, {} threads\n",
        scene.name, steps, median * 1e-6, mean * 1e-6, sorted.front() * 1e-6, sim->tears(),
        vertices, elements, thread_count());
  }
  return 0;
}

}  // namespace rift::cli

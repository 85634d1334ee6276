// `rift bench SCENE`: runs a scene without outputs and reports step times.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "cli/commands.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/core/parallel.hpp"
#include "rift/scene/scene_setup.hpp"

namespace rift::cli {

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "bench", "Run a scene without output and print step statistics (median ns per step)");
  cmd->add_option("SCENE", options.scene, "The scene file (TOML)")->required();
  cmd->add_option("--steps", options.steps, "Number of steps (default: the scene's)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--json", options.json,
                "Print one JSON object: ns_per_step (median), ns_per_vertex, steps, tears, "
                "vertices, threads, setup_ms, "
                "peak_rss_mb, setup_phases (each set-up phase's name, ms and rss_mb), "
                "memory_mb and memory (the arrays held after the last step, largest first: "
                "owner, what, mb), ...");
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
  const auto setup_start = std::chrono::steady_clock::now();
  SetupReport report;
  std::unique_ptr<Simulation> sim = build_simulation(scene, packs, SetupOptions{}, &report);
  const double setup_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - setup_start)
          .count();
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
  // Per vertex of the final mesh (tears add vertices): comparable across mesh sizes.
  const double ns_per_vertex = median / static_cast<double>(std::max<std::size_t>(vertices, 1));
  // The process's peak resident set so far: set-up and every step (Linux reports KiB).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  // What holds the memory after the last step, largest first.
  MemoryReport memory;
  sim->report_memory(memory);
  std::vector<MemoryReport::Item> held = memory.items();
  // std::sort with a full order (stable_sort's buffer is deprecated under clang).
  std::sort(held.begin(), held.end(), [](const MemoryReport::Item& a, const MemoryReport::Item& b) {
    if (a.bytes != b.bytes) return a.bytes > b.bytes;
    if (a.owner != b.owner) return a.owner < b.owner;
    return a.what < b.what;
  });
  constexpr double kMiB = 1024.0 * 1024.0;
  if (options.json) {
    // Phase names are the runtime's own words and interaction names
    // (identifiers): nothing to escape.
    std::string phases;
    for (const SetupPhase& p : report.phases.phases()) {
      phases += fmt::format("{}{{\"name\": \"{}\", \"ms\": {:.3f}, \"rss_mb\": {:.1f}}}",
                            phases.empty() ? "" : ", ", p.name, p.ms, p.rss_mb);
    }
    // Owners and arrays are the runtime's words, embedding and interaction
    // names (identifiers) and orbits (<0,1>): nothing to escape either.
    std::string arrays;
    for (const MemoryReport::Item& i : held) {
      arrays += fmt::format("{}{{\"owner\": \"{}\", \"what\": \"{}\", \"mb\": {:.3f}}}",
                            arrays.empty() ? "" : ", ", i.owner, i.what,
                            static_cast<double>(i.bytes) / kMiB);
    }
    fmt::print(
        "{{\"scene\": \"{}\", \"ns_per_step\": {:.0f}, \"mean_ns_per_step\": {:.0f}, "
        "\"min_ns_per_step\": {:.0f}, \"ns_per_vertex\": {:.2f}, \"steps\": {}, "
        "\"tears\": {}, \"vertices\": {}, "
        "\"elements\": {}, \"threads\": {}, \"setup_ms\": {:.3f}, \"peak_rss_mb\": {:.1f}, "
        "\"setup_phases\": [{}], \"memory_mb\": {:.3f}, \"memory\": [{}]}}\n",
        scene.name, median, mean, sorted.front(), ns_per_vertex, steps, sim->tears(), vertices,
        elements, thread_count(), setup_ms, peak_rss_mb, phases,
        static_cast<double>(memory.total()) / kMiB, arrays);
  } else {
    fmt::print(
        "{}: {} steps, median {:.3f} ms/step (mean {:.3f}, min {:.3f}), {} tears, {} "
        "vertices, {} elements, {} threads; set-up {:.1f} ms, peak RSS {:.1f} MiB\n",
        scene.name, steps, median * 1e-6, mean * 1e-6, sorted.front() * 1e-6, sim->tears(),
        vertices, elements, thread_count(), setup_ms, peak_rss_mb);
    std::string largest;
    for (std::size_t k = 0; k < std::min<std::size_t>(held.size(), 5); ++k) {
      largest += fmt::format("{}{} ({}) {:.2f} MiB", k == 0 ? "" : ", ", held[k].owner,
                             held[k].what, static_cast<double>(held[k].bytes) / kMiB);
    }
    fmt::print("arrays held: {:.2f} MiB; largest: {}\n", static_cast<double>(memory.total()) / kMiB,
               largest);
  }
  return 0;
}

}  // namespace rift::cli

#include "cli/info_command.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "rift/io/load_map.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/mesh/map_statistics.hpp"

namespace rift::cli {

CLI::App* add_info_command(CLI::App& app, InfoOptions& options) {
  CLI::App* info =
      app.add_subcommand("info", "Print the dimension and cell counts (G-map orbits) of a mesh");
  info->add_option("MESH", options.mesh,
                   "A mesh file (.obj, .msh, .mesh, .vtu, .vtk) or a generator spelling")
      ->required();
  info->add_flag("--json", options.json, "Print one JSON object instead of key=value pairs");
  info->footer(std::string("Generator spellings:\n") + kGeneratorHelp +
               "\nCounts are orbits of the G-map: a vertex whose elements form two separate\n"
               "fans counts as two vertices.");
  return info;
}

int run_info(const InfoOptions& options) {
  AssemblyReport report;
  const GMap map = load_map(options.mesh, &report);
  for (const std::string& warning : assembly_warnings(report, map.dimension()))
    fmt::print(stderr, "{}: warning: {}\n", options.mesh, warning);
  const MapStatistics stats = compute_statistics(map);
  fmt::print("{}\n", options.json ? stats.to_json() : stats.to_line());
  return 0;
}

}  // namespace rift::cli

#include "cli/app.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cli/commands.hpp"
#include "cli/info_command.hpp"
#include "cli/large_allocations.hpp"
#include "rift/core/input_error.hpp"
#include "rift/pack/pack.hpp"

#ifndef RIFT_VERSION
#define RIFT_VERSION "0.1.0"
#endif

namespace rift::cli {

int run(int argc, char** argv, const PackRegistry& packs) {
  // Links the huge-page operator new into the executable (large_allocations.cpp).
  [[maybe_unused]] const bool huge_pages = large_allocations_in_huge_pages();
  give_large_blocks_back_when_freed();
  CLI::App app{"rift: simulate deformable bodies that tear and fracture, with G-maps and rules"};
  app.set_version_flag("--version", std::string("rift ") + RIFT_VERSION);
  app.require_subcommand(1);
  app.footer("Run 'rift COMMAND --help' for the options of a command. Documentation: docs/.");

  RunOptions run_options;
  BenchOptions bench_options;
  InfoOptions info_options;
  CLI::App* run_cmd = add_run_command(app, run_options);
  CLI::App* bench_cmd = add_bench_command(app, bench_options);
  CLI::App* info_cmd = add_info_command(app, info_options);
  CLI::App* list_cmd = add_list_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (run_cmd->parsed()) return run_run(run_options, packs);
    if (bench_cmd->parsed()) return run_bench(bench_options, packs);
    if (info_cmd->parsed()) return run_info(info_options);
    if (list_cmd->parsed()) return run_list(packs);
  } catch (const InputError& e) {
    fmt::print(stderr, "{}\n", e.what());  // already "file:line: error: ..."
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rift: error: {}\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace rift::cli

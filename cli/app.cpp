#include "cli/app.hpp"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cli/info_command.hpp"

#ifndef RIFT_VERSION
#define RIFT_VERSION "0.1.0"
#endif

namespace rift::cli {

int run(int argc, char** argv) {
  CLI::App app{"rift: simulate deformable bodies that tear and fracture, with G-maps and rules"};
  app.set_version_flag("--version", std::string("rift ") + RIFT_VERSION);
  app.require_subcommand(1);

  InfoOptions info;
  CLI::App* info_cmd = add_info_command(app, info);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (info_cmd->parsed()) return run_info(info);
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    // MeshError messages already read "file:line: error: ...".
    if (msg.find(": error: ") != std::string::npos) {
      fmt::print(stderr, "{}\n", msg);
    } else {
      fmt::print(stderr, "rift: error: {}\n", msg);
    }
    return 1;
  }
  return 0;
}

}  // namespace rift::cli

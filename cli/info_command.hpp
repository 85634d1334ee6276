// `rift info MESH`: dimension and cell counts of a mesh file or generator spelling.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace rift::cli {

struct InfoOptions {
  std::string mesh;
  bool json = false;
};

/// Adds the `info` subcommand to `app`; `options` receives its arguments.
CLI::App* add_info_command(CLI::App& app, InfoOptions& options);
int run_info(const InfoOptions& options);

}  // namespace rift::cli

// The rift command line, shared by `rift` and every simulator built with
// rift_add_simulator: one entry point that parses arguments and dispatches
// to a subcommand.
#pragma once

namespace rift::cli {

/// Runs the command line; returns the process exit code (0 success,
/// 1 bad input or failed run, 2 usage error).
int run(int argc, char** argv);

}  // namespace rift::cli

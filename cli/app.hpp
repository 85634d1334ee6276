// The rift command line, shared by `rift` and every simulator built with
// rift_add_simulator: one entry point that parses arguments and dispatches
// to a subcommand. The packs compiled into the executable are passed in.
#pragma once

namespace rift {
class PackRegistry;
}

namespace rift::cli {

/// Runs the command line; returns the process exit code (0 success,
/// 1 bad input or failed run, 2 usage error, 130 interrupted).
int run(int argc, char** argv, const PackRegistry& packs);

}  // namespace rift::cli

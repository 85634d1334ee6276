// riftc: checks rule packs and generates C++ for them.
#include <cstdio>
#include <iostream>
#include <string>

#include "diag/diagnostics.hpp"
#include "driver/compile.hpp"

namespace {

constexpr const char* kUsage = R"(usage: riftc FILE.rules... [-o OUTDIR] [options]

Checks rift rule packs (docs/language.md) and, with -o, writes the C++ that
implements their rules, interactions and criteria into OUTDIR.

options:
  -o OUTDIR       write generated C++ into OUTDIR (without it riftc only checks):
                  OUTDIR/PACK.hpp and OUTDIR/PACK.cpp, PACK being the first file's pack
  --depfile FILE  with -o, also write the files read (includes and imports too) as a
                  Make-style dependency file, for build systems
  -I DIR          also look for included and imported files in DIR (after the
                  including file's own folder); may be repeated
  --no-line-directives
                  no #line directives into the .rules files: the output then
                  does not change when lines are added to them (diffable)
  --require-jacobians
                  an error when an interaction's forces cannot be differentiated
                  (for packs meant for integrator = "implicit_euler"); without
                  it such an interaction only lacks Jacobians
  -Wno-NAME       disable warning NAME
  -Werror         treat warnings as errors
  --list-warnings print the names of all warnings
  -h, --help      print this help
  --version       print riftc's version

exit status: 0 when every file compiled, 1 on any error.
)";

int usage_error(const std::string& message) {
  std::cerr << "riftc: error: " << message << "\nTry 'riftc --help'.\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  rift::driver::Options options;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (arg == "--version") {
      std::cout << "riftc 0.1.0\n";
      return 0;
    }
    if (arg == "--list-warnings") {
      for (const auto& w : rift::diag::known_warnings())
        std::cout << w << '\n';
      return 0;
    }
    if (arg == "-o") {
      if (k + 1 >= argc) return usage_error("-o needs a directory");
      options.out_dir = argv[++k];
    } else if (arg == "--no-line-directives") {
      options.line_directives = false;
    } else if (arg == "--depfile") {
      if (k + 1 >= argc) return usage_error("--depfile needs a file name");
      options.depfile = argv[++k];
    } else if (arg == "-I" || (arg.rfind("-I", 0) == 0 && arg.size() > 2)) {
      if (arg == "-I" && k + 1 >= argc) return usage_error("-I needs a directory");
      options.include_dirs.push_back(arg == "-I" ? std::string(argv[++k]) : arg.substr(2));
    } else if (arg == "--require-jacobians") {
      options.require_jacobians = true;
    } else if (arg == "-Werror") {
      options.warnings_as_errors = true;
    } else if (arg.rfind("-Wno-", 0) == 0) {
      const std::string name = arg.substr(5);
      bool known = false;
      for (const auto& w : rift::diag::known_warnings())
        known = known || w == name;
      if (!known) return usage_error("unknown warning '" + name + "' (see --list-warnings)");
      options.disabled_warnings.push_back(name);
    } else if (!arg.empty() && arg[0] == '-') {
      return usage_error("unknown option '" + arg + "'");
    } else {
      options.inputs.push_back(arg);
    }
  }
  if (options.inputs.empty()) return usage_error("no input files");
  const rift::driver::Result result = rift::driver::compile(options);
  std::cerr << result.diagnostics;
  return result.exit_code;
}

#include "driver/compile.hpp"

#include "check/embeddings.hpp"
#include "check/topology.hpp"
#include "check/types.hpp"
#include "check/warnings.hpp"
#include "parse/loader.hpp"
#include "resolve/resolve.hpp"

namespace rift::driver {

namespace {

void run_checks(const ast::Program& program, diag::Diagnostics& diags) {
  // Semantic checks on a partly parsed pack would mostly report the holes
  // that syntax errors left: report the syntax errors alone.
  if (diags.has_errors()) return;
  if (program.dimension < 0 || program.dimension > 3) {
    for (const ast::File& f : program.files) {
      if (f.has_header && f.dimension == program.dimension) {
        diags.error(f.dimension_loc,
                    "dimension " + std::to_string(f.dimension) +
                        " is not supported; rift handles G-maps of dimension 0 to 3");
        return;  // every other check depends on the dimension
      }
    }
  }
  const resolve::Symbols symbols = resolve::collect_symbols(program, diags);
  resolve::resolve_names(program, symbols, diags);
  check::check_types(program, symbols, diags);
  const auto rules = check::check_rules(program, diags);
  check::check_interactions(program, diags);
  check::check_applies(program, rules, diags);
  check::check_embeddings(rules, symbols, diags);
  check::check_unused(program, diags);
}

Result finish(diag::Diagnostics& diags) {
  Result r;
  r.diagnostics = diags.render();
  r.exit_code = diags.has_errors() ? 1 : 0;
  return r;
}

void configure(diag::Diagnostics& diags, const Options& options) {
  for (const std::string& w : options.disabled_warnings)
    diags.disable_warning(w);
  diags.set_warnings_as_errors(options.warnings_as_errors);
}

}  // namespace

Result compile(const Options& options) {
  diag::SourceManager sources;
  diag::Diagnostics diags(sources);
  configure(diags, options);
  const ast::Program program = parse::load_program(options.inputs, sources, diags);
  run_checks(program, diags);
  return finish(diags);
}

Result compile_text(const std::string& path, const std::string& text, const Options& options) {
  diag::SourceManager sources;
  diag::Diagnostics diags(sources);
  configure(diags, options);
  const ast::Program program = parse::load_text(path, text, sources, diags);
  run_checks(program, diags);
  return finish(diags);
}

}  // namespace rift::driver

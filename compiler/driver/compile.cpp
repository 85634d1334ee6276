#include "driver/compile.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "check/criterion_nodes.hpp"
#include "check/embeddings.hpp"
#include "check/jacobian_blocks.hpp"
#include "check/kernels.hpp"
#include "check/topology.hpp"
#include "check/types.hpp"
#include "check/warnings.hpp"
#include "emit/pack_emit.hpp"
#include "lower/derivative.hpp"
#include "lower/interaction_plan.hpp"
#include "lower/kernel_plan.hpp"
#include "lower/pack_plan.hpp"
#include "parse/loader.hpp"
#include "parse/state_embeddings.hpp"
#include "resolve/resolve.hpp"

namespace rift::driver {

namespace {

struct Checked {
  resolve::Symbols symbols;
  check::ExprTypes types;
  std::vector<check::CheckedRule> rules;
  std::vector<check::CheckedInteraction> interactions;
};

void require_jacobians(const Checked& checked, diag::Diagnostics& diags) {
  for (const check::CheckedInteraction& ci : checked.interactions) {
    const lower::InteractionPlan plan = lower::plan_interaction(ci, checked.symbols, checked.types);
    const lower::DerivativePlan d =
        lower::plan_derivative(plan.body, plan.kernel, ci.interaction->name.loc);
    if (!d.available) {
      diags.error(d.where, "interaction '" + ci.interaction->name.text +
                               "' has no Jacobian (--require-jacobians): " + d.why);
    }
  }
}

void run_checks(const ast::Program& program, diag::Diagnostics& diags, Checked& out) {
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
  out.symbols = resolve::collect_symbols(program, diags);
  resolve::resolve_names(program, out.symbols, diags);
  check::check_types(program, out.symbols, out.types, diags);
  out.rules = check::check_rules(program, diags);
  out.interactions = check::check_interactions(program, out.symbols, diags);
  check::check_applies(program, out.rules, diags);
  check::check_kernels(program, out.symbols, diags);
  check::check_jacobian_blocks(program, diags);
  check::check_criterion_nodes(program, diags);
  check::check_generated_names(program, out.symbols, diags);
  check::check_embeddings(out.rules, out.symbols, diags);
  check::check_unused(program, out.symbols, diags);
}

/// Writes `text` unless the file already holds it, so that an unchanged
/// output does not make the build system recompile its dependents.
bool write_if_changed(const std::filesystem::path& path, const std::string& text) {
  {
    std::ifstream in(path, std::ios::binary);
    if (in) {
      std::ostringstream old;
      old << in.rdbuf();
      if (old.str() == text) return true;
    }
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

/// "out.hpp: a.rules b.rules": every file read, includes too, so that editing an
/// included pack regenerates its includers.
std::string depfile_text(const std::filesystem::path& target, const diag::SourceManager& sources) {
  auto escape = [](const std::string& path) {
    std::string out;
    for (char c : path) {
      if (c == ' ' || c == '#' || c == '$') out += '\\';
      out += c;
    }
    return out;
  };
  std::string text = escape(target.string()) + ":";
  for (std::size_t k = 0; k < sources.size(); ++k) {
    const std::string& path = sources.file(static_cast<int>(k)).path;
    if (path == parse::kStateSource) continue;  // built in, not a file
    std::error_code ec;
    const auto abs = std::filesystem::absolute(path, ec);
    text += ' ';
    text += escape(ec ? path : abs.lexically_normal().string());
  }
  return text + "\n";
}

void generate(const ast::Program& program, const Checked& checked,
              const diag::SourceManager& sources, const Options& options,
              diag::Diagnostics& diags) {
  const std::string& out_dir = options.out_dir;
  const std::string& depfile = options.depfile;
  emit::PackModel model;
  model.line_directives = options.line_directives;
  model.program = &program;
  // lower: every declaration to its plan, its expressions in the IR.
  const lower::PackPlan plan = lower::plan_pack(program, checked.rules, checked.interactions,
                                                checked.symbols, checked.types);
  model.plan = &plan;
  model.pack = program.files.empty() ? "pack" : program.files.front().pack.text;
  model.pack_namespace = "rift::packs::" + model.pack;
  const emit::GeneratedPack pack = emit::generate_pack(model, sources);
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  const std::filesystem::path dir(out_dir);
  if (ec || !write_if_changed(dir / pack.header_name, pack.header) ||
      !write_if_changed(dir / pack.source_name, pack.source)) {
    diags.error({}, "cannot write the generated files into '" + out_dir + "'");
    return;
  }
  if (!depfile.empty() &&
      !write_if_changed(depfile, depfile_text(dir / pack.header_name, sources))) {
    diags.error({}, "cannot write the dependency file '" + depfile + "'");
  }
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
  const ast::Program program =
      parse::load_program(options.inputs, sources, diags, options.include_dirs);
  Checked checked;
  run_checks(program, diags, checked);
  if (options.require_jacobians && !diags.has_errors()) require_jacobians(checked, diags);
  if (!diags.has_errors() && !options.out_dir.empty()) {
    generate(program, checked, sources, options, diags);
  }
  return finish(diags);
}

Result compile_text(const std::string& path, const std::string& text, const Options& options) {
  diag::SourceManager sources;
  diag::Diagnostics diags(sources);
  configure(diags, options);
  const ast::Program program = parse::load_text(path, text, sources, diags);
  Checked checked;
  run_checks(program, diags, checked);
  if (options.require_jacobians && !diags.has_errors()) require_jacobians(checked, diags);
  if (!diags.has_errors() && !options.out_dir.empty()) {
    generate(program, checked, sources, options, diags);
  }
  return finish(diags);
}

Lowered lower_text(const std::string& path, const std::string& text) {
  struct State {
    diag::SourceManager sources;
    diag::Diagnostics diags{sources};
    ast::Program program;
    Checked checked;
  };
  auto state = std::make_shared<State>();
  state->program = parse::load_text(path, text, state->sources, state->diags);
  run_checks(state->program, state->diags, state->checked);
  Lowered out;
  out.ok = !state->diags.has_errors();
  out.diagnostics = state->diags.render();
  if (out.ok) {
    for (const check::CheckedInteraction& ci : state->checked.interactions)
      out.interactions.push_back(
          lower::plan_interaction(ci, state->checked.symbols, state->checked.types));
  }
  out.keep_alive = state;
  return out;
}

}  // namespace rift::driver

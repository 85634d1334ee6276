#include "check/warnings.hpp"

#include "check/builtins.hpp"

namespace rift::check {

namespace {

void unused_lets(const std::vector<ast::Let>& lets, const resolve::Symbols& symbols,
                 diag::Diagnostics& diags) {
  for (const ast::Let& l : lets) {
    if (symbols.uses(l) == 0) {
      diags.warning("unused-variable", l.name.loc, "'" + l.name.text + "' is never used");
    }
  }
}

void unused_params(const std::vector<ast::Param>& params, const char* kind,
                   const std::string& owner, const resolve::Symbols& symbols,
                   diag::Diagnostics& diags) {
  for (const ast::Param& p : params) {
    if (symbols.uses(p) == 0) {
      diags.warning(
          "unused-parameter", p.name.loc,
          "parameter '" + p.name.text + "' of " + kind + " '" + owner + "' is never used");
    }
  }
}

}  // namespace

void check_unused(const ast::Program& program, const resolve::Symbols& symbols,
                  diag::Diagnostics& diags) {
  for (const ast::File& file : program.files) {
    // An imported pack's declarations are reported when that pack compiles.
    if (!file.owner.empty()) continue;
    for (const ast::Function& f : file.functions) {
      unused_lets(f.lets, symbols, diags);
      unused_params(f.params, "function", f.name.text, symbols, diags);
      // An included pack, or a pack of functions only, is a library: its
      // users need not call all of it.
      const bool library = file.included || ast::declares_only_functions(file);
      const auto calls = symbols.calls.find(&f);
      // Not a duplicate or a built-in's name, which are errors already.
      const bool declared = symbols.function(f.name.text) == &f && !builtin(f.name.text);
      if (declared && !library && (calls == symbols.calls.end() || calls->second == 0)) {
        diags.warning("unused-function", f.name.loc,
                      "function '" + f.name.text + "' is never called");
      }
    }
    for (const ast::Rule& r : file.rules) {
      unused_lets(r.lets, symbols, diags);
      for (const ast::Param& p : r.params) {
        if (symbols.uses(p) == 0) {
          diags.warning(
              "unused-parameter", p.name.loc,
              "parameter '" + p.name.text + "' of rule '" + r.name.text + "' is never used");
        }
      }
    }
    for (const ast::Interaction& i : file.interactions) {
      unused_lets(i.lets, symbols, diags);
      unused_params(i.params, "interaction", i.name.text, symbols, diags);
    }
    for (const ast::Script& sc : file.scripts) {
      unused_lets(sc.lets, symbols, diags);
      for (const ast::Param& p : sc.params) {
        if (symbols.uses(p) == 0) {
          diags.warning(
              "unused-parameter", p.name.loc,
              "parameter '" + p.name.text + "' of script '" + sc.name.text + "' is never used");
        }
      }
    }
    for (const ast::Criterion& c : file.criteria) {
      unused_lets(c.lets, symbols, diags);
      unused_params(c.params, "criterion", c.name.text, symbols, diags);
    }
  }
}

}  // namespace rift::check

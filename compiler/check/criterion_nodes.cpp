#include "check/criterion_nodes.hpp"

#include <string>
#include <utility>
#include <vector>

#include "ast/orbit_text.hpp"
#include "check/alpha_word.hpp"

namespace rift::check {

namespace {

using ast::path_text;

void check_criterion(const ast::Criterion& crit, int dimension, diag::Diagnostics& diags) {
  // Each node's path from the criterion's dart, and its normal form.
  std::vector<std::string> names = {crit.dart.text};
  std::vector<std::vector<int>> words = {{}};
  std::vector<std::vector<int>> forms = {{}};
  for (const ast::CriterionNode& n : crit.nodes) {
    bool in_range = true;
    for (int h : n.hops) {
      if (h >= 0 && h <= dimension) continue;
      in_range = false;
      diags.error(n.path_loc, "link dimension " + std::to_string(h) + " is out of range 0.." +
                                  std::to_string(dimension));
    }
    std::size_t from = names.size();
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (names[k] == n.from.text) from = k;
    }
    if (from == names.size() || !in_range || n.hops.empty()) return;  // reported already
    std::vector<int> word = words[from];
    word.insert(word.end(), n.hops.begin(), n.hops.end());
    std::vector<int> form = normal_form(word);
    for (std::size_t k = 0; k < forms.size(); ++k) {
      if (forms[k] != form) continue;
      diags
          .error(n.path_loc, "node '" + n.name.text + "' is always the dart '" + names[k] + "' (" +
                                 path_text(crit.dart.text, word) + " is " +
                                 path_text(crit.dart.text, form) +
                                 "): the nodes of a criterion are distinct darts, so it would "
                                 "never hold")
          .notes.push_back({k == 0 ? crit.dart.loc : crit.nodes[k - 1].name.loc,
                            "'" + names[k] + "' declared here"});
      break;
    }
    names.push_back(n.name.text);
    words.push_back(std::move(word));
    forms.push_back(std::move(form));
  }
}

}  // namespace

void check_criterion_nodes(const ast::Program& program, diag::Diagnostics& diags) {
  for (const ast::File& file : program.files) {
    for (const ast::Criterion& crit : file.criteria)
      check_criterion(crit, program.dimension, diags);
  }
}

}  // namespace rift::check

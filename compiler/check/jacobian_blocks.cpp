#include "check/jacobian_blocks.hpp"

#include <map>
#include <string>
#include <tuple>

#include "check/kernels.hpp"

namespace rift::check {

namespace {

bool is_pattern_node(const ast::Interaction& inter, const std::string& name) {
  for (const ast::NodeDecl& n : inter.pattern.nodes)
    if (n.name.text == name) return true;
  return false;
}

/// "a.f, b.f" (or "none"): what a block's force may name.
std::string forces_text(const ast::Interaction& inter) {
  std::string out;
  for (const ast::Assign& f : inter.forces) {
    if (!out.empty()) out += ", ";
    out += f.node.text + "." + f.embedding.text;
  }
  return out.empty() ? "none" : out;
}

void check_interaction(const ast::Interaction& inter, diag::Diagnostics& diags) {
  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::map<Key, const ast::JacobianBlock*> given;
  for (const ast::JacobianBlock& j : inter.jacobians) {
    bool ok = true;
    const ast::Assign* stored = nullptr;
    for (const ast::Assign& f : inter.forces) {
      if (f.node.text == j.force_node.text && f.embedding.text == j.force.text) {
        stored = &f;
        break;
      }
    }
    if (!stored) {
      diags
          .error(j.force.loc, "interaction '" + inter.name.text + "' stores no force '" +
                                  j.force_node.text + "." + j.force.text +
                                  "': a Jacobian block is of a force its `force` statements " +
                                  "store (here: " + forces_text(inter) + ")")
          .notes.push_back({inter.name.loc, "the interaction"});
      ok = false;
    }
    if (!is_pattern_node(inter, j.by_node.text)) {
      diags
          .error(j.by_node.loc,
                 "'" + j.by_node.text + "' is not a node of the pattern of '" + inter.name.text +
                     "': a Jacobian block is by the position or velocity of " + "one of its nodes")
          .notes.push_back({inter.pattern.loc, "the pattern"});
      ok = false;
    }
    if (j.by_state.text != kPositionEmbedding && j.by_state.text != kVelocityEmbedding) {
      diags.error(j.by_state.loc, "a Jacobian block is by '" + j.by_node.text + ".position' or '" +
                                      j.by_node.text + ".velocity', not '" + j.by_node.text + "." +
                                      j.by_state.text + "'");
      ok = false;
    }
    if (!ok) continue;
    const Key key{j.force_node.text, j.force.text, j.by_node.text, j.by_state.text};
    auto [it, fresh] = given.emplace(key, &j);
    if (!fresh) {
      diags
          .error(j.loc, "the block of '" + j.force_node.text + "." + j.force.text + "' by '" +
                            j.by_node.text + "." + j.by_state.text + "' is given twice")
          .notes.push_back({it->second->loc, "first given here"});
    }
  }
}

}  // namespace

void check_jacobian_blocks(const ast::Program& program, diag::Diagnostics& diags) {
  for (const ast::File& file : program.files) {
    for (const ast::Interaction& inter : file.interactions)
      check_interaction(inter, diags);
  }
}

}  // namespace rift::check

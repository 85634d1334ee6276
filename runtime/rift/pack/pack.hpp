// A rule pack compiled by riftc: its embeddings, initialisers, rules,
// interactions and criteria, and factories that bind them to a scene.
// Simulators list their packs in a PackRegistry.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "rift/pack/catalog.hpp"
#include "rift/pack/component_use.hpp"
#include "rift/pack/rule.hpp"
#include "rift/sim/criterion.hpp"
#include "rift/sim/force_model.hpp"

namespace rift {

struct EmbeddingDecl {
  std::string name;
  ValueType type = ValueType::kReal;
  Orbit orbit;
  MergePolicy policy = MergePolicy::kKeepFirst;
  Value default_value = Real(0);
};

class Pack {
 public:
  virtual ~Pack() = default;
  virtual const std::string& name() const = 0;
  virtual int dimension() const = 0;
  /// One line for `rift list`.
  virtual const std::string& description() const = 0;
  virtual const std::vector<EmbeddingDecl>& embeddings() const = 0;
  /// Interactions and criteria with their parameters.
  virtual const Catalog& catalog() const = 0;
  virtual std::vector<std::string> rule_names() const = 0;

  /// Runs the pack's initialisers on the initial map (rest values, masses...),
  /// after declaring its embeddings.
  virtual void initialise(GMap& map) const = 0;
  virtual std::unique_ptr<ForceModel> make_interaction(const ComponentUse& use) const = 0;
  virtual std::unique_ptr<Criterion> make_criterion(const ComponentUse& use) const = 0;
  virtual std::unique_ptr<Rule> make_rule(const std::string& name) const = 0;
};

/// Declares every embedding of `decls` the map lacks; throws
/// std::invalid_argument when one exists with another type or orbit.
void declare_embeddings(GMap& map, const std::vector<EmbeddingDecl>& decls);

class PackRegistry {
 public:
  void add(std::unique_ptr<Pack> pack) { packs_.push_back(std::move(pack)); }
  /// The pack named `name`, or nullptr (a pack registers the packs it
  /// imports unless they are registered already).
  const Pack* find(const std::string& name) const;
  const std::vector<std::unique_ptr<Pack>>& packs() const { return packs_; }
  /// The interactions and criteria of every pack (of one dimension, or all with 0).
  Catalog catalog(int dimension = 0) const;
  /// The pack offering an interaction / criterion for maps of `dimension`.
  const Pack* pack_of_interaction(const std::string& name, int dimension) const;
  const Pack* pack_of_criterion(const std::string& name, int dimension) const;

 private:
  std::vector<std::unique_ptr<Pack>> packs_;
};

}  // namespace rift

// What a simulator offers a scene: its interactions and criteria with their
// parameters. Generated rule packs fill it; scene files are checked against it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rift/embed/value.hpp"

namespace rift {

struct ParamSpec {
  std::string name;
  ValueType type = ValueType::kReal;
  std::optional<Value> default_value;  ///< none: the scene must give it
  std::string description;
  bool positive = false;  ///< reals and ints must be > 0
  bool non_negative = false;
};

struct ComponentSpec {
  std::string name;
  std::string description;
  std::vector<ParamSpec> params;
  int dimension = 0;  ///< 2 or 3: the maps it runs on; 0: any
  /// Interactions: the force embeddings they store for criteria to read.
  std::vector<std::string> stores = {};
  /// Criteria: what their lets, measure, rule arguments and same-pack script read (the set-up
  /// stores those forces; a criterion reading only forces nothing stores can never fire).
  std::vector<std::string> reads = {};

  const ParamSpec* find_param(const std::string& param) const {
    for (const ParamSpec& p : params) {
      if (p.name == param) return &p;
    }
    return nullptr;
  }
};

struct Catalog {
  std::vector<ComponentSpec> interactions;
  std::vector<ComponentSpec> criteria;

  static const ComponentSpec* find(const std::vector<ComponentSpec>& list,
                                   const std::string& name) {
    for (const ComponentSpec& c : list) {
      if (c.name == name) return &c;
    }
    return nullptr;
  }
};

}  // namespace rift

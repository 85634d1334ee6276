// What a scene asks of one interaction or criterion a pack offers: its name
// and every parameter resolved. A pack's factories build their components
// from it (Pack::make_interaction, Pack::make_criterion); the scene reader
// fills it, checked against the pack's catalog (rift/pack/catalog.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "rift/embed/value.hpp"

namespace rift {

/// A parameter's value with the line of the scene that gave it (0: its
/// default), for messages.
struct SceneParam {
  Value value;
  int line = 0;
};

/// One [[interaction]] or [[criterion]] table: a name from the catalog and
/// every parameter resolved (given, or its default).
struct ComponentUse {
  std::string name;
  int line = 0;
  std::map<std::string, SceneParam> params;

  /// The parameter's value; an integer given for a real is converted.
  Real real(const std::string& param) const;
  Vec3 vec3(const std::string& param) const;
  std::int64_t integer(const std::string& param) const;
  bool boolean(const std::string& param) const;
};

}  // namespace rift

#include "rift/gmap/state_columns.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rift {

namespace {

template <class T>
constexpr state::Kind kind_of() {
  if constexpr (std::is_same_v<T, Vec3>) {
    return state::Kind::kVec3;
  } else if constexpr (std::is_same_v<T, Real>) {
    return state::Kind::kReal;
  } else if constexpr (std::is_same_v<T, Bool>) {
    return state::Kind::kBool;
  } else {
    static_assert(std::is_same_v<T, std::int64_t>, "state embeddings are vec3, real, bool or int");
    return state::Kind::kInt;
  }
}

template <class T>
T fill_value(const state::Declaration& d) {
  if constexpr (std::is_same_v<T, Vec3>) {
    return Vec3::Constant(d.fill);
  } else if constexpr (std::is_same_v<T, Bool>) {
    return Bool(d.fill != 0);
  } else {
    return static_cast<T>(d.fill);
  }
}

}  // namespace

Orbit state_orbit(const state::Declaration& declaration, int dimension) {
  switch (declaration.where) {
    case state::Where::kVertex:
      return Orbit::cell(0, dimension);
    case state::Where::kCorner:
      return Orbit::all(dimension - 1).without(0);
    case state::Where::kElement:
      return Orbit::all(dimension - 1);
  }
  return Orbit();
}

MergePolicy state_policy(const state::Declaration& declaration) {
  switch (declaration.merge) {
    case state::Merge::kKeep:
      return MergePolicy::kKeepFirst;
    case state::Merge::kSum:
      return MergePolicy::kSum;
    case state::Merge::kMean:
      return MergePolicy::kMean;
  }
  return MergePolicy::kKeepFirst;
}

template <class T>
Embedding<T> state_embedding(GMap& map, std::string_view name) {
  const state::Declaration* d = state::find(name);
  if (d == nullptr || d->kind != kind_of<T>()) {
    throw std::logic_error("'" + std::string(name) + "' is not a state embedding of this type");
  }
  const Orbit orbit = state_orbit(*d, map.dimension());
  const MergePolicy policy = state_policy(*d);
  if (const ColumnBase* column = map.find_column(name)) {
    const std::string what = "the map's embedding '" + std::string(name) + "'";
    Embedding<T> e = map.embedding<T>(name);  // throws when the column holds another type
    if (e.orbit() != orbit) {
      throw std::invalid_argument(what + " lives on " + e.orbit().str() + ", not on " +
                                  orbit.str() + " as the simulator's does");
    }
    if (column->policy() != policy) {
      throw std::invalid_argument(what + " merges by '" + std::string(to_string(column->policy())) +
                                  "', not by '" + std::string(to_string(policy)) +
                                  "' as the simulator's does");
    }
    return e;
  }
  return map.add_embedding<T>(std::string(name), orbit, policy, fill_value<T>(*d));
}

template Embedding<Vec3> state_embedding<Vec3>(GMap&, std::string_view);
template Embedding<Real> state_embedding<Real>(GMap&, std::string_view);
template Embedding<Bool> state_embedding<Bool>(GMap&, std::string_view);
template Embedding<std::int64_t> state_embedding<std::int64_t>(GMap&, std::string_view);

}  // namespace rift

// The columns of the simulator's state embeddings (rift/core/state_embeddings.hpp)
// on a map: created from the one table riftc also reads, so that a pack and
// the runtime never disagree on an orbit or a merge policy.
#pragma once

#include <string_view>

#include "rift/core/state_embeddings.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift {

/// The orbit the state embedding lives on in a map of dimension `dimension`.
Orbit state_orbit(const state::Declaration& declaration, int dimension);

/// The runtime's merge policy for the table's merge rule.
MergePolicy state_policy(const state::Declaration& declaration);

/// The state embedding `name` of `map`: the map's column when it has one,
/// else a new column with the table's orbit, policy and value. A column of
/// that name on another orbit, of another type or with another merge policy
/// is an error (std::invalid_argument naming what differs): the map did not
/// come from rift's mesh assembly or a pack riftc compiled.
/// T is Vec3, Real, Bool or std::int64_t, as the table's kind says.
template <class T>
Embedding<T> state_embedding(GMap& map, std::string_view name);

}  // namespace rift

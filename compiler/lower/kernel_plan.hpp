// Lowering of an interaction to a force kernel: the straight-line walk from
// the support dart to every pattern node, the links and the injectivity to
// verify, and the slots a match caches so that the force loop reads every
// value by index, without traversing the map.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lower/checked.hpp"
#include "lower/rule_plan.hpp"

namespace rift::lower {

/// One slot a match caches: the slot of the dart `node@hops...` in the
/// attachment of `orbit`, computed through embedding `via`.
struct SlotUse {
  int node = 0;
  std::vector<int> hops;
  std::vector<int> orbit;  // sorted dimensions
  std::string via;         // an embedding on that orbit
  bool vertex = false;     // the vertex orbit: indexes ForceInput::x / ::v and f
};

struct ForceStore {
  int vertex_slot = 0;  // where f gets the force
  int store_slot = 0;   // where the force embedding stores it
  std::string embedding;
};

struct KernelPlan {
  std::vector<std::string> nodes;  // pattern node names, hook first
  MatchPlan match;                 // follows and arc checks (node indices as in the pattern)
  /// The pairs of nodes whose darts find compares for an injective match
  /// (distinct_pairs.hpp), one per class of pairs that collide together.
  std::vector<std::pair<int, int>> distinct;
  std::vector<int> node_order;  // pattern node indices in the order they are reached
  std::vector<int> depth;       // links from the support dart, per pattern node
  std::vector<SlotUse> slots;
  std::vector<ForceStore> forces;  // parallel to the interaction's `force` statements
  std::vector<int> stores;         // the slot of each `store =`, then of each `store +=`
  int radius = 0;                  // kRadius: the farthest dart any read or check touches
  /// kReach (runtime/rift/sim/reach.hpp): the links from the support dart to
  /// each dart a match reads (its nodes, and the darts read through hops),
  /// without the first links that stay in the support orbit, each word once,
  /// in the order they are met. Empty when the pattern has more than one hook.
  std::vector<std::vector<int>> reach;

  /// Index of the slot of node@hops on `orbit`, or -1.
  int find(int node, const std::vector<int>& hops, const std::vector<int>& orbit) const;
};

/// The vertex orbit <1..n> of a map of dimension n.
std::vector<int> vertex_orbit(int dimension);

KernelPlan plan_kernel(const check::CheckedInteraction& inter, const resolve::Symbols& symbols);

}  // namespace rift::lower

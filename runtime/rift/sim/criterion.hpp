// The interface between the simulation loop and a tearing criterion (§5), as
// ForceModel is for an interaction: evaluated on every orbit of its type after
// forces are known; where it holds, it proposes to apply its rule. riftc
// generates the criteria; the loop knows none of them in particular.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rift/core/candidate_payload.hpp"
#include "rift/core/memory_report.hpp"
#include "rift/gmap/gmap.hpp"

namespace rift {

/// One place where a criterion holds, with what its rule needs to apply.
struct TearCandidate {
  std::uint32_t criterion = 0;  ///< index of the criterion in the simulation
  Dart at = kNoDart;            ///< the dart the criterion was evaluated at
  /// How far the measure passed its threshold (measure - threshold for > and
  /// >=, threshold - measure for < and <=): larger is more critical, and
  /// candidates are applied largest first.
  Real measure = 0;
  /// The values of the criterion's `apply` arguments at detection, laid out
  /// by riftc (rift/core/candidate_payload.hpp; read and written through
  /// rift/generated/candidate_payload.hpp): the rule applies with the state
  /// that made the criterion hold, not one an earlier tear of the step left.
  std::array<Real, kCandidatePayloadReals> payload{};
  std::uint32_t payload_reals = 0;  ///< how many of `payload` the criterion filled
};

class Criterion {
 public:
  virtual ~Criterion() = default;
  virtual const std::string& name() const = 0;
  /// Binds embeddings; called once on the initial map.
  virtual void initialise(GMap& map) = 0;
  /// Appends a candidate (with `criterion` left to the caller) for every
  /// orbit where the criterion holds.
  virtual void collect(const GMap& map, std::vector<TearCandidate>& out) const = 0;
  /// Applies the criterion's rule at the candidate. The neighbourhood may
  /// have changed since collect(): the rule is matched again, and the call
  /// returns false when it no longer applies. Appends touched darts.
  virtual bool apply(GMap& map, const TearCandidate& candidate, std::vector<Dart>& touched) = 0;
  /// After rewrites took the map from topology version `from` to its
  /// current one, touching exactly the darts of `touched`: a criterion that
  /// keeps anything derived from the links (its cells, CellList) follows
  /// them here instead of building it anew from the whole map.
  virtual void topology_changed(const GMap& map, std::span<const Dart> touched,
                                std::uint64_t from) {
    (void)map;
    (void)touched;
    (void)from;
  }
  /// Its arrays (the cells it visits, ...) under "criterion NAME".
  virtual void report_memory(MemoryReport& /*report*/) const {}
};

}  // namespace rift

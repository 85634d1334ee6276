// Adapts a generated interaction kernel to the ForceModel interface, with
// its matches cached in a MatchCache. The kernel supplies:
//
//   using Match = ...;                      // trivially copyable: slots and darts
//   static constexpr Orbit kSupport;        // the orbit carrying the parameters
//   static constexpr int kRadius;           // links from the support dart to the farthest matched
//   dart const std::string& name() const; void initialise(GMap&);                 // declare
//   embeddings, compute rest values bool match(const GMap&, Dart, Match&) const; void
//   add_forces(const Match&, const ForceInput&, Vec3* f, bool store); void reset_stored(const
//   Match&);        // zero the stored forces of a lost match Real energy(const Match&, const
//   ForceInput&) const;
//
// The force loop is a flat loop over the cached matches with the kernel
// inlined: no virtual call and no traversal per element.
//
// A kernel with Jacobians (riftc derives them from the rule) also supplies:
//
//   static constexpr int kJacobianVertices;  // vertices per match, k
//   void vertex_slots(const Match&, Slot* out) const;              // k slots
//   void jacobian(const Match&, const ForceInput&, Mat3* dfdx, Mat3* dfdv);  // k² blocks each
//   void jacobian_product(const Match&, const ForceInput&, const Vec3* px,
//                         const Vec3* pv, Vec3* out);  // out += Jx px + Jv pv
//
// and a kernel without them may give `static constexpr const char*
// kJacobianUnavailable` (riftc's located reason).
#pragma once

#include <algorithm>
#include <string>
#include <utility>

#include "rift/core/interrupt.hpp"
#include "rift/sim/force_model.hpp"
#include "rift/sim/match_cache.hpp"

namespace rift {

template <class Kernel>
class CachedInteraction final : public ForceModel {
 public:
  template <class... Args>
  explicit CachedInteraction(Args&&... args) : kernel_(std::forward<Args>(args)...) {}

  const std::string& name() const override { return kernel_.name(); }
  Kernel& kernel() { return kernel_; }

  void initialise(GMap& map) override {
    kernel_.initialise(map);
    cache_.build(map, Kernel::kSupport, [&](const GMap& m, Dart d, typename Kernel::Match& out) {
      return kernel_.match(m, d, out);
    });
  }

  void rematch(const GMap& map, std::span<const Dart> region) override {
    cache_.rematch(
        map, Kernel::kSupport, Kernel::kRadius, region,
        [&](const GMap& m, Dart d, typename Kernel::Match& out) {
          return kernel_.match(m, d, out);
        },
        [&](const typename Kernel::Match& lost, bool alive) {
          if (alive) kernel_.reset_stored(lost);
        });
  }

  void add_forces(const ForceInput& in, Vec3* f, bool store) override {
    using Match = typename Kernel::Match;
    const std::span<const Match> all(cache_.matches());
    // The pass runs in blocks so that an interrupt is seen within one block
    // (a few thousand matches: microseconds), not one whole pass.
    for (std::size_t first = 0; first < all.size(); first += kInterruptBlock) {
      throw_if_interrupted();
      const std::span<const Match> block =
          all.subspan(first, std::min(kInterruptBlock, all.size() - first));
      if constexpr (requires(Kernel & k, std::span<const Match> ms) {
                      k.add_forces_all(ms, in, f, store);
                    }) {
        // Generated kernels run the whole block themselves (columns read once).
        kernel_.add_forces_all(block, in, f, store);
      } else {
        for (const auto& m : block)
          kernel_.add_forces(m, in, f, store);
      }
    }
  }

  Real potential_energy(const ForceInput& in) const override {
    Real e = 0;
    for (const auto& m : cache_.matches())
      e += kernel_.energy(m, in);
    return e;
  }

  std::size_t active_matches() const override { return cache_.size(); }

  int jacobian_vertices() const override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      return Kernel::kJacobianVertices;
    } else {
      return 0;
    }
  }

  std::string jacobian_unavailable_reason() const override {
    if constexpr (requires { Kernel::kJacobianUnavailable; }) {
      return std::string(Kernel::kJacobianUnavailable);
    } else {
      return ForceModel::jacobian_unavailable_reason();
    }
  }

  void jacobians(const ForceInput& in, Slot* slots, Mat3* dfdx, Mat3* dfdv) override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      constexpr int k = Kernel::kJacobianVertices;
      std::size_t i = 0;
      for (const auto& m : cache_.matches()) {
        kernel_.vertex_slots(m, slots + i * k);
        kernel_.jacobian(m, in, dfdx + i * k * k, dfdv + i * k * k);
        ++i;
      }
    }
  }

  void add_jacobian_product(const ForceInput& in, const Vec3* px, const Vec3* pv,
                            Vec3* out) override {
    if constexpr (requires { Kernel::kJacobianVertices; }) {
      for (const auto& m : cache_.matches())
        kernel_.jacobian_product(m, in, px, pv, out);
    }
  }
  const MatchCache<typename Kernel::Match>& cache() const { return cache_; }

 private:
  static constexpr std::size_t kInterruptBlock = 4096;
  Kernel kernel_;
  MatchCache<typename Kernel::Match> cache_;
};

}  // namespace rift

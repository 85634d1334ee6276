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
// A kernel whose rule gives an energy states `static constexpr bool
// kHasEnergy = true;`. It may state `static constexpr bool kJacobianSemidefinite = true;` (the
// rule's `semidefinite;`), and a kernel without them may give `static constexpr const char*
// kJacobianUnavailable` (riftc's located reason).
//
// On several threads (rift/core/parallel.hpp) a kernel that supplies
//
//   static constexpr int kForceTerms;                   // forces per match
//   void force_targets(const Match&, Slot* out) const;  // their vertex slots
//   void force_terms_all(std::span<const Match>, const ForceInput&, Vec3* terms, bool store);
//
// has its matches evaluated in parallel blocks, each match writing its forces
// to its own entries, then summed per vertex by a TermGather in match order:
// the bits of the one-thread pass, whatever the thread count.
#pragma once

#include <algorithm>
#include <string>
#include <utility>

#include "rift/core/interrupt.hpp"
#include "rift/core/parallel.hpp"
#include "rift/sim/force_model.hpp"
#include "rift/sim/match_cache.hpp"
#include "rift/sim/term_gather.hpp"

namespace rift {

template <class Kernel>
class CachedInteraction final : public ForceModel {
 public:
  template <class... Args>
  explicit CachedInteraction(Args&&... args) : kernel_(std::forward<Args>(args)...) {}

  const std::string& name() const override { return kernel_.name(); }
  Kernel& kernel() { return kernel_; }

  void initialise(GMap& map) override {
    gather_stale_ = true;
    kernel_.initialise(map);
    cache_.build(map, Kernel::kSupport, [&](const GMap& m, Dart d, typename Kernel::Match& out) {
      return kernel_.match(m, d, out);
    });
  }

  void rematch(const GMap& map, std::span<const Dart> region) override {
    gather_stale_ = true;
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
    if constexpr (requires { Kernel::kForceTerms; }) {
      if (thread_count() > 1 && all.size() >= kMinParallelBlocks * kParallelBlock) {
        add_forces_parallel(in, f, store);
        return;
      }
    }
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

  bool has_energy() const override {
    if constexpr (requires { Kernel::kHasEnergy; }) {
      return Kernel::kHasEnergy;
    } else {
      return false;
    }
  }

  bool jacobian_semidefinite() const override {
    if constexpr (requires { Kernel::kJacobianSemidefinite; }) {
      return Kernel::kJacobianSemidefinite;
    } else {
      return false;
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
      constexpr std::size_t k = Kernel::kJacobianVertices;
      const auto all = cache_.matches();
      // Each match writes its own blocks: parallel without any reduction.
      auto run = [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          kernel_.vertex_slots(all[i], slots + i * k);
          kernel_.jacobian(all[i], in, dfdx + i * k * k, dfdv + i * k * k);
        }
      };
      parallel_blocks(all.size(), kParallelBlock, run);
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
  void add_forces_parallel(const ForceInput& in, Vec3* f, bool store) {
    using Match = typename Kernel::Match;
    constexpr std::size_t k = Kernel::kForceTerms;
    const std::span<const Match> all(cache_.matches());
    if (gather_stale_) {
      // Once per change of the matches (a tear), not per pass.
      targets_.resize(all.size() * k);
      for (std::size_t i = 0; i < all.size(); ++i)
        kernel_.force_targets(all[i], targets_.data() + i * k);
      gather_.build(targets_);
      gather_stale_ = false;
    }
    terms_.resize(all.size() * k);  // keeps its capacity: no allocation once warm
    auto run = [&](std::size_t first, std::size_t last) {
      throw_if_interrupted();
      kernel_.force_terms_all(all.subspan(first, last - first), in, terms_.data() + first * k,
                              store);
    };
    parallel_blocks(all.size(), kParallelBlock, run);
    gather_.add_to(terms_.data(), f);
  }

  static constexpr std::size_t kInterruptBlock = 4096;
  Kernel kernel_;
  MatchCache<typename Kernel::Match> cache_;
  // The force pass on several threads: per-match forces and their gather.
  std::vector<Vec3> terms_;
  std::vector<Slot> targets_;
  TermGather gather_;
  bool gather_stale_ = true;
};

}  // namespace rift

// Backward Euler for M v' = f(x, v), x' = v, solved for the end-of-step
// velocity v1 with x1 = x0 + h v1 (docs/physics.md, "The implicit step"):
//
//   g(v1) = M (v1 - v0) - h f(x0 + h v1, v1) = 0.
//
// Linearised once (Baraff & Witkin 1998, eq. 6), with K = ∂f/∂x, D = ∂f/∂v
// at (x0, v0):
//
//   (M - h D - h² K) Δv = h (f0 + h K v0),   v1 = v0 + Δv,   x1 = x0 + h v1,
//
// and optionally continued by Newton iterations on g with a backtracking
// line search. When the forces have a potential Φ (every interaction gives
// an energy, the external forces are gravity, and ∂f/∂v = 0), g is the
// gradient of the incremental potential of backward Euler
//
//   E(v1) = ½ (v1 - v0)ᵀ M (v1 - v0) + Φ(x0 + h v1),
//
// and the search asks E to decrease enough (Armijo); otherwise (damping: no
// potential has the step as its minimum) it asks |g| to decrease. Each linear
// system is solved by preconditioned conjugate gradients with constrained
// vertices (pins, moving handles) as Dirichlet degrees of freedom: their
// end-of-step velocity is prescribed and filtered out of the iteration
// (never a huge mass). External forces (gravity) enter the right-hand side;
// their Jacobians are zero.
#pragma once

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "rift/sim/element_matrix.hpp"
#include "rift/sim/pcg.hpp"
#include "rift/sim/preconditioner.hpp"

namespace rift {

enum class JacobianMode {
  kAssembled,   ///< element blocks evaluated once per linearisation, products from them
  kMatrixFree,  ///< every CG product re-evaluates the interactions' J·p (no block storage)
};

/// "assembled", "matrix_free".
std::optional<JacobianMode> parse_jacobian_mode(std::string_view name);

enum class LineSearch {
  kEnergy,    ///< on the incremental potential where it exists, else on |g|
  kResidual,  ///< on |g| always
};

/// "energy", "residual".
std::optional<LineSearch> parse_line_search(std::string_view name);

/// The [implicit] table of a scene (docs/scenes.md).
struct ImplicitSettings {
  Real cg_tolerance = 1e-6;  ///< stop when |r| <= tolerance |b| (free vertices)
  int cg_max_iterations = 200;
  PreconditionerKind preconditioner = PreconditionerKind::kJacobi;
  int newton_iterations = 1;     ///< 1: linearised once (Baraff & Witkin); more: Newton
  Real newton_tolerance = 1e-8;  ///< stop Newton when |g| <= tolerance · |M v0| + tiny
  JacobianMode jacobian = JacobianMode::kAssembled;
  LineSearch line_search = LineSearch::kEnergy;
  /// Project element matrices that are not semidefinite (element_matrix.hpp);
  /// assembled Jacobians only.
  bool project_definite = true;
};

/// What the last step did, for benchmarks and tests.
struct ImplicitStats {
  int newton_iterations = 0;
  int cg_iterations = 0;          ///< summed over Newton iterations
  Real cg_relative_residual = 0;  ///< of the last solve
  Real residual = 0;              ///< |g(v1)| at the end, when Newton ran more than once (else 0)
  bool energy_search = false;     ///< the Newton line search was on the incremental potential
  std::size_t projected = 0;  ///< element matrices made semidefinite, summed over linearisations
};

/// Seconds spent since construction (or reset_times), for `rift bench`.
struct ImplicitTimes {
  double total = 0, assembly = 0, products = 0, preconditioner = 0;
};

class ImplicitEuler {
 public:
  /// f(x, v, out): total force per vertex slot (interactions + external).
  using ForceFn = std::function<void(const std::vector<Vec3>& x, const std::vector<Vec3>& v,
                                     std::vector<Vec3>& f)>;
  /// Φ(x): the potential energy of every force, f = -∂Φ/∂x where f does not
  /// depend on v.
  using PotentialFn = std::function<Real(const std::vector<Vec3>& x)>;

  explicit ImplicitEuler(ImplicitSettings settings = {});

  const ImplicitSettings& settings() const { return settings_; }
  const ImplicitStats& last() const { return stats_; }
  const ImplicitTimes& times() const { return times_; }
  void reset_times() { times_ = {}; }

  /// The interactions whose Jacobians enter the system. Throws
  /// std::invalid_argument naming the first without Jacobians and why.
  void set_models(std::span<ForceModel* const> models);

  /// The forces' potential, for the Newton line search on the incremental
  /// potential (null: none, the search is on |g|). It is used only at
  /// states where the assembled ∂f/∂v is zero.
  void set_potential(PotentialFn potential) { potential_ = std::move(potential); }

  /// Its element blocks, preconditioner and vectors under "implicit" (MemoryReport).
  void report_memory(MemoryReport& report) const;
  /// The element blocks of the last assembly.
  const ElementMatrix& blocks() const { return blocks_; }

  /// The matches changed (after a tear): the incomplete-Cholesky pattern is
  /// rebuilt at the next step, and the element blocks' gathers.
  void topology_changed() {
    pattern_changed_ = true;
    blocks_.pattern_changed();
  }

  /// One step of size h. mass[s]: vertex masses by slot; is_free[s] = 0 for
  /// constrained slots (pins, handles, dead slots); target_v: end-of-step
  /// velocity of constrained slots (null: zero). f0, when given, holds
  /// force(x, v) already.
  void step(const ForceFn& force, const std::vector<Real>& mass, const std::vector<char>& is_free,
            const Vec3* target_v, std::vector<Vec3>& x, std::vector<Vec3>& v, Real h,
            const std::vector<Vec3>* f0 = nullptr);

 private:
  // Evaluates the Jacobians at `at` (element blocks, K v into kxv_) and
  // updates the preconditioner.
  void linearise(const ForceInput& at, const std::vector<Real>& mass,
                 const std::vector<char>& is_free, Real h);
  // Solves (M - h D - h² K) dv = rhs_ at the linearisation state `at`.
  void solve(const ForceInput& at, const std::vector<Real>& mass, const std::vector<char>& is_free,
             Real h, std::vector<Vec3>& dv);
  void apply_a(const ForceInput& at, const std::vector<Real>& mass, Real h, const Vec3* p,
               Vec3* out);

  ImplicitSettings settings_;
  ImplicitStats stats_;
  ImplicitTimes times_;
  std::vector<ForceModel*> models_;
  PotentialFn potential_;
  ElementMatrix blocks_;
  Preconditioner preconditioner_;
  PcgScratch pcg_;
  bool pattern_changed_ = true;
  std::vector<Vec3> f_, kxv_, rhs_, dv_, x1_, v1_, trial_v_, trial_x_, scaled_h2_, scaled_h_;
};

}  // namespace rift

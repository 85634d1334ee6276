// The matrix of an implicit step, A = M - h² ∂f/∂x - h ∂f/∂v, stored element
// by element: for each match of each interaction, its k vertex slots and its
// k×k blocks C_e = -(h² ∂f_e/∂x + h ∂f_e/∂v), so that
//
//   A p = M p + Σ_e Σ_{i,j} C_e(i, j) p[slot_j]   (scattered to slot_i).
//
// Why per element and not a global block-CSR: the Jacobian changes with the
// state and is rewritten every step anyway, and storing it in match order
// makes the match cache *be* the pattern. A tear re-matches a few support
// orbits (MatchCache::rematch) and the next assembly writes their blocks:
// the pattern follows the topology locally without any search, insertion or
// renumbering, assembly is a contiguous write per match (no scatter, no
// atomics, thread-count independent), and the arrays only grow, so a warm
// step allocates nothing. The price is storage and product flops: a vertex
// pair shared by several elements keeps one block per element (about 16
// blocks per tetrahedron instead of ~3 per tetrahedron in a global pattern).
// The incomplete-Cholesky preconditioner, which needs a global matrix,
// assembles one from these blocks (pcg.cpp).
//
// Definiteness: CG needs A symmetric positive definite, and A = M + Σ C_e is
// when every -∂f_e/∂x and -∂f_e/∂v is positive semidefinite. That holds for
// stretched springs and for co-rotational elements with R held constant, but
// not for a compressed spring (its transverse stiffness k(1 - L0/L) turns
// negative) or an inverted element: at a time step far beyond the explicit
// limit, M no longer outweighs them and CG meets negative curvature. With
// projection on, an element matrix that is not semidefinite (it has no
// Cholesky factorisation even with a tiny diagonal added) is replaced by its nearest
// semidefinite matrix: eigenvalues clamped at zero (as in Teran et al. 2005
// and the incremental-potential solvers). The linearisation is then a
// modified Newton step; the forces themselves are unchanged. Interactions
// whose rule states `semidefinite;` (ForceModel::jacobian_semidefinite) skip
// the test: the co-rotational element with R held constant is semidefinite
// for any admissible material, and the Cholesky test was 14 % of its step.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "rift/sim/force_model.hpp"
#include "rift/sim/term_gather.hpp"

namespace rift {

/// One interaction's element blocks at one state.
struct ElementBlocks {
  ForceModel* model = nullptr;
  int k = 0;                  ///< vertices per match
  bool semidefinite = false;  ///< -C_e semidefinite by construction: never projected
  std::size_t matches = 0;    ///< matches written at the last assembly
  std::vector<Slot> slots;    ///< matches × k
  std::vector<Mat3> blocks;   ///< matches × k²: C_e (row-major i k + j)
  std::vector<Mat3> dfdv;     ///< scratch for ∂f/∂v while assembling
  /// Products on every core: each match writes its k rows of C_e p to its
  /// own entries of `terms`, summed per vertex in match order by `gather`
  /// (built from `slots` when the matches changed).
  mutable std::vector<Vec3> terms;
  TermGather gather;
  bool gather_stale = true;
};

/// Replaces the k×k blocks J (row-major, ∂f_i/∂x_j or ∂f_i/∂v_j) of one
/// element by the nearest matrix whose negative is symmetric positive
/// semidefinite. Returns true when it changed them.
bool project_to_semidefinite(Mat3* blocks, int k);

class ElementMatrix {
 public:
  /// Takes the interactions whose Jacobians enter A. Each must have
  /// jacobian_vertices() > 0 (the caller reports those that do not).
  void set_models(std::span<ForceModel* const> models);

  /// Projects every element matrix to semidefinite while assembling (above).
  void set_projection(bool on) { project_ = on; }

  /// The matches changed (a tear): the gathers of the products are rebuilt
  /// at the next assembly.
  void pattern_changed();

  /// Evaluates every element Jacobian at `in` and stores C_e for step h.
  /// Also returns kxv = (∂f/∂x) v for the right-hand side of the linearised
  /// step (Baraff & Witkin 1998), sized n.
  void assemble(const ForceInput& in, Real h, std::size_t n, std::vector<Vec3>& kxv);

  /// out = Σ_e C_e p (the Jacobian part of A p), out sized n, overwritten.
  void multiply(const Vec3* p, Vec3* out, std::size_t n) const;

  /// Adds the diagonal blocks Σ_e C_e(i, i) to diag[slot_i].
  void add_diagonal(Mat3* diag) const;

  std::span<const ElementBlocks> elements() const { return elements_; }
  /// Each interaction's blocks, slots and product terms under "implicit" (MemoryReport).
  void report_memory(MemoryReport& report) const;

  /// Element matrices the last assembly projected (∂f/∂x and ∂f/∂v counted apart).
  std::size_t projected() const { return projected_; }

  /// True when some ∂f/∂v block of the last assembly was nonzero (damping):
  /// the forces then have no potential.
  bool velocity_dependent() const { return velocity_dependent_; }

 private:
  std::vector<ElementBlocks> elements_;
  bool project_ = true;
  std::size_t projected_ = 0;
  bool velocity_dependent_ = false;
};

}  // namespace rift

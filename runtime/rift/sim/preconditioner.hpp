// Preconditioners for the implicit step's conjugate gradients.
//  - none: z = r.
//  - jacobi: the inverse of each vertex's 3×3 diagonal block of A (block
//    Jacobi): cheap, no allocation once warm, enough for well-graded meshes.
//  - incomplete_cholesky: Eigen's IncompleteCholesky (Lin & Moré's
//    limited-memory IC with a diagonal shift) of the scalar A assembled from
//    the element blocks. Fewer iterations on stiff or badly graded meshes;
//    its global matrix's pattern is rebuilt when the topology changed, and
//    the factorisation allocates (Eigen's), so it costs more per step.
// Constrained vertices get identity rows (their values never change).
#pragma once

#include <Eigen/Sparse>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "rift/sim/element_matrix.hpp"

namespace rift {

enum class PreconditionerKind { kNone, kJacobi, kIncompleteCholesky };

/// "none", "jacobi", "incomplete_cholesky" (or "ic").
std::optional<PreconditionerKind> parse_preconditioner(std::string_view name);
std::string_view to_string(PreconditionerKind kind);

class Preconditioner {
 public:
  explicit Preconditioner(PreconditionerKind kind);
  ~Preconditioner();
  PreconditionerKind kind() const { return kind_; }

  /// The element blocks, masses and free mask changed (a new step).
  /// `pattern_changed`: the matches changed since the last update (a tear).
  /// `blocks` may be null (matrix-free): Jacobi (and incomplete Cholesky)
  /// then use the masses only.
  void update(const ElementMatrix* blocks, const std::vector<Real>& mass,
              const std::vector<char>& is_free, bool pattern_changed);

  void apply(const Vec3* r, Vec3* z) const;
  /// Its diagonal, matrix and factor under "implicit" (MemoryReport).
  void report_memory(MemoryReport& report) const;

 private:
  void build_pattern(const ElementMatrix& blocks, std::size_t n);

  PreconditionerKind kind_;
  std::size_t n_ = 0;
  std::vector<Mat3> inverse_diagonal_;
  // Incomplete Cholesky: lower triangle of A, and for every scalar entry of
  // every element block its index in A's values (-1 above the diagonal).
  Eigen::SparseMatrix<Real> a_;
  std::vector<int> scatter_;
  std::vector<int> diagonal_index_;
  // The pattern's vertex pairs (column << 32 | row, row > column), sorted,
  // and where each column's start: kept to rebuild without reallocating.
  std::vector<std::uint64_t> pairs_;
  std::vector<std::size_t> first_pair_;
  struct Factor;
  std::unique_ptr<Factor> factor_;
  mutable Eigen::VectorXd rhs_, sol_;
  bool have_pattern_ = false;
  bool diagonal_only_ = false;  // Jacobi, or incomplete Cholesky without blocks (matrix-free)
};

}  // namespace rift

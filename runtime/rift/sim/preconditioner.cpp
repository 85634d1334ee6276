#include "rift/sim/preconditioner.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>

#include "rift/core/parallel.hpp"

namespace rift {

struct Preconditioner::Factor {
  Eigen::IncompleteCholesky<Real, Eigen::Lower, Eigen::AMDOrdering<int>> ic;
};

std::optional<PreconditionerKind> parse_preconditioner(std::string_view name) {
  if (name == "none") return PreconditionerKind::kNone;
  if (name == "jacobi") return PreconditionerKind::kJacobi;
  if (name == "incomplete_cholesky" || name == "ic") return PreconditionerKind::kIncompleteCholesky;
  return std::nullopt;
}

std::string_view to_string(PreconditionerKind kind) {
  switch (kind) {
    case PreconditionerKind::kNone:
      return "none";
    case PreconditionerKind::kJacobi:
      return "jacobi";
    case PreconditionerKind::kIncompleteCholesky:
      return "incomplete_cholesky";
  }
  return "?";
}

Preconditioner::Preconditioner(PreconditionerKind kind)
    : kind_(kind), factor_(std::make_unique<Factor>()) {}
Preconditioner::~Preconditioner() = default;

namespace {

// Values, inner indices and outer starts of a compressed sparse matrix.
std::size_t sparse_bytes(const Eigen::SparseMatrix<Real>& m) {
  return static_cast<std::size_t>(m.nonZeros()) * (sizeof(Real) + sizeof(int)) +
         static_cast<std::size_t>(m.outerSize() + 1) * sizeof(int);
}

}  // namespace

void Preconditioner::report_memory(MemoryReport& report) const {
  report.add("implicit", "preconditioner diagonal", inverse_diagonal_);
  report.add("implicit", "preconditioner matrix", sparse_bytes(a_));
  report.add("implicit", "preconditioner scatter", scatter_);
  report.add("implicit", "preconditioner diagonal index", diagonal_index_);
  report.add("implicit", "preconditioner pattern", pairs_);
  report.add("implicit", "preconditioner pattern columns", first_pair_);
  report.add("implicit", "preconditioner vectors",
             static_cast<std::size_t>(rhs_.size() + sol_.size()) * sizeof(Real));
  if (kind_ == PreconditionerKind::kIncompleteCholesky && factor_->ic.info() == Eigen::Success &&
      factor_->ic.matrixL().rows() > 0) {
    report.add("implicit", "incomplete Cholesky factor", sparse_bytes(factor_->ic.matrixL()));
  }
}

void Preconditioner::update(const ElementMatrix* blocks, const std::vector<Real>& mass,
                            const std::vector<char>& is_free, bool pattern_changed) {
  const std::size_t n = mass.size();
  const bool size_changed = n != n_;
  n_ = n;
  if (kind_ == PreconditionerKind::kNone) return;
  diagonal_only_ = kind_ == PreconditionerKind::kJacobi || !blocks;
  if (diagonal_only_) {
    // Each vertex on its own: in parallel, the same bits on any threads.
    inverse_diagonal_.resize(n);
    parallel_for(n, [&](std::size_t i) { inverse_diagonal_[i] = mass[i] * Mat3::Identity(); });
    if (blocks) blocks->add_diagonal(inverse_diagonal_.data());
    parallel_for(n, [&](std::size_t i) {
      if (!is_free[i]) {
        inverse_diagonal_[i].setZero();
        return;
      }
      bool invertible = false;
      Mat3 inv;
      inverse_diagonal_[i].computeInverseWithCheck(inv, invertible);
      inverse_diagonal_[i] = invertible ? inv : Mat3::Identity();
    });
    return;
  }
  // Incomplete Cholesky on the scalar matrix (3 n unknowns).
  if (pattern_changed || !have_pattern_ || size_changed) build_pattern(*blocks, n);
  Real* values = a_.valuePtr();
  std::fill(values, values + a_.nonZeros(), Real(0));
  std::size_t next = 0;
  for (const ElementBlocks& e : blocks->elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          const bool used = s[i] != kNoSlot && s[j] != kNoSlot && is_free[s[i]] && is_free[s[j]];
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b, ++next) {
              const int at = scatter_[next];
              if (used && at >= 0) values[at] += c[i * k + j](a, b);
            }
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      Real& d = values[diagonal_index_[3 * i + a]];
      d = is_free[i] ? d + mass[i] : Real(1);
    }
  }
  factor_->ic.factorize(a_);
}

void Preconditioner::build_pattern(const ElementMatrix& blocks, std::size_t n) {
  // Whole-matrix rebuild: only the incomplete Cholesky preconditioner needs a
  // global pattern, and only after a tear (the element blocks themselves
  // follow the match cache without one). Built vertex by vertex, not entry by
  // entry: the lower triangle of A is made of the 3×3 blocks (r, c) of the
  // vertex pairs r > c some element couples, and the lower triangles of the
  // diagonal blocks. So the pairs are collected once per block (not nine
  // scalar triplets), sorted, and A's compressed columns written directly;
  // each scalar entry's index follows from its block's place in its column.
  // (Scalar triplets through Eigen's setFromTriplets cost 10x more: about
  // 2 implicit steps of the 19,200-tetrahedron beam, docs/physics.md.)
  pairs_.clear();
  for (const ElementBlocks& e : blocks.elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          if (s[i] == kNoSlot || s[j] == kNoSlot || s[i] <= s[j]) continue;
          pairs_.push_back((std::uint64_t{s[j]} << 32) | s[i]);  // column s[j], row s[i]
        }
      }
    }
  }
  std::sort(pairs_.begin(), pairs_.end());
  pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  // first_pair_[c]: where vertex c's rows below the diagonal start in pairs_.
  first_pair_.assign(n + 1, 0);
  for (const std::uint64_t p : pairs_)
    ++first_pair_[(p >> 32) + 1];
  for (std::size_t c = 0; c < n; ++c)
    first_pair_[c + 1] += first_pair_[c];
  const int dofs = static_cast<int>(3 * n);
  const std::size_t nonzeros = 6 * n + 9 * pairs_.size();
  a_.resize(dofs, dofs);
  a_.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  int* outer = a_.outerIndexPtr();
  int* inner = a_.innerIndexPtr();
  int at = 0;
  for (std::size_t c = 0; c < n; ++c) {
    for (int b = 0; b < 3; ++b) {
      outer[3 * c + static_cast<std::size_t>(b)] = at;
      for (int a = b; a < 3; ++a)
        inner[at++] = static_cast<int>(3 * c) + a;  // the diagonal block's lower triangle
      for (std::size_t q = first_pair_[c]; q < first_pair_[c + 1]; ++q) {
        const int r = static_cast<int>(pairs_[q] & 0xffffffffU);
        for (int a = 0; a < 3; ++a)
          inner[at++] = 3 * r + a;
      }
    }
  }
  outer[dofs] = at;
  diagonal_index_.resize(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i)
    diagonal_index_[i] = outer[i];  // each column starts at its diagonal
  // Index in A's values of entry (3 r + a, 3 c + b), r >= c, r coupled with c.
  auto index_of = [&](Slot r, Slot c, int a, int b) {
    const int col = outer[3 * std::size_t{c} + static_cast<std::size_t>(b)];
    if (r == c) return col + (a - b);
    const std::uint64_t key = (std::uint64_t{c} << 32) | r;
    const auto begin = pairs_.begin() + static_cast<std::ptrdiff_t>(first_pair_[c]);
    const auto end = pairs_.begin() + static_cast<std::ptrdiff_t>(first_pair_[c + 1]);
    const auto p = static_cast<int>(std::lower_bound(begin, end, key) - begin);
    return col + (3 - b) + 3 * p + a;
  };
  scatter_.clear();
  for (const ElementBlocks& e : blocks.elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          const bool below = s[i] != kNoSlot && s[j] != kNoSlot && s[i] >= s[j];
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
              scatter_.push_back(below && (s[i] > s[j] || a >= b) ? index_of(s[i], s[j], a, b)
                                                                  : -1);
            }
          }
        }
      }
    }
  }
  factor_->ic.analyzePattern(a_);
  rhs_.resize(dofs);
  sol_.resize(dofs);
  have_pattern_ = true;
}

void Preconditioner::apply(const Vec3* r, Vec3* z) const {
  switch (kind_) {
    case PreconditionerKind::kNone:
      parallel_for(n_, [&](std::size_t i) { z[i] = r[i]; });
      return;
    case PreconditionerKind::kJacobi:
    case PreconditionerKind::kIncompleteCholesky:
      if (diagonal_only_) {
        parallel_for(n_, [&](std::size_t i) { z[i] = inverse_diagonal_[i] * r[i]; });
        return;
      }
      for (std::size_t i = 0; i < n_; ++i)
        rhs_.segment<3>(static_cast<Eigen::Index>(3 * i)) = r[i];
      sol_ = factor_->ic.solve(rhs_);
      for (std::size_t i = 0; i < n_; ++i)
        z[i] = sol_.segment<3>(static_cast<Eigen::Index>(3 * i));
      return;
  }
}

}  // namespace rift

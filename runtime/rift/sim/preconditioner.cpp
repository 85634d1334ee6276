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

void Preconditioner::update(const ElementMatrix* blocks, const std::vector<Real>& mass,
                            const std::vector<char>& is_free, bool pattern_changed) {
  const std::size_t n = mass.size();
  const bool size_changed = n != n_;
  n_ = n;
  if (kind_ == PreconditionerKind::kNone) return;
  diagonal_only_ = kind_ == PreconditionerKind::kJacobi || !blocks;
  if (diagonal_only_) {
    inverse_diagonal_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      inverse_diagonal_[i] = mass[i] * Mat3::Identity();
    if (blocks) blocks->add_diagonal(inverse_diagonal_.data());
    for (std::size_t i = 0; i < n; ++i) {
      if (!is_free[i]) {
        inverse_diagonal_[i].setZero();
        continue;
      }
      bool invertible = false;
      Mat3 inv;
      inverse_diagonal_[i].computeInverseWithCheck(inv, invertible);
      inverse_diagonal_[i] = invertible ? inv : Mat3::Identity();
    }
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
  // follow the match cache without one).
  using Triplet = Eigen::Triplet<Real>;
  std::vector<Triplet> triplets;
  triplets.reserve(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i)
    triplets.emplace_back(static_cast<int>(i), static_cast<int>(i), 0.0);
  for (const ElementBlocks& e : blocks.elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          if (s[i] == kNoSlot || s[j] == kNoSlot) continue;
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
              const int row = static_cast<int>(3 * s[i]) + a, col = static_cast<int>(3 * s[j]) + b;
              if (row >= col) triplets.emplace_back(row, col, 0.0);
            }
          }
        }
      }
    }
  }
  const int dofs = static_cast<int>(3 * n);
  a_.resize(dofs, dofs);
  a_.setFromTriplets(triplets.begin(), triplets.end());
  a_.makeCompressed();
  auto index_of = [&](int row, int col) {
    const int* rows = a_.innerIndexPtr();
    const int begin = a_.outerIndexPtr()[col], end = a_.outerIndexPtr()[col + 1];
    const int* at = std::lower_bound(rows + begin, rows + end, row);
    return static_cast<int>(at - rows);
  };
  diagonal_index_.resize(3 * n);
  for (int i = 0; i < dofs; ++i)
    diagonal_index_[static_cast<std::size_t>(i)] = index_of(i, i);
  scatter_.clear();
  for (const ElementBlocks& e : blocks.elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) {
              if (s[i] == kNoSlot || s[j] == kNoSlot) {
                scatter_.push_back(-1);
                continue;
              }
              const int row = static_cast<int>(3 * s[i]) + a, col = static_cast<int>(3 * s[j]) + b;
              scatter_.push_back(row >= col ? index_of(row, col) : -1);
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

#include "rift/sim/element_matrix.hpp"

#include "rift/core/parallel.hpp"

namespace rift {

void ElementMatrix::set_models(std::span<ForceModel* const> models) {
  elements_.clear();
  for (ForceModel* m : models) {
    ElementBlocks e;
    e.model = m;
    e.k = m->jacobian_vertices();
    elements_.push_back(std::move(e));
  }
}

void ElementMatrix::pattern_changed() {
  for (ElementBlocks& e : elements_)
    e.gather_stale = true;
}

void ElementMatrix::assemble(const ForceInput& in, Real h, std::size_t n, std::vector<Vec3>& kxv) {
  kxv.resize(n);
  parallel_for(n, [&](std::size_t i) { kxv[i].setZero(); });
  for (ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    const std::size_t matches = e.model->active_matches();
    if (matches != e.matches) e.gather_stale = true;
    e.matches = matches;
    // resize() keeps the capacity: after the largest match count seen,
    // assembling allocates nothing.
    e.slots.resize(e.matches * k);
    e.blocks.resize(e.matches * k * k);
    e.dfdv.resize(e.matches * k * k);
    e.terms.resize(e.matches * k);
    e.model->jacobians(in, e.slots.data(), e.blocks.data(), e.dfdv.data());
    if (e.gather_stale) {
      e.gather.build(e.slots);
      e.gather_stale = false;
    }
    const Real h2 = h * h;
    // Row i of each match: its part of kxv (a term for the gather), then
    // the blocks of A.
    parallel_for(e.matches, [&](std::size_t m) {
      const Slot* s = e.slots.data() + m * k;
      Mat3* c = e.blocks.data() + m * k * k;
      const Mat3* dv = e.dfdv.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        Vec3 row = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          Mat3& b = c[i * k + j];  // holds ∂f_i/∂x_j on entry
          if (s[i] != kNoSlot && s[j] != kNoSlot) row += b * in.v[s[j]];
          b = -(h2 * b + h * dv[i * k + j]);
        }
        e.terms[m * k + i] = row;
      }
    });
    e.gather.add_to(e.terms.data(), kxv.data());
  }
}

void ElementMatrix::multiply(const Vec3* p, Vec3* out, std::size_t n) const {
  parallel_for(n, [&](std::size_t i) { out[i].setZero(); });
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    parallel_for(e.matches, [&](std::size_t m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        Vec3 sum = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          if (s[j] != kNoSlot) sum += c[i * k + j] * p[s[j]];
        }
        e.terms[m * k + i] = sum;  // dropped by the gather when s[i] is kNoSlot
      }
    });
    e.gather.add_to(e.terms.data(), out);
  }
}

void ElementMatrix::add_diagonal(Mat3* diag) const {
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        if (s[i] != kNoSlot) diag[s[i]] += c[i * k + i];
      }
    }
  }
}

}  // namespace rift

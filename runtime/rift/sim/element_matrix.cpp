#include "rift/sim/element_matrix.hpp"

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

void ElementMatrix::assemble(const ForceInput& in, Real h, std::size_t n, std::vector<Vec3>& kxv) {
  kxv.assign(n, Vec3::Zero());
  for (ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    e.matches = e.model->active_matches();
    // resize() keeps the capacity: after the largest match count seen,
    // assembling allocates nothing.
    e.slots.resize(e.matches * k);
    e.blocks.resize(e.matches * k * k);
    e.dfdv.resize(e.matches * k * k);
    e.model->jacobians(in, e.slots.data(), e.blocks.data(), e.dfdv.data());
    const Real h2 = h * h;
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      Mat3* c = e.blocks.data() + m * k * k;
      const Mat3* dv = e.dfdv.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = 0; j < k; ++j) {
          Mat3& b = c[i * k + j];  // holds ∂f_i/∂x_j on entry
          if (s[i] != kNoSlot && s[j] != kNoSlot) kxv[s[i]] += b * in.v[s[j]];
          b = -(h2 * b + h * dv[i * k + j]);
        }
      }
    }
  }
}

void ElementMatrix::multiply(const Vec3* p, Vec3* out, std::size_t n) const {
  for (std::size_t i = 0; i < n; ++i)
    out[i].setZero();
  for (const ElementBlocks& e : elements_) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      const Slot* s = e.slots.data() + m * k;
      const Mat3* c = e.blocks.data() + m * k * k;
      for (std::size_t i = 0; i < k; ++i) {
        if (s[i] == kNoSlot) continue;
        Vec3 sum = Vec3::Zero();
        for (std::size_t j = 0; j < k; ++j) {
          if (s[j] != kNoSlot) sum += c[i * k + j] * p[s[j]];
        }
        out[s[i]] += sum;
      }
    }
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

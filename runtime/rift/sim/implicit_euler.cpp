#include "rift/sim/implicit_euler.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "rift/core/parallel.hpp"

namespace rift {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Real free_norm(const std::vector<Vec3>& a, const std::vector<char>& is_free) {
  Real s = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (is_free[i]) s += a[i].squaredNorm();
  return std::sqrt(s);
}

}  // namespace

std::optional<JacobianMode> parse_jacobian_mode(std::string_view name) {
  if (name == "assembled") return JacobianMode::kAssembled;
  if (name == "matrix_free") return JacobianMode::kMatrixFree;
  return std::nullopt;
}

std::optional<LineSearch> parse_line_search(std::string_view name) {
  if (name == "energy") return LineSearch::kEnergy;
  if (name == "residual") return LineSearch::kResidual;
  return std::nullopt;
}

ImplicitEuler::ImplicitEuler(ImplicitSettings settings)
    : settings_(settings), preconditioner_(settings.preconditioner) {
  blocks_.set_projection(settings.project_definite);
}

void ImplicitEuler::set_models(std::span<ForceModel* const> models) {
  for (ForceModel* m : models) {
    if (m->jacobian_vertices() <= 0) {
      throw std::invalid_argument(
          "the implicit integrator needs the Jacobians of every "
          "interaction: " +
          m->jacobian_unavailable_reason());
    }
  }
  models_.assign(models.begin(), models.end());
  blocks_.set_models(models_);
  pattern_changed_ = true;
}

void ImplicitEuler::apply_a(const ForceInput& at, const std::vector<Real>& mass, Real h,
                            const Vec3* p, Vec3* out) {
  const auto start = Clock::now();
  const std::size_t n = mass.size();
  if (settings_.jacobian == JacobianMode::kAssembled) {
    blocks_.multiply(p, out, n);
    parallel_for(n, [&](std::size_t i) { out[i] += mass[i] * p[i]; });
  } else {
    // A p = M p - (h² K + h D) p, with J·p evaluated by the interactions.
    scaled_h2_.resize(n), scaled_h_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      scaled_h2_[i] = h * h * p[i];
      scaled_h_[i] = h * p[i];
      out[i].setZero();
    }
    for (ForceModel* m : models_)
      m->add_jacobian_product(at, scaled_h2_.data(), scaled_h_.data(), out);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = mass[i] * p[i] - out[i];
  }
  times_.products += seconds_since(start);
}

void ImplicitEuler::linearise(const ForceInput& at, const std::vector<Real>& mass,
                              const std::vector<char>& is_free, Real h) {
  const std::size_t n = mass.size();
  auto start = Clock::now();
  if (settings_.jacobian == JacobianMode::kAssembled) {
    blocks_.assemble(at, h, n, kxv_);
    stats_.projected += blocks_.projected();
  } else {
    // K v0 by the matrix-free product with a zero velocity direction.
    kxv_.assign(n, Vec3::Zero());
    scaled_h_.assign(n, Vec3::Zero());
    for (ForceModel* m : models_)
      m->add_jacobian_product(at, at.v, scaled_h_.data(), kxv_.data());
  }
  times_.assembly += seconds_since(start);
  start = Clock::now();
  preconditioner_.update(settings_.jacobian == JacobianMode::kAssembled ? &blocks_ : nullptr, mass,
                         is_free, pattern_changed_);
  pattern_changed_ = false;
  times_.preconditioner += seconds_since(start);
}

void ImplicitEuler::solve(const ForceInput& at, const std::vector<Real>& mass,
                          const std::vector<char>& is_free, Real h, std::vector<Vec3>& dv) {
  const PcgResult r =
      filtered_pcg([&](const Vec3* p, Vec3* out) { apply_a(at, mass, h, p, out); },
                   [&](const Vec3* res, Vec3* z) {
                     const auto start = Clock::now();
                     preconditioner_.apply(res, z);
                     times_.preconditioner += seconds_since(start);
                   },
                   is_free, rhs_, dv, settings_.cg_tolerance, settings_.cg_max_iterations, pcg_);
  stats_.cg_iterations += r.iterations;
  stats_.cg_relative_residual = r.relative_residual;
}

void ImplicitEuler::step(const ForceFn& force, const std::vector<Real>& mass,
                         const std::vector<char>& is_free, const Vec3* target_v,
                         std::vector<Vec3>& x, std::vector<Vec3>& v, Real h,
                         const std::vector<Vec3>* f0) {
  const auto start = Clock::now();
  const std::size_t n = x.size();
  stats_ = {};
  if (f0) {
    f_.assign(f0->begin(), f0->end());
  } else {
    f_.resize(n);
    force(x, v, f_);
  }
  // Linearised at (x0, v0): (M - h D - h² K) Δv = h (f0 + h K v0).
  const ForceInput at0{x.data(), v.data()};
  linearise(at0, mass, is_free, h);
  rhs_.resize(n);
  dv_.resize(n);
  parallel_for(n, [&](std::size_t i) {
    rhs_[i] = h * (f_[i] + h * kxv_[i]);
    dv_[i] = is_free[i] ? Vec3::Zero() : Vec3((target_v ? target_v[i] : Vec3::Zero()) - v[i]);
  });
  solve(at0, mass, is_free, h, dv_);
  v1_.resize(n);
  parallel_for(n, [&](std::size_t i) { v1_[i] = v[i] + dv_[i]; });
  stats_.newton_iterations = 1;

  // Newton on g(v1) = M (v1 - v0) - h f(x0 + h v1, v1), free vertices only
  // (constrained ones already hold their target).
  if (settings_.newton_iterations > 1) {
    x1_.resize(n), trial_v_.resize(n), trial_x_.resize(n);
    auto residual = [&](const std::vector<Vec3>& vt, std::vector<Vec3>& xt) {
      for (std::size_t i = 0; i < n; ++i)
        xt[i] = x[i] + h * vt[i];
      force(xt, vt, f_);
      for (std::size_t i = 0; i < n; ++i)
        rhs_[i] = is_free[i] ? Vec3(h * f_[i] - mass[i] * (vt[i] - v[i])) : Vec3::Zero();
      return free_norm(rhs_, is_free);  // rhs_ = -g
    };
    Real scale = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (is_free[i]) scale += (mass[i] * v[i]).squaredNorm() + (h * f_[i]).squaredNorm();
    const Real stop = settings_.newton_tolerance * std::sqrt(scale) + 1e-300;
    // The incremental potential E(v) = ½ |v - v0|²_M + Φ(x0 + h v), whose
    // gradient is g, where the forces have a potential (velocity-independent
    // at the first linearisation, assembled, a potential given).
    const bool energy_search = settings_.line_search == LineSearch::kEnergy && potential_ &&
                               settings_.jacobian == JacobianMode::kAssembled &&
                               !blocks_.velocity_dependent();
    stats_.energy_search = energy_search;
    auto energy = [&](const std::vector<Vec3>& vt, const std::vector<Vec3>& xt) {
      Real kinetic = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (is_free[i]) kinetic += mass[i] * (vt[i] - v[i]).squaredNorm();
      return 0.5 * kinetic + potential_(xt);
    };
    Real g = residual(v1_, x1_);
    Real e = energy_search ? energy(v1_, x1_) : 0;
    for (int it = 1; it < settings_.newton_iterations && g > stop; ++it) {
      const ForceInput at{x1_.data(), v1_.data()};
      linearise(at, mass, is_free, h);
      for (std::size_t i = 0; i < n; ++i)
        dv_[i].setZero();
      solve(at, mass, is_free, h, dv_);  // rhs_ holds -g
      ++stats_.newton_iterations;
      // The slope of E along dv is g·dv = -rhs_·dv (free vertices).
      Real slope = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (is_free[i]) slope -= rhs_[i].dot(dv_[i]);
      // Backtracking: halve the step until E decreases by at least 1e-4 of
      // its linear prediction (Armijo), or, on |g|, until |g| decreases (at
      // most 10 times). When no step does (dv is no descent direction: the
      // linear solve met negative curvature), Newton stops at the best
      // iterate so far.
      if (energy_search && !(slope < 0)) break;
      Real alpha = 1, g_trial = g, e_trial = e;
      bool decreased = false;
      for (int k = 0; k < 10 && !decreased; ++k, alpha /= 2) {
        for (std::size_t i = 0; i < n; ++i)
          trial_v_[i] = v1_[i] + alpha * dv_[i];
        g_trial = residual(trial_v_, trial_x_);
        if (energy_search) {
          e_trial = energy(trial_v_, trial_x_);
          decreased = e_trial <= e + 1e-4 * alpha * slope;
        } else {
          decreased = g_trial < g;
        }
      }
      if (!decreased) break;
      std::swap(v1_, trial_v_);
      std::swap(x1_, trial_x_);
      g = g_trial;
      e = e_trial;
    }
    stats_.residual = g;
  }
  parallel_for(n, [&](std::size_t i) {
    v[i] = v1_[i];
    x[i] += h * v1_[i];
  });
  times_.total += seconds_since(start);
}

void ImplicitEuler::report_memory(MemoryReport& report) const {
  blocks_.report_memory(report);
  preconditioner_.report_memory(report);
  std::size_t vectors = 0;
  for (const std::vector<Vec3>* a :
       {&f_, &kxv_, &rhs_, &dv_, &x1_, &v1_, &trial_v_, &trial_x_, &scaled_h2_, &scaled_h_})
    vectors += a->size();
  report.add("implicit", "Newton vectors", vectors * sizeof(Vec3));
  report.add("implicit", "conjugate gradient vectors",
             (pcg_.r.size() + pcg_.z.size() + pcg_.d.size() + pcg_.q.size()) * sizeof(Vec3));
}

}  // namespace rift

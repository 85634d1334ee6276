// The implicit integrator (ImplicitEuler, Simulation with implicit_euler) on
// hand-written interactions with analytic Jacobians, so that it is tested
// apart from riftc's derivatives: Jacobians against finite differences,
// order 1 on the harmonic oscillator, stiff undamped springs bounded far
// beyond the explicit limit, static equilibrium under gravity with pinned
// vertices as Dirichlet DOFs, preconditioners and matrix-free products that
// agree, Newton's residual, and tearing with the system following the map.
#include "rift/sim/implicit_euler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rift/core/parallel.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "rift/sim/bdf2.hpp"
#include "rift/sim/element_matrix.hpp"
#include "rift/sim/simulation.hpp"
#include "test_spring_model.hpp"

namespace rift {
namespace {

// f = -k x on every slot: a linear oscillator per vertex, Jacobian -k I.
class AnchorSprings final : public ForceModel {
 public:
  AnchorSprings(Real k, std::size_t n) : k_(k), n_(n) {}
  const std::string& name() const override { return name_; }
  void initialise(GMap&) override {}
  void rematch(const GMap&, std::span<const Dart>) override {}
  void add_forces(const ForceInput& in, Vec3* f, bool) override {
    for (std::size_t i = 0; i < n_; ++i)
      f[i] -= k_ * in.x[i];
  }
  std::size_t active_matches() const override { return n_; }
  int jacobian_vertices() const override { return 1; }
  void jacobians(const ForceInput&, Slot* slots, Mat3* dfdx, Mat3* dfdv) override {
    for (std::size_t i = 0; i < n_; ++i) {
      slots[i] = static_cast<Slot>(i);
      dfdx[i] = -k_ * Mat3::Identity();
      dfdv[i].setZero();
    }
  }
  void add_jacobian_product(const ForceInput&, const Vec3* px, const Vec3*, Vec3* out) override {
    for (std::size_t i = 0; i < n_; ++i)
      out[i] -= k_ * px[i];
  }

 private:
  std::string name_ = "anchor";
  Real k_;
  std::size_t n_;
};

Real oscillator_error(Real dt, Real t_end, bool bdf2 = false) {
  const Real k = 4.0;  // omega = 2 with unit mass
  AnchorSprings model(k, 1);
  ForceModel* models[] = {&model};
  ImplicitEuler euler;
  euler.set_models(models);
  std::vector<Vec3> x{Vec3(1, 0, 0)}, v{Vec3::Zero()};
  const std::vector<Real> mass{1.0};
  const std::vector<char> is_free{1};
  auto force = [&](const std::vector<Vec3>& xs, const std::vector<Vec3>& vs, std::vector<Vec3>& f) {
    f.assign(xs.size(), Vec3::Zero());
    model.add_forces({xs.data(), vs.data()}, f.data(), false);
  };
  const int steps = static_cast<int>(std::lround(t_end / dt));
  Bdf2 method;
  for (int s = 0; s < steps; ++s) {
    if (bdf2) {
      method.step(euler, force, mass, is_free, nullptr, x, v, dt);
    } else {
      euler.step(force, mass, is_free, nullptr, x, v, dt);
    }
  }
  return std::abs(x[0].x() - std::cos(2.0 * steps * dt));
}

TEST(ImplicitEuler, ConvergesAtOrderOneOnTheOscillator) {
  const Real e1 = oscillator_error(1e-3, 1.0), e2 = oscillator_error(5e-4, 1.0);
  EXPECT_NEAR(std::log2(e1 / e2), 1.0, 0.05);
  EXPECT_LT(e1, 1e-2);
}

TEST(Bdf2, ConvergesAtOrderTwoOnTheOscillator) {
  // Halving the step divides the error by about 4 (backward Euler's by 2).
  const Real e1 = oscillator_error(1e-2, 1.0, true), e2 = oscillator_error(5e-3, 1.0, true);
  EXPECT_NEAR(e1 / e2, 4.0, 0.3);
  EXPECT_LT(e1, oscillator_error(1e-2, 1.0, false) / 10);
}

TEST(ImplicitEuler, HalfEdgeSpringJacobiansMatchCentralDifferences) {
  GMap map = assemble_gmap(make_grid(GridKind::Mix, 3, 3));
  test::HalfEdgeSprings springs(50.0, 0.7);
  springs.initialise(map);
  std::vector<Vec3> x = map.embedding<Vec3>("position").values();
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-0.05, 0.05);
  std::vector<Vec3> v(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] += Vec3(u(rng), u(rng), u(rng));
    v[i] = 10 * Vec3(u(rng), u(rng), u(rng));
  }
  const std::size_t m = springs.active_matches();
  std::vector<Slot> slots(2 * m);
  std::vector<Mat3> jx(4 * m), jv(4 * m);
  springs.jacobians({x.data(), v.data()}, slots.data(), jx.data(), jv.data());
  // Global dense Jacobians from the blocks, and from central differences.
  const std::size_t n = x.size();
  Eigen::MatrixXd kx = Eigen::MatrixXd::Zero(3 * n, 3 * n), kv = kx;
  for (std::size_t e = 0; e < m; ++e)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const Eigen::Index r = 3 * slots[2 * e + i], c = 3 * slots[2 * e + j];
        kx.block<3, 3>(r, c) += jx[4 * e + 2 * i + j];
        kv.block<3, 3>(r, c) += jv[4 * e + 2 * i + j];
      }
  auto forces = [&](const std::vector<Vec3>& xs, const std::vector<Vec3>& vs) {
    std::vector<Vec3> f(n, Vec3::Zero());
    springs.add_forces({xs.data(), vs.data()}, f.data(), false);
    return f;
  };
  const Real h = 1e-6;
  Real worst = 0;
  for (std::size_t col = 0; col < 3 * n; ++col) {
    for (int wrt = 0; wrt < 2; ++wrt) {
      std::vector<Vec3> xp = x, xm = x, vp = v, vm = v;
      (wrt == 0 ? xp : vp)[col / 3][col % 3] += h;
      (wrt == 0 ? xm : vm)[col / 3][col % 3] -= h;
      const auto fp = forces(xp, vp), fm = forces(xm, vm);
      const Eigen::MatrixXd& k = wrt == 0 ? kx : kv;
      for (std::size_t row = 0; row < 3 * n; ++row) {
        const Real fd = (fp[row / 3][row % 3] - fm[row / 3][row % 3]) / (2 * h);
        const Real exact = k(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col));
        worst = std::max(worst, std::abs(fd - exact) / (1 + std::abs(exact)));
      }
    }
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(kx.norm(), 1.0);  // not trivially zero
}

Simulation spring_cloth(IntegratorKind kind, Real dt, Real k, Real c, Vec3 gravity,
                        ImplicitSettings implicit = {}) {
  SimulationSettings settings{kind, dt, gravity};
  settings.implicit = implicit;
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 6, 6)), settings);
  sim.set_total_mass(0.1);
  sim.pin_where([](const Vec3& p) { return p.y() > 0.99; });
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(k, c));
  sim.initialise();
  return sim;
}

// Largest omega of M⁻¹ K (free vertices) by power iteration on the blocks.
Real largest_omega(Simulation& sim) {
  ForceModel& model = *sim.force_models()[0];
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const std::size_t m = model.active_matches(), k = 2, n = x.size();
  std::vector<Slot> slots(m * k);
  std::vector<Mat3> jx(m * k * k), jv(m * k * k);
  model.jacobians({x.data(), v.data()}, slots.data(), jx.data(), jv.data());
  const auto& mass = sim.vertex_mass().values();
  std::vector<char> free(n);
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    free[sim.position().slot(d)] =
        !sim.map().embedding<Bool>("pinned")[d] && sim.vertex_mass()[d] > 0;
  });
  // A random start: constant vectors are rigid translations, in K's kernel.
  std::mt19937 rng(1);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Vec3> p(n), q(n);
  for (Vec3& e : p)
    e = Vec3(u(rng), u(rng), u(rng));
  Real lambda = 0;
  for (int it = 0; it < 2000; ++it) {
    for (auto& e : q)
      e.setZero();
    for (std::size_t e = 0; e < m; ++e)
      for (std::size_t i = 0; i < k; ++i)
        for (std::size_t j = 0; j < k; ++j)
          q[slots[e * k + i]] -= jx[e * k * k + i * k + j] * p[slots[e * k + j]];
    Real norm = 0;
    for (std::size_t i = 0; i < n; ++i) {
      q[i] = free[i] ? Vec3(q[i] / mass[i]) : Vec3::Zero();
      norm = std::max(norm, q[i].cwiseAbs().maxCoeff());
    }
    lambda = norm;
    for (std::size_t i = 0; i < n; ++i)
      p[i] = q[i] / norm;
  }
  return std::sqrt(lambda);
}

Real energy(const Simulation& sim) {
  return sim.kinetic_energy() + sim.potential_energy();
}

// Stretches the cloth away from its pinned top edge (y = 1) by `factor` and
// gives it a random out-of-plane velocity: every spring is in tension.
void stretch(Simulation& sim, unsigned seed, Real factor = 1.3, Real speed = 0.5) {
  std::mt19937 rng(seed);
  std::normal_distribution<Real> noise(0.0, speed);
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    if (sim.map().embedding<Bool>("pinned")[d]) return;
    Vec3& x = sim.position()[d];
    x.y() = 1 - factor * (1 - x.y());
    sim.velocity()[d] = Vec3(0, 0, noise(rng));
  });
}

TEST(ImplicitEuler, UndampedStiffSpringsStayBoundedAtAHundredTimesTheExplicitLimit) {
  const Real k = 1e4;
  Simulation probe = spring_cloth(IntegratorKind::kSymplecticEuler, 1e-3, k, 0, Vec3::Zero());
  const Real limit = 2 / largest_omega(probe);  // symplectic Euler: h omega_max < 2
  ASSERT_GT(limit, 0);
  ASSERT_LT(limit, 1);
  // The limit is real: symplectic Euler just above it blows up...
  {
    Simulation sim =
        spring_cloth(IntegratorKind::kSymplecticEuler, 1.2 * limit, k, 0, Vec3::Zero());
    stretch(sim, 5);
    const Real e0 = energy(sim);
    bool blew_up = false;
    for (int s = 0; s < 3000 && !blew_up; ++s) {
      try {
        sim.step();
      } catch (const SimulationError&) {
        blew_up = true;
      }
      if (!blew_up && energy(sim) > 1e3 * e0) blew_up = true;
    }
    EXPECT_TRUE(blew_up);
  }
  // ...while implicit Euler at 100 times the limit keeps its energy bounded
  // by the initial energy (it only dissipates). So far beyond the limit the
  // springs overshoot into compression, where one linearisation is not
  // enough: Newton iterations solve each step.
  ImplicitSettings newton;
  newton.newton_iterations = 20;
  Simulation sim =
      spring_cloth(IntegratorKind::kImplicitEuler, 100 * limit, k, 0, Vec3::Zero(), newton);
  stretch(sim, 5);
  const Real e0 = energy(sim);
  ASSERT_GT(e0, 0);
  std::size_t projected = 0;
  for (int s = 0; s < 60; ++s) {
    sim.step();
    ASSERT_LE(energy(sim), e0 * (1 + 1e-6)) << "step " << s;
    projected += sim.implicit()->last().projected;
  }
  EXPECT_GT(sim.implicit()->last().cg_iterations, 0);
  // Overshooting into compression makes spring Jacobians indefinite: the
  // projection (element_matrix.hpp) is what keeps each system definite.
  EXPECT_GT(projected, 0u);
}

TEST(Bdf2, UndampedStiffSpringsStayBoundedAtAHundredTimesTheExplicitLimit) {
  const Real k = 1e4;
  Simulation probe = spring_cloth(IntegratorKind::kSymplecticEuler, 1e-3, k, 0, Vec3::Zero());
  const Real limit = 2 / largest_omega(probe);  // the limit symplectic Euler blows up above
  ASSERT_GT(limit, 0);
  // BDF2 is A-stable but, unlike backward Euler, not monotone in energy
  // step by step: bounded means a few times the initial energy at most,
  // over many periods of the stiffest mode, and dissipated in the end.
  ImplicitSettings newton;
  newton.newton_iterations = 20;
  Simulation sim = spring_cloth(IntegratorKind::kBdf2, 100 * limit, k, 0, Vec3::Zero(), newton);
  stretch(sim, 5);
  const Real e0 = energy(sim);
  ASSERT_GT(e0, 0);
  Real largest = 0;
  for (int s = 0; s < 200; ++s) {
    sim.step();
    const Real e = energy(sim);
    ASSERT_TRUE(std::isfinite(e)) << "step " << s;
    largest = std::max(largest, e);
  }
  EXPECT_LT(largest, 2 * e0);
  EXPECT_LT(energy(sim), e0);
  EXPECT_GT(sim.implicit()->last().cg_iterations, 0);
}

TEST(ImplicitEuler, HangingClothReachesStaticEquilibriumWithPinsFixed) {
  // dt = 0.02 is far beyond the explicit limit of k = 2000 (about 2e-3).
  Simulation sim = spring_cloth(IntegratorKind::kImplicitEuler, 0.02, 2000, 1.0, Vec3(0, -9.81, 0));
  std::vector<std::pair<Dart, Vec3>> pins;
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    if (sim.map().embedding<Bool>("pinned")[d]) pins.emplace_back(d, sim.position()[d]);
  });
  ASSERT_EQ(pins.size(), 7u);
  for (int s = 0; s < 1500; ++s)
    sim.step();
  for (const auto& [d, p] : pins)
    EXPECT_EQ(sim.position()[d], p);
  // At rest: interactions balance gravity on every free vertex.
  sim.step();
  const auto& f = sim.internal_forces();
  Real worst = 0, weight = 0;
  sim.map().for_each_cell(Orbit{1, 2}, [&](Dart d) {
    if (sim.map().embedding<Bool>("pinned")[d]) return;
    const Vec3 gravity = sim.vertex_mass()[d] * Vec3(0, -9.81, 0);
    worst = std::max(worst, (f[sim.position().slot(d)] + gravity).norm());
    weight = std::max(weight, gravity.norm());
  });
  EXPECT_LT(worst, 1e-5 * weight);
  EXPECT_LT(sim.kinetic_energy(), 1e-12);
}

// The Jacobi preconditioner's diagonal: Σ_e C_e(i, i) per vertex, the sum a
// serial loop over the matches makes, bit for bit, on 1, 2 and 8 threads
// (a mesh of more blocks than the parallel passes' minimum).
TEST(ElementMatrix, DiagonalBlocksSumAsTheSerialLoopOnAnyThreads) {
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 90, 90)),
                 {IntegratorKind::kImplicitEuler, 0.01, Vec3::Zero()});
  sim.set_total_mass(1.0);
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(300, 0.5));
  sim.initialise();
  std::vector<Vec3> x = sim.position().values();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> jitter(-0.002, 0.002);
  for (Vec3& p : x)
    p += Vec3(jitter(rng), jitter(rng), jitter(rng));
  const std::vector<Vec3> v(x.size(), Vec3(0.1, 0, 0));
  const std::size_t n = x.size();
  ASSERT_GT(n, 4 * kParallelBlock);
  std::vector<ForceModel*> models;
  for (const auto& m : sim.force_models())
    models.push_back(m.get());
  ElementMatrix blocks;
  blocks.set_models(models);
  std::vector<Vec3> kxv;
  blocks.assemble({x.data(), v.data()}, 0.01, n, kxv);
  std::vector<Mat3> serial(n, Mat3::Identity());
  for (const ElementBlocks& e : blocks.elements()) {
    const std::size_t k = static_cast<std::size_t>(e.k);
    for (std::size_t m = 0; m < e.matches; ++m) {
      for (std::size_t i = 0; i < k; ++i) {
        const Slot s = e.slots[m * k + i];
        if (s != kNoSlot) serial[s] += e.blocks[m * k * k + i * k + i];
      }
    }
  }
  for (const int threads : {1, 2, 8}) {
    set_thread_count(threads);
    std::vector<Mat3> diag(n, Mat3::Identity());
    blocks.add_diagonal(diag.data());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < n; ++i)
      differ += (diag[i].array() != serial[i].array()).any() ? 1 : 0;
    EXPECT_EQ(differ, 0u) << threads << " threads";
  }
  set_thread_count(0);
}

TEST(ImplicitEuler, PreconditionersAndMatrixFreeProductsGiveTheSameStep) {
  auto run = [](PreconditionerKind p, JacobianMode mode) {
    ImplicitSettings s;
    s.preconditioner = p;
    s.jacobian = mode;
    s.cg_tolerance = 1e-13;
    s.cg_max_iterations = 2000;
    // From rest under gravity: every spring stretches, so K is negative
    // definite and A = M - h D - h² K positive definite (compressed springs
    // make K indefinite, where CG's iterates depend on the preconditioner).
    Simulation sim =
        spring_cloth(IntegratorKind::kImplicitEuler, 0.01, 3000, 0.5, Vec3(0, -9.81, 0), s);
    for (int step = 0; step < 5; ++step)
      sim.step();
    return std::make_pair(sim.position().values(), sim.implicit()->last().cg_iterations);
  };
  const auto [reference, none_iterations] =
      run(PreconditionerKind::kNone, JacobianMode::kAssembled);
  const auto [jacobi, jacobi_iterations] =
      run(PreconditionerKind::kJacobi, JacobianMode::kAssembled);
  const auto [ic, ic_iterations] =
      run(PreconditionerKind::kIncompleteCholesky, JacobianMode::kAssembled);
  const auto [free, free_iterations] = run(PreconditionerKind::kJacobi, JacobianMode::kMatrixFree);
  Real worst = 0;

  for (std::size_t i = 0; i < reference.size(); ++i) {
    worst = std::max({worst, (jacobi[i] - reference[i]).norm(), (ic[i] - reference[i]).norm(),
                      (free[i] - reference[i]).norm()});
  }
  EXPECT_LT(worst, 1e-9);
  // The incomplete Cholesky factor is a better preconditioner than none.
  EXPECT_LT(ic_iterations, none_iterations);
  EXPECT_GT(free_iterations, 0);
}

TEST(ImplicitEuler, NewtonIterationsSolveTheNonlinearStep) {
  auto residual_after = [](int newton) {
    ImplicitSettings s;
    s.newton_iterations = newton;
    s.cg_tolerance = 1e-12;
    s.cg_max_iterations = 2000;
    s.newton_tolerance = 1e-14;
    // Undamped (the damping term of a spring's ∂f/∂x is not symmetric, and
    // CG then solves the Newton systems only approximately), soft springs
    // that stretch far under gravity in one step: nonlinear, but every
    // spring stays in tension, so each Newton system is positive definite.
    Simulation sim =
        spring_cloth(IntegratorKind::kImplicitEuler, 0.05, 20, 0, Vec3(0, -9.81, 0), s);
    sim.step();
    return sim.implicit()->last();
  };
  const ImplicitStats two = residual_after(2), many = residual_after(20);
  EXPECT_GT(two.residual, 0);
  EXPECT_LT(many.residual, 1e-6 * two.residual);
  EXPECT_GT(many.newton_iterations, 2);
}

// Cuts every inner edge longer than `limit` (the two faces separate).
class LongEdgeCriterion final : public Criterion {
 public:
  explicit LongEdgeCriterion(Real limit) : limit_(limit) {}
  const std::string& name() const override { return name_; }
  void initialise(GMap& map) override { position_ = map.embedding<Vec3>("position"); }
  void collect(const GMap& map, std::vector<TearCandidate>& out) const override {
    map.for_each_cell(Orbit{0, 2}, [&](Dart d) {
      if (map.is_free(d, 2)) return;
      const Real len = (position_[map.alpha(d, 0)] - position_[d]).norm();
      if (len > limit_) out.push_back({0, d, len, {}, 0});
    });
  }
  bool apply(GMap& map, const TearCandidate& c, std::vector<Dart>& touched) override {
    if (map.is_free(c.at, 2)) return false;
    map.for_each_in_orbit(c.at, Orbit{0, 2}, [&](Dart x) { touched.push_back(x); });
    map.unsew(c.at, 2);
    cut.push_back(c.at);
    return true;
  }
  std::vector<Dart> cut;

 private:
  std::string name_ = "long_edge";
  Real limit_;
  Embedding<Vec3> position_;
};

std::vector<Dart> tears_with(IntegratorKind kind, PreconditionerKind p) {
  SimulationSettings settings{kind, 2e-4, Vec3(0, -9.81, 0), 0, true};
  settings.implicit.preconditioner = p;
  settings.implicit.cg_tolerance = 1e-10;
  Simulation sim(assemble_gmap(make_grid(GridKind::Mix, 6, 6)), settings);
  sim.set_total_mass(0.1);
  sim.pin_where([](const Vec3& q) { return q.y() > 0.99 && (q.x() < 0.01 || q.x() > 0.99); });
  sim.add_force_model(std::make_unique<test::HalfEdgeSprings>(5.0, 0.05));
  auto c = std::make_unique<LongEdgeCriterion>(0.25);
  LongEdgeCriterion* criterion = c.get();
  sim.add_criterion(std::move(c));
  sim.initialise();
  for (int s = 0; s < 2000; ++s)
    sim.step();
  EXPECT_TRUE(sim.map().check_validity(5).empty());
  return criterion->cut;
}

TEST(ImplicitEuler, TearsTheClothLikeRk4AtSmallSteps) {
  const std::vector<Dart> rk4 = tears_with(IntegratorKind::kRK4, PreconditionerKind::kJacobi);
  ASSERT_GE(rk4.size(), 3u);
  EXPECT_EQ(tears_with(IntegratorKind::kImplicitEuler, PreconditionerKind::kJacobi), rk4);
  EXPECT_EQ(tears_with(IntegratorKind::kImplicitEuler, PreconditionerKind::kIncompleteCholesky),
            rk4);
}

// After each tear the slots change: BDF2 restarts with a backward Euler step
// on the new system (its pattern follows the map) and tears as RK4 does.
TEST(Bdf2, TearsTheClothLikeRk4AtSmallSteps) {
  const std::vector<Dart> rk4 = tears_with(IntegratorKind::kRK4, PreconditionerKind::kJacobi);
  ASSERT_GE(rk4.size(), 3u);
  EXPECT_EQ(tears_with(IntegratorKind::kBdf2, PreconditionerKind::kJacobi), rk4);
}

TEST(ImplicitEuler, NamesTheInteractionWithoutJacobians) {
  class NoJacobian final : public ForceModel {
   public:
    const std::string& name() const override { return name_; }
    void initialise(GMap&) override {}
    void rematch(const GMap&, std::span<const Dart>) override {}
    void add_forces(const ForceInput&, Vec3*, bool) override {}
    std::size_t active_matches() const override { return 0; }

   private:
    std::string name_ = "plain";
  };
  Simulation sim(assemble_gmap(make_grid(GridKind::Quad, 2, 2)),
                 {IntegratorKind::kImplicitEuler, 1e-2, Vec3::Zero()});
  sim.set_total_mass(1.0);
  sim.add_force_model(std::make_unique<NoJacobian>());
  try {
    sim.initialise();
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'plain'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rift

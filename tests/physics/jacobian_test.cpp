// The Jacobians riftc derives (forward mode over the rules' force
// expressions) for every interaction of the standard packs, 2D and 3D:
// against central differences of the generated forces on random deformed
// and moving states, the matrix-free product against the blocks, and the
// symmetry the physics implies. The co-rotational element holds its
// rotation constant (stop_gradient): its position Jacobian is compared
// where that is exact, at rigidly moved rest shapes (there dR contributes
// nothing: σ = 0 and sym(dRᵀR) = 0), its velocity Jacobian everywhere.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "given_jacobians.hpp"
#include "physics_setup.hpp"
#include "rift/io/load_map.hpp"

namespace rift::physics_test {
namespace {

struct Case {
  const char* mesh;
  Use interaction;
  bool rotation_held = false;              // co-rotational: R constant for the Jacobian
  const PackRegistry* registry = nullptr;  // null: the standard packs
};

std::vector<Case> cases(Real damping) {
  auto with = [&](const char* name, std::vector<std::pair<std::string, Real>> p) {
    p.emplace_back("damping", damping);
    return Use{name, p};
  };
  return {
      {"grid:mix:3x3", with("stretch", {{"stiffness", 60.0}})},
      {"grid:mix:3x3", with("shear", {{"stiffness", 43.0}})},
      {"grid:mix:3x3", with("bend", {{"stiffness", 10.0}})},
      {"grid:mix:3x3", with("angular_shear", {{"stiffness", 0.5}})},
      {"grid:mix:3x3", with("angular_bend", {{"stiffness", 0.01}})},
      {"grid:quad:3x3", with("angular_bend", {{"stiffness", 0.01}})},
      {"grid:tri:3x3", with("membrane", {{"young", 1000.0}, {"poisson", 0.3}})},
      {"block:hex:2x2x1", with("stretch", {{"stiffness", 60.0}})},
      {"block:hex:2x2x1", with("shear", {{"stiffness", 43.0}})},
      {"block:hex:2x2x1", with("volume_shear", {{"stiffness", 43.0}})},
      {"block:tet:2x1x1", with("corotational", {{"young", 1000.0}, {"poisson", 0.3}}), true},
  };
}

struct Dense {
  Eigen::MatrixXd kx, kv;
};

// The blocks of every match summed into dense 3n × 3n matrices.
Dense dense_jacobians(Simulation& sim) {
  ForceModel& model = *sim.force_models()[0];
  const auto& x = sim.position().values();
  const auto& v = sim.velocity().values();
  const std::size_t k = static_cast<std::size_t>(model.jacobian_vertices());
  const std::size_t m = model.active_matches(), n = x.size();
  std::vector<Slot> slots(m * k);
  std::vector<Mat3> jx(m * k * k), jv(m * k * k);
  model.jacobians({x.data(), v.data()}, slots.data(), jx.data(), jv.data());
  const Eigen::Index dofs = static_cast<Eigen::Index>(3 * n);
  Dense d{Eigen::MatrixXd::Zero(dofs, dofs), Eigen::MatrixXd::Zero(dofs, dofs)};
  for (std::size_t e = 0; e < m; ++e) {
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < k; ++j) {
        const Slot a = slots[e * k + i], b = slots[e * k + j];
        if (a == kNoSlot || b == kNoSlot) continue;
        d.kx.block<3, 3>(3 * a, 3 * b) += jx[e * k * k + i * k + j];
        d.kv.block<3, 3>(3 * a, 3 * b) += jv[e * k * k + i * k + j];
      }
    }
  }
  return d;
}

// Largest |central difference - Jacobian| over every entry, relative to the
// largest Jacobian entry; wrt_x selects positions or velocities.
Real finite_difference_error(Simulation& sim, const Eigen::MatrixXd& k, bool wrt_x) {
  auto& state = wrt_x ? sim.position().values() : sim.velocity().values();
  const OrbitAttachment& att = sim.position().attachment();
  const Real h = 1e-6;
  Real worst = 0;
  for (Slot s = 0; s < state.size(); ++s) {
    if (!att.slot_alive(s)) continue;
    for (int c = 0; c < 3; ++c) {
      const Real keep = state[s][c];
      state[s][c] = keep + h;
      const std::vector<Vec3> plus = internal_forces(sim);
      state[s][c] = keep - h;
      const std::vector<Vec3> minus = internal_forces(sim);
      state[s][c] = keep;
      for (std::size_t r = 0; r < plus.size(); ++r) {
        for (int a = 0; a < 3; ++a) {
          const Real fd = (plus[r][a] - minus[r][a]) / (2 * h);
          worst = std::max(worst, std::abs(fd - k(static_cast<Eigen::Index>(3 * r + a),
                                                  static_cast<Eigen::Index>(3 * s + c))));
        }
      }
    }
  }
  return worst / std::max(k.cwiseAbs().maxCoeff(), 1e-300);
}

std::unique_ptr<Simulation> state(const Case& c, unsigned seed, bool deform) {
  SimSetup setup;
  setup.settings.gravity = Vec3::Zero();
  setup.interactions = {c.interaction};
  setup.registry = c.registry;
  auto sim = simulate(load_map(c.mesh), setup);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  // A rigid motion (rotation about a random axis, translation) ...
  const Eigen::AngleAxisd rot(0.3 + u(rng), Vec3(u(rng), u(rng), 1 + u(rng)).normalized());
  const Vec3 shift(u(rng), u(rng), u(rng));
  move_vertices(*sim, [&](const Vec3& p) {
    Vec3 q = rot * p + shift;
    if (deform) q += 0.05 * Vec3(u(rng), u(rng), u(rng));  // ... and a deformation
    return q;
  });
  for (Vec3& v : sim->velocity().values())
    v = 0.5 * Vec3(u(rng), u(rng), u(rng));
  return sim;
}

TEST(Jacobians, EveryInteractionMatchesCentralDifferencesOfItsForces) {
  for (const Case& c : cases(0.05)) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    for (unsigned seed : {1u, 2u}) {
      auto sim = state(c, seed, true);
      ASSERT_GT(sim->force_models()[0]->jacobian_vertices(), 0)
          << sim->force_models()[0]->jacobian_unavailable_reason();
      const Dense d = dense_jacobians(*sim);
      ASSERT_GT(d.kx.cwiseAbs().maxCoeff(), 0.0);
      ASSERT_GT(d.kv.cwiseAbs().maxCoeff(), 0.0);
      EXPECT_LT(finite_difference_error(*sim, d.kv, false), 1e-6);
      if (!c.rotation_held) {
        EXPECT_LT(finite_difference_error(*sim, d.kx, true), 1e-6);
      }
    }
    if (c.rotation_held) {
      // Undamped at a rigidly moved rest shape, where R constant is exact.
      Case undamped = c;
      undamped.interaction.params.back().second = 0.0;
      auto sim = state(undamped, 3, false);
      const Dense d = dense_jacobians(*sim);
      ASSERT_GT(d.kx.cwiseAbs().maxCoeff(), 0.0);
      EXPECT_LT(finite_difference_error(*sim, d.kx, true), 1e-6);
    }
  }
}

TEST(Jacobians, ConservativeStiffnessIsSymmetric) {
  // Undamped: ∂f/∂x = -∂²E/∂x² (and R K_e Rᵀ for the co-rotational element).
  for (const Case& c : cases(0.0)) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    auto sim = state(c, 4, true);
    const Dense d = dense_jacobians(*sim);
    const Real scale = d.kx.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    EXPECT_LT((d.kx - d.kx.transpose()).cwiseAbs().maxCoeff(), 1e-10 * scale);
  }
}

// The smallest eigenvalue of the symmetric part of -J, relative to its largest.
Real smallest_relative_eigenvalue(const Eigen::MatrixXd& j) {
  const Eigen::MatrixXd s = -0.5 * (j + j.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s);
  return eig.eigenvalues().minCoeff() / std::max(eig.eigenvalues().cwiseAbs().maxCoeff(), 1e-300);
}

TEST(Jacobians, InteractionsDeclaredSemidefiniteAreSo) {
  // A rule's `semidefinite;` lets the implicit solver skip its test and
  // projection (element_matrix.hpp): check the claim on strongly deformed,
  // moving states, damped, where a wrong claim would show.
  int declared = 0;
  for (const Case& c : cases(0.05)) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    for (unsigned seed : {7u, 8u, 9u}) {
      auto sim = state(c, seed, true);
      if (!sim->force_models()[0]->jacobian_semidefinite()) break;
      ++declared;
      // Squash the element hard (an inverted or compressed state is where
      // springs lose definiteness).
      move_vertices(*sim, [](const Vec3& p) { return Vec3(p.x(), 0.2 * p.y(), 1.5 * p.z()); });
      const Dense d = dense_jacobians(*sim);
      EXPECT_GT(smallest_relative_eigenvalue(d.kx), -1e-12);
      EXPECT_GT(smallest_relative_eigenvalue(d.kv), -1e-12);
    }
  }
  EXPECT_GT(declared, 0) << "no standard interaction declares `semidefinite;`";
}

TEST(Jacobians, TheSemidefiniteCheckSeesAnIndefiniteSpring) {
  // The check above can fail: a compressed spring's transverse stiffness
  // k(1 - L0/L) is negative, and its -J has a negative eigenvalue.
  const Case spring{"grid:mix:3x3", {"stretch", {{"stiffness", 60.0}, {"damping", 0.0}}}};
  auto sim = state(spring, 7, false);
  EXPECT_FALSE(sim->force_models()[0]->jacobian_semidefinite());
  move_vertices(*sim, [](const Vec3& p) { return 0.5 * p; });
  EXPECT_LT(smallest_relative_eigenvalue(dense_jacobians(*sim).kx), -1e-3);
}

// Largest |J·p - (blocks)·p| of the matrix-free product at random p,
// relative to the blocks' product.
Real product_error(Simulation& sim, const Dense& d) {
  const std::size_t n = sim.position().values().size();
  std::mt19937 rng(6);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Vec3> px(n), pv(n), out(n, Vec3::Zero());
  Eigen::VectorXd qx(3 * n), qv(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    px[i] = Vec3(u(rng), u(rng), u(rng));
    pv[i] = Vec3(u(rng), u(rng), u(rng));
    qx.segment<3>(static_cast<Eigen::Index>(3 * i)) = px[i];
    qv.segment<3>(static_cast<Eigen::Index>(3 * i)) = pv[i];
  }
  const ForceInput in{sim.position().values().data(), sim.velocity().values().data()};
  sim.force_models()[0]->add_jacobian_product(in, px.data(), pv.data(), out.data());
  const Eigen::VectorXd expected = d.kx * qx + d.kv * qv;
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 0.0);
  Real worst = 0;
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst,
                     (out[i] - Vec3(expected.segment<3>(static_cast<Eigen::Index>(3 * i)))).norm());
  return worst / (1 + expected.cwiseAbs().maxCoeff());
}

TEST(Jacobians, MatrixFreeProductEqualsTheBlocks) {
  for (const Case& c : cases(0.05)) {
    SCOPED_TRACE(std::string(c.mesh) + " " + c.interaction.name);
    auto sim = state(c, 5, true);
    EXPECT_LT(product_error(*sim, dense_jacobians(*sim)), 1e-10);
  }
}

// ---- Blocks a rule gives (`jacobian a.f by b.position = ...;`),
// tests/physics/given_jacobians.rules: the damped spring written four ways.

const PackRegistry& given_jacobian_packs() {
  static const PackRegistry registry = [] {
    PackRegistry r;
    rift_register_pack_given_jacobians(r);
    return r;
  }();
  return registry;
}

Case given(const char* interaction) {
  return {"block:hex:2x2x1",
          {interaction, {{"stiffness", 60.0}, {"damping", 0.05}, {"rest", 0.4}}},
          false,
          &given_jacobian_packs()};
}

TEST(GivenJacobians, BlocksEqualToTheDerivedOnesGiveTheSameJacobians) {
  for (unsigned seed : {1u, 2u}) {
    auto derived = state(given("spring_derived"), seed, true);
    auto given_blocks = state(given("spring_given"), seed, true);
    const Dense d = dense_jacobians(*derived), g = dense_jacobians(*given_blocks);
    const Real sx = d.kx.cwiseAbs().maxCoeff(), sv = d.kv.cwiseAbs().maxCoeff();
    ASSERT_GT(sx, 0.0);
    ASSERT_GT(sv, 0.0);
    EXPECT_LT((d.kx - g.kx).cwiseAbs().maxCoeff(), 1e-12 * sx);
    EXPECT_LT((d.kv - g.kv).cwiseAbs().maxCoeff(), 1e-12 * sv);
    EXPECT_LT(finite_difference_error(*given_blocks, g.kx, true), 1e-6);
    EXPECT_LT(finite_difference_error(*given_blocks, g.kv, false), 1e-6);
    EXPECT_LT(product_error(*given_blocks, g), 1e-10);
  }
}

TEST(GivenJacobians, AForceWithoutDerivativeHasJacobiansWhenItsBlocksAreGiven) {
  // spring_eigen's direction is an eigenvector (no derivative): riftc
  // accepts it for implicit integration because every block the eigenvector
  // enters is given; its velocity blocks are derived.
  for (unsigned seed : {1u, 2u}) {
    auto sim = state(given("spring_eigen"), seed, true);
    ASSERT_GT(sim->force_models()[0]->jacobian_vertices(), 0)
        << sim->force_models()[0]->jacobian_unavailable_reason();
    const Dense d = dense_jacobians(*sim);
    ASSERT_GT(d.kx.cwiseAbs().maxCoeff(), 0.0);
    ASSERT_GT(d.kv.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(finite_difference_error(*sim, d.kx, true), 1e-6);
    EXPECT_LT(finite_difference_error(*sim, d.kv, false), 1e-6);
    EXPECT_LT(product_error(*sim, d), 1e-10);
  }
}

TEST(GivenJacobians, ImplicitEulerStepsOnGivenBlocksAsOnDerivedOnes) {
  // Implicit Euler takes spring_eigen (it refuses a force without
  // Jacobians): hanging under gravity at dt = 0.02, it moves as the same
  // spring with derived Jacobians does.
  auto hang = [](const char* interaction) {
    SimSetup setup;
    setup.settings.integrator = IntegratorKind::kImplicitEuler;
    setup.settings.dt = 0.02;
    setup.settings.gravity = Vec3(0, 0, -9.81);
    setup.interactions = {given(interaction).interaction};
    setup.registry = &given_jacobian_packs();
    setup.prepare = [](Simulation& s) {
      s.set_total_mass(0.1);
      s.pin_where([](const Vec3& p) { return p.z() > 0.99; });
    };
    auto sim = simulate(load_map("block:hex:2x2x1"), setup);
    for (int s = 0; s < 50; ++s)
      sim->step();
    return sim;
  };
  auto eigen = hang("spring_eigen");
  auto derived = hang("spring_derived");
  const auto& xe = eigen->position().values();
  const auto& xd = derived->position().values();
  ASSERT_EQ(xe.size(), xd.size());
  Real moved = 0, apart = 0;
  for (std::size_t i = 0; i < xe.size(); ++i) {
    ASSERT_TRUE(xe[i].allFinite());
    apart = std::max(apart, (xe[i] - xd[i]).norm());
    moved = std::max(moved, std::abs(xe[i].z() - std::round(xe[i].z())));
  }
  EXPECT_GT(moved, 0.1);  // the block has moved off the grid
  EXPECT_LT(apart, 1e-8);
}

TEST(GivenJacobians, TheFiniteDifferenceTestSeesAWrongGivenBlock) {
  // spring_eigen_wrong leaves the damping's position part out of a.f's
  // blocks: on a moving state the central differences disagree, far above
  // the 1e-6 the tests above pass with (2.5e-4 at damping 0.05, so the
  // damping is raised to make the mistake plain).
  Case wrong = given("spring_eigen_wrong");
  wrong.interaction.params[1].second = 1.0;
  auto sim = state(wrong, 1, true);
  const Dense d = dense_jacobians(*sim);
  EXPECT_GT(finite_difference_error(*sim, d.kx, true), 1e-3);
  EXPECT_LT(finite_difference_error(*sim, d.kv, false), 1e-6);  // derived, right
}

}  // namespace
}  // namespace rift::physics_test

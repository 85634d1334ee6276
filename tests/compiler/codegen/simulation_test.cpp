// Generated packs inside the real simulation loop: a generated stretch spring
// against the hand-written one, a bending-like interaction losing the matches
// of cut edges, a generated criterion tearing a cloth, and registration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "../../sim/test_spring_model.hpp"
#include "gen2d.hpp"
#include "rift/io/load_map.hpp"
#include "rift/sim/simulation.hpp"

namespace {

namespace g2 = rift::packs::gen2d;
using rift::ComponentUse;
using rift::Dart;
using rift::GMap;
using rift::Real;
using rift::SceneParam;
using rift::Simulation;
using rift::Value;
using rift::Vec3;

ComponentUse use(const char* name, std::initializer_list<std::pair<const char*, Value>> params) {
  ComponentUse u;
  u.name = name;
  for (const auto& [key, value] : params)
    u.params[key] = SceneParam{value, 0};
  return u;
}

std::unique_ptr<Simulation> cloth(const char* mesh, std::unique_ptr<rift::ForceModel> model,
                                  std::unique_ptr<rift::Criterion> criterion = nullptr,
                                  bool grouped = true) {
  GMap g = rift::load_map(mesh);
  g2::Pack().initialise(g);
  rift::SimulationSettings settings;
  settings.group_interactions = grouped;
  settings.integrator = rift::IntegratorKind::kRK4;
  settings.dt = 1e-3;
  settings.check_each_rewrite = true;
  auto sim = std::make_unique<Simulation>(std::move(g), settings);
  sim->set_total_mass(0.1);
  sim->pin_where([](const Vec3& p) { return p.y() > 0.99; });
  sim->add_force_model(std::move(model));
  if (criterion) sim->add_criterion(std::move(criterion));
  sim->initialise();
  return sim;
}

rift::ForceInput state(const Simulation& sim) {
  return {sim.position().values().data(), sim.velocity().values().data()};
}

TEST(GeneratedSimulation, StretchMatchesTheHandWrittenSpringModel) {
  const g2::Pack pack;
  auto generated = cloth(
      "grid:quad:4x4",
      pack.make_interaction(use("stretch", {{"stiffness", Value(60.0)}, {"damping", Value(0.1)}})));
  auto reference = cloth("grid:quad:4x4", std::make_unique<rift::test::HalfEdgeSprings>(60.0, 0.1));
  ASSERT_EQ(generated->force_models()[0]->active_matches(),
            reference->force_models()[0]->active_matches());
  // Forces on a deformed state, slot by slot.
  for (auto* sim : {generated.get(), reference.get()}) {
    auto& x = sim->position().values();
    for (std::size_t s = 0; s < x.size(); ++s)
      x[s] += Vec3(0.01 * std::sin(3.0 * s), 0.02 * std::cos(5.0 * s), 0.03 * std::sin(7.0 * s));
  }
  const std::size_t n = generated->position().values().size();
  std::vector<Vec3> fg(n, Vec3::Zero()), fr(n, Vec3::Zero());
  generated->force_models()[0]->add_forces(state(*generated), fg.data(), false);
  reference->force_models()[0]->add_forces(state(*reference), fr.data(), false);
  Real largest = 0;
  for (std::size_t s = 0; s < n; ++s) {
    EXPECT_LT((fg[s] - fr[s]).norm(), 1e-12 * (1 + fr[s].norm())) << "slot " << s;
    largest = std::max(largest, fr[s].norm());
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_NEAR(generated->potential_energy(), reference->potential_energy(), 1e-12);
  // A few RK4 steps: the generated kernel reads the integrator's stages.
  for (int step = 0; step < 25; ++step) {
    generated->step();
    reference->step();
  }
  for (std::size_t s = 0; s < n; ++s) {
    EXPECT_LT((generated->position().values()[s] - reference->position().values()[s]).norm(), 1e-12)
        << "slot " << s;
  }
  EXPECT_GT((generated->position().values()[0] - Vec3(0, 0, 0)).norm(), 0.0);
}

TEST(GeneratedSimulation, CutEdgesLoseTheirBendingMatchesAndStoredForces) {
  const g2::Pack pack;
  auto sim = cloth("grid:quad:4x4", pack.make_interaction(use("bend", {{"k", Value(2.0)}})));
  GMap& g = sim->map();
  EXPECT_EQ(g2::BendKernel::kRadius, 3);  // q = a@2@1@0
  rift::ForceModel& bend = *sim->force_models()[0];
  // Every inner dart is one side of a 2-link: one match per <2> orbit of two darts.
  std::size_t inner = 0;
  g.for_each_dart([&](Dart d) { inner += g.is_free(d, 2) ? 0 : 1; });
  EXPECT_EQ(bend.active_matches(), inner / 2);
  auto& x = sim->position().values();
  for (std::size_t s = 0; s < x.size(); ++s)
    x[s] += Vec3(0.02 * std::sin(3.0 * s), 0.01 * std::cos(5.0 * s), 0.04 * std::sin(2.0 * s));
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  bend.add_forces(state(*sim), f.data(), true);
  auto stored = g.embedding<Vec3>("f_bend");
  std::vector<Vec3> before(g.capacity(), Vec3::Zero());
  g.for_each_dart([&](Dart d) { before[d] = stored[d]; });

  // Cut two interior edges.
  std::vector<Dart> cut_edges;
  g.for_each_dart([&](Dart d) {
    if (cut_edges.size() < 2 && !g.is_free(d, 2) && !g.is_free(g.alpha(d, 0), 2)) {
      for (Dart c : cut_edges) {
        if (g.in_same_orbit(c, d, rift::Orbit{0, 2})) return;
      }
      cut_edges.push_back(d);
    }
  });
  ASSERT_EQ(cut_edges.size(), 2u);
  std::vector<Dart> touched, lost_stores;
  for (Dart e : cut_edges) {
    g.for_each_in_orbit(e, rift::Orbit{0, 2}, [&](Dart a) {
      touched.push_back(a);
      lost_stores.push_back(g.alpha(g.alpha(a, 1), 0));  // node p of the match at <2>(a)
    });
    g.unsew(e, 2);
  }
  EXPECT_TRUE(g.is_valid());
  sim->on_topology_changed(touched);
  // Each cut edge had two extremities <2>, each with one match.
  EXPECT_EQ(bend.active_matches(), inner / 2 - 2 * cut_edges.size());
  for (Dart p : lost_stores)
    EXPECT_EQ(stored[p], Vec3::Zero()) << "dart " << p;
  // Every other match is intact: storing again gives the same forces (the
  // cut split vertices, so there are more vertex slots now).
  f.assign(sim->position().values().size(), Vec3::Zero());
  bend.add_forces(state(*sim), f.data(), true);
  std::size_t kept = 0;
  g.for_each_dart([&](Dart d) {
    if (std::find(lost_stores.begin(), lost_stores.end(), d) != lost_stores.end()) {
      EXPECT_EQ(stored[d], Vec3::Zero());
      return;
    }
    EXPECT_LT((stored[d] - before[d]).norm(), 1e-12) << "dart " << d;
    kept += stored[d].norm() > 0 ? 1 : 0;
  });
  EXPECT_GT(kept, 0u);
}

// This pack's bend keeps its rest length on one dart (p, `<>`), written by
// its init from the dart the support orbit is matched from: the result
// depends on that dart. Grouping identical matches must not change it:
// grouped and ungrouped give the same forces and, dart by dart, the same
// stored forces, before and after cuts.
TEST(GeneratedSimulation, GroupingKeepsTheDartEachMatchStartsFrom) {
  const g2::Pack pack;
  auto make = [&](bool grouped) {
    return cloth("grid:quad:6x6", pack.make_interaction(use("bend", {{"k", Value(2.0)}})), nullptr,
                 grouped);
  };
  auto grouped = make(true);
  auto plain = make(false);
  rift::ForceModel& gb = *grouped->force_models()[0];
  rift::ForceModel& pb = *plain->force_models()[0];
  EXPECT_LT(gb.evaluated_matches(), pb.evaluated_matches()) << "nothing was grouped";
  // The rest lengths the inits wrote, dart by dart.
  auto rest_g = grouped->map().embedding<Real>("bend_rest");
  auto rest_p = plain->map().embedding<Real>("bend_rest");
  grouped->map().for_each_dart([&](Dart d) { ASSERT_EQ(rest_g[d], rest_p[d]) << "dart " << d; });
  auto compare = [&](const char* when) {
    for (auto* sim : {grouped.get(), plain.get()}) {
      auto& x = sim->position().values();
      for (std::size_t s = 0; s < x.size(); ++s)
        x[s] += Vec3(0.02 * std::sin(3.0 * s), 0.01 * std::cos(5.0 * s), 0.04 * std::sin(2.0 * s));
    }
    const std::size_t n = grouped->position().values().size();
    ASSERT_EQ(n, plain->position().values().size());
    std::vector<Vec3> fg(n, Vec3::Zero()), fp(n, Vec3::Zero());
    gb.add_forces(state(*grouped), fg.data(), true);
    pb.add_forces(state(*plain), fp.data(), true);
    Real largest = 0;
    for (const Vec3& f : fp)
      largest = std::max(largest, f.norm());
    ASSERT_GT(largest, 0);
    for (std::size_t s = 0; s < n; ++s)
      ASSERT_LE((fg[s] - fp[s]).norm(), 1e-12 * largest) << when << ", slot " << s;
    auto sg = grouped->map().embedding<Vec3>("f_bend");
    auto sp = plain->map().embedding<Vec3>("f_bend");
    std::size_t stored = 0;
    grouped->map().for_each_dart([&](Dart d) {
      ASSERT_EQ(sg[d], sp[d]) << when << ", dart " << d;
      stored += sp[d] != Vec3::Zero() ? 1 : 0;
    });
    EXPECT_GT(stored, 0u) << when;
  };
  compare("before the cuts");
  // Cut three interior edges, the same in both maps (built alike).
  for (int cut = 0; cut < 3; ++cut) {
    GMap& g = grouped->map();
    Dart e = rift::kNoDart;
    std::size_t skip = 7 + 11 * static_cast<std::size_t>(cut);
    g.for_each_dart([&](Dart d) {
      if (e == rift::kNoDart && !g.is_free(d, 2) && skip-- == 0) e = d;
    });
    ASSERT_NE(e, rift::kNoDart);
    std::vector<Dart> touched;
    g.for_each_in_orbit(e, rift::Orbit{0, 2}, [&](Dart a) { touched.push_back(a); });
    for (auto* sim : {grouped.get(), plain.get()}) {
      sim->map().unsew(e, 2);
      ASSERT_TRUE(sim->map().is_valid());
      sim->on_topology_changed(touched);
    }
    EXPECT_EQ(gb.active_matches(), pb.active_matches());
    compare("after a cut");
  }
}

TEST(GeneratedSimulation, CriterionTearsTheClothAndKeepsTheMap) {
  const g2::Pack pack;
  auto sim =
      cloth("grid:quad:4x4", pack.make_interaction(use("stretch", {{"stiffness", Value(60.0)}})),
            pack.make_criterion(use("long_edge", {{"limit", Value(0.4)}})));
  const Real mass = sim->total_mass();
  auto free_darts = [&] {
    std::size_t n = 0;
    sim->map().for_each_dart([&](Dart d) { n += sim->map().is_free(d, 2) ? 1 : 0; });
    return n;
  };
  const std::size_t boundary = free_darts();
  // Pull the lower half of the cloth down: edges across y = 0.5 stretch past the limit.
  for (Vec3& p : sim->position().values()) {
    if (p.y() < 0.49) p.y() -= 0.3;
  }
  sim->step();  // check_each_rewrite: an invalid map would throw
  EXPECT_GT(sim->tears(), 0u);
  EXPECT_TRUE(sim->map().is_valid());
  EXPECT_EQ(free_darts(), boundary + 4 * sim->tears());  // each separated edge: 4 free darts
  EXPECT_NEAR(sim->total_mass(), mass, 1e-12);
  for (int step = 0; step < 10; ++step)
    sim->step();
  EXPECT_TRUE(sim->map().is_valid());
  EXPECT_NEAR(sim->total_mass(), mass, 1e-12);
}

// riftc runs an interaction's inits in one pass over its matches unless one
// reads what an earlier one writes (kernel_emit.cpp, init_passes). chain's
// next_rest(a) reads chain_rest at the half-edge after b, which that
// half-edge's own match writes: run in the same pass, the matches visited
// before their neighbour would read the default, 0. On a grid with moved
// vertices every half-edge has its own length, so next_rest must be exactly
// the length of one of the two half-edges that follow its ends.
TEST(GeneratedSimulation, AnInitReadingAnotherMatchsInitRunsAfterIt) {
  GMap g = rift::load_map("grid:quad:5x5");
  g2::Pack().initialise(g);
  auto x = g.embedding<Vec3>("position");
  for (std::size_t s = 0; s < x.values().size(); ++s)
    x.values()[s] += Vec3(0.013 * std::sin(3.0 * s), 0.021 * std::cos(7.0 * s), 0);
  rift::SimulationSettings settings;
  settings.dt = 1e-3;
  Simulation sim(std::move(g), settings);
  sim.set_total_mass(0.1);
  sim.add_force_model(g2::Pack().make_interaction(use("chain", {{"k", Value(1.0)}})));
  sim.initialise();
  const GMap& m = sim.map();
  auto pos = m.embedding<Vec3>("position");
  auto rest = m.embedding<Real>("chain_rest");
  auto next = m.embedding<Real>("next_rest");
  auto length = [&](Dart d) { return (pos[m.alpha(d, 0)] - pos[d]).norm(); };
  std::size_t checked = 0;
  m.for_each_dart([&](Dart d) {
    ASSERT_EQ(rest[d], length(d)) << "dart " << d;
    // The match started from d or from its alpha_0; b is the other one.
    const Real after_other = length(m.alpha(m.alpha(d, 0), 1));
    const Real after_d = length(m.alpha(d, 1));
    ASSERT_GT(next[d], 0) << "dart " << d << ": read before its neighbour's init";
    ASSERT_TRUE(next[d] == after_other || next[d] == after_d) << "dart " << d;
    ++checked;
  });
  EXPECT_EQ(checked, m.size());
}

TEST(GeneratedRegistration, AddsThePackWithItsCatalog) {
  rift::PackRegistry registry;
  rift_register_pack_gen2d(registry);
  ASSERT_EQ(registry.packs().size(), 1u);
  const rift::Pack* pack = registry.pack_of_interaction("stretch", 2);
  ASSERT_NE(pack, nullptr);
  EXPECT_EQ(pack->name(), "gen2d");
  EXPECT_EQ(registry.pack_of_interaction("stretch", 3), nullptr);
  EXPECT_EQ(registry.pack_of_criterion("long_edge", 2), pack);
  const rift::Catalog catalog = registry.catalog(2);
  const rift::ComponentSpec* stretch = rift::Catalog::find(catalog.interactions, "stretch");
  ASSERT_NE(stretch, nullptr);
  EXPECT_EQ(stretch->dimension, 2);
  // The `///` comment above the interaction describes it.
  EXPECT_EQ(stretch->description.rfind("A damped spring on every half-edge.", 0), 0u)
      << stretch->description;
  ASSERT_EQ(stretch->params.size(), 2u);
  const rift::ParamSpec* k = stretch->find_param("stiffness");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(k->type, rift::ValueType::kReal);
  EXPECT_FALSE(k->default_value.has_value());  // required
  EXPECT_TRUE(k->positive);
  EXPECT_EQ(k->description, "N/m");
  const rift::ParamSpec* c = stretch->find_param("damping");
  ASSERT_NE(c, nullptr);
  ASSERT_TRUE(c->default_value.has_value());
  EXPECT_EQ(std::get<Real>(*c->default_value), 0.0);
  EXPECT_TRUE(c->non_negative);
  const rift::ComponentSpec* edge = rift::Catalog::find(catalog.criteria, "long_edge");
  ASSERT_NE(edge, nullptr);
  EXPECT_EQ(std::get<Real>(*edge->find_param("limit")->default_value), 0.5);
  // The factories check what a scene gives.
  EXPECT_THROW(pack->make_interaction(use("stretch", {})), std::invalid_argument);
  EXPECT_THROW(pack->make_interaction(use("stretch", {{"stiffness", Value(-1.0)}})),
               std::invalid_argument);
  EXPECT_THROW(pack->make_interaction(use("nope", {})), std::invalid_argument);
  const auto model =
      pack->make_interaction(use("stretch", {{"stiffness", Value(std::int64_t{3})}}));
  EXPECT_EQ(model->name(), "stretch");
}

}  // namespace

// Random rules on random maps (issue 9, deliverable 5): every rule of the
// standard packs that rewrite (topology2d, topology3d, construction2d) and of
// the random packs (a few hundred consistent rules that
// generate_random_rules.cpp wrote and riftc accepted) is applied at random
// darts of random 2D and 3D maps; after every application the map must be
// valid (GMap::check_validity: links, cycles, embedding slots), and a rule
// that does not apply must leave the map as it was.
//
// Two passes per map: each rule alone on a fresh map, a few times in a row;
// then long random sequences mixing every rule of the dimension on one map,
// so that rules meet the maps that other rules made (free darts, isolated
// cells, relabelled orbits).
//
// The generator's report gives riftc's verdicts: it must accept (nearly)
// every rule the generator's checker found consistent, and reject every rule
// that checker found inconsistent.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "construction2d.hpp"
#include "random2d.hpp"
#include "random3d.hpp"
#include "rift/io/load_map.hpp"
#include "rift/pack/pack.hpp"
#include "shared_test_data.hpp"
#include "topology2d.hpp"
#include "topology3d.hpp"

namespace rift {
namespace {

using Rng = std::mt19937_64;

int uniform_int(Rng& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// ---- riftc's verdicts -----------------------------------------------------------------

struct Report {
  std::map<std::string, int> counts;
  std::string rejected, accepted_bad;  // the two lists of the report
};

Report read_report(const std::string& pack) {
  std::ifstream in(std::string(RIFT_RANDOM_RULES_DIR) + "/" + pack + "_report.txt");
  Report r;
  std::string line;
  std::string* section = nullptr;
  while (std::getline(in, line)) {
    if (line.rfind("---- consistent", 0) == 0) {
      section = &r.rejected;
    } else if (line.rfind("---- inconsistent", 0) == 0) {
      section = &r.accepted_bad;
    } else if (section != nullptr) {
      *section += line + "\n";
    } else {
      std::istringstream fields(line);
      std::string key;
      int value = 0;
      fields >> key >> value;
      r.counts[key] = value;
    }
  }
  return r;
}

class RiftcVerdicts : public ::testing::TestWithParam<const char*> {};

TEST_P(RiftcVerdicts, AcceptsTheConsistentRulesAndRejectsTheOthers) {
  const Report r = read_report(GetParam());
  const int generated =
      r.counts.count("consistent_generated") != 0 ? r.counts.at("consistent_generated") : 0;
  ASSERT_GE(generated, 100) << "the generator's report is missing or short";
  // riftc decides cycles as the generator's checker does: every consistent
  // rule should pass. A few rejections would be riftc being cautious where
  // the checker is not (listed); more means one of them is wrong.
  EXPECT_GE(r.counts.at("consistent_accepted"), generated * 95 / 100)
      << "consistent rules riftc rejected:\n"
      << r.rejected;
  EXPECT_TRUE(r.rejected.empty()) << "consistent rules riftc rejected:\n" << r.rejected;
  ASSERT_GE(r.counts.at("inconsistent_generated"), 30);
  EXPECT_EQ(r.counts.at("inconsistent_rejected"), r.counts.at("inconsistent_generated"))
      << "inconsistent rules riftc accepted:\n"
      << r.accepted_bad;
}

INSTANTIATE_TEST_SUITE_P(Packs, RiftcVerdicts, ::testing::Values("random2d", "random3d"));

// ---- rules applied at random darts ----------------------------------------------------

const PackRegistry& packs() {
  static const PackRegistry registry = [] {
    PackRegistry r;
    rift_register_pack_random2d(r);
    rift_register_pack_random3d(r);
    rift_register_pack_topology2d(r);
    rift_register_pack_topology3d(r);
    rift_register_pack_construction2d(r);
    return r;
  }();
  return registry;
}

struct NamedRule {
  const Pack* pack;
  std::unique_ptr<Rule> rule;
};

std::vector<NamedRule> rules_of_dimension(int dim) {
  std::vector<NamedRule> out;
  for (const auto& pack : packs().packs()) {
    if (pack->dimension() != dim) continue;
    for (const std::string& name : pack->rule_names())
      out.push_back({pack.get(), pack->make_rule(name)});
  }
  return out;
}

std::vector<std::string> maps_of_dimension(int dim) {
  const std::string shared = RIFT_SHARED_MESHES;
  if (dim == 2) {
    return {"grid:quad:3x3", "grid:tri:3x2", "grid:mix:4x3", shared + "/triangleGrid_10_10.obj",
            shared + "/square3.msh"};
  }
  return {"block:hex:2x2x1", "block:tet:2x1x1", "block:hex:1x1x1", shared + "/cube_low_res.msh"};
}

/// A map with the embeddings and initial values of every pack of its dimension.
GMap prepared_map(const std::string& spec, int dim) {
  GMap map = load_map(spec);
  for (const auto& pack : packs().packs()) {
    if (pack->dimension() == dim) pack->initialise(map);
  }
  return map;
}

/// Random arguments of the rule's types (fracture planes, flags).
std::vector<Value> random_args(const Rule& rule, Rng& rng) {
  std::vector<Value> args;
  std::normal_distribution<double> gauss;
  for (const ParamSpec& p : rule.params()) {
    switch (p.type) {
      case ValueType::kVec3:
        args.emplace_back(Vec3(Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized() * 0.5));
        break;
      case ValueType::kBool:
        args.emplace_back(Bool(uniform_int(rng, 0, 1) == 1));
        break;
      case ValueType::kInt:
        args.emplace_back(std::int64_t{uniform_int(rng, 1, 3)});
        break;
      case ValueType::kMat3:
        args.emplace_back(Mat3(Mat3::Identity()));
        break;
      case ValueType::kReal:
        args.emplace_back(Real(uniform_int(rng, 1, 10)) / 10.0);
        break;
    }
  }
  return args;
}

/// Hook darts: random live darts, half of the time among darts free in some
/// dimension (patterns with loops match there).
std::vector<Dart> random_hooks(const GMap& map, int count, Rng& rng) {
  std::vector<Dart> live, free;
  map.for_each_dart([&](Dart d) {
    live.push_back(d);
    for (int i = 0; i <= map.dimension(); ++i) {
      if (map.is_free(d, i)) {
        free.push_back(d);
        break;
      }
    }
  });
  std::vector<Dart> hooks;
  for (int h = 0; h < count && !live.empty(); ++h) {
    const auto& from = !free.empty() && uniform_int(rng, 0, 1) == 0 ? free : live;
    hooks.push_back(
        from[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(from.size()) - 1))]);
  }
  return hooks;
}

/// Applies `rule` at random darts; fails the test at the first invalid map
/// or a refused application that changed the map. Returns whether it applied.
bool apply_once(GMap& map, NamedRule& r, Rng& rng, const std::string& where) {
  const std::vector<Dart> hooks = random_hooks(map, r.rule->hook_count(), rng);
  if (static_cast<int>(hooks.size()) != r.rule->hook_count()) return false;
  const std::vector<Value> args = random_args(*r.rule, rng);
  const std::size_t darts = map.size();
  std::vector<Dart> touched;
  const bool applied = r.rule->apply(map, hooks, args, touched);
  const auto problems = map.check_validity(3);
  EXPECT_TRUE(problems.empty()) << r.pack->name() << "::" << r.rule->name() << " at dart "
                                << hooks.front() << " " << where << ": "
                                << (problems.empty() ? "" : problems.front());
  if (!applied) {
    EXPECT_EQ(map.size(), darts) << r.pack->name() << "::" << r.rule->name()
                                 << " did not apply but changed the map " << where;
  }
  return applied;
}

class RandomRulesOnRandomMaps : public ::testing::TestWithParam<int> {};

TEST_P(RandomRulesOnRandomMaps, EveryApplicationLeavesAValidMap) {
  const int dim = GetParam();
  RIFT_EXPECT_SHARED_MESHES(std::filesystem::is_directory(RIFT_SHARED_MESHES));
  std::vector<NamedRule> rules = rules_of_dimension(dim);
  ASSERT_GE(rules.size(), 100U);
  Rng rng(9000 + static_cast<unsigned>(dim));
  std::map<std::string, int> applied;  // pack::rule -> applications
  const auto key = [](const NamedRule& r) { return r.pack->name() + "::" + r.rule->name(); };
  int applications = 0;

  // Each rule alone, a few times in a row, on every map.
  for (const std::string& spec : maps_of_dimension(dim)) {
    for (NamedRule& r : rules) {
      GMap map = prepared_map(spec, dim);
      for (int attempt = 0; attempt < 6; ++attempt) {
        if (apply_once(map, r, rng, "(alone, on " + spec + ")")) {
          ++applied[key(r)];
          ++applications;
        }
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  // Random sequences of every rule of the dimension on one map.
  for (const std::string& spec : maps_of_dimension(dim)) {
    GMap map = prepared_map(spec, dim);
    for (int step = 0; step < 600 && map.size() > 0; ++step) {
      NamedRule& r =
          rules[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(rules.size()) - 1))];
      if (apply_once(map, r, rng,
                     "(step " + std::to_string(step) + " of a sequence on " + spec + ")")) {
        ++applied[key(r)];
        ++applications;
      }
      if (::testing::Test::HasFailure()) return;
    }
  }

  // Every standard rule applied, and most random ones (a pattern of loops
  // or of two hooks may find no match at random darts).
  int random_rules = 0, random_applied = 0;
  for (const NamedRule& r : rules) {
    const bool random = r.pack->name().rfind("random", 0) == 0;
    if (random) {
      ++random_rules;
      random_applied += applied.count(key(r)) != 0 ? 1 : 0;
    } else {
      EXPECT_GT(applied[key(r)], 0) << key(r) << " never applied";
    }
  }
  std::cout << "dimension " << dim << ": " << applications << " applications, " << random_applied
            << " of " << random_rules << " random rules applied\n";
  EXPECT_GE(random_applied * 10, random_rules * 7) << "too few random rules matched";
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RandomRulesOnRandomMaps, ::testing::Values(2, 3));

}  // namespace
}  // namespace rift

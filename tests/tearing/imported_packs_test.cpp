// `import` (docs/language.md): criteria2d and criteria3d apply the rules and
// scripts of topology2d and topology3d without copying them, and registering
// an importing pack registers what it imports, once.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "criteria2d.hpp"
#include "criteria3d.hpp"
#include "rift/pack/pack.hpp"
#include "topology2d.hpp"
#include "topology3d.hpp"

namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(ImportedPacks, RegisteringCriteriaRegistersTheTopologyTheyApply) {
  rift::PackRegistry registry;
  rift_register_pack_criteria2d(registry);
  rift_register_pack_criteria3d(registry);
  const rift::Pack* topology2d = registry.find("topology2d");
  const rift::Pack* topology3d = registry.find("topology3d");
  ASSERT_NE(topology2d, nullptr);
  ASSERT_NE(topology3d, nullptr);
  EXPECT_EQ(registry.packs().size(), 4u);
  // The rules live in the topology packs only.
  EXPECT_TRUE(has(topology2d->rule_names(), "separate_faces"));
  EXPECT_TRUE(has(topology2d->rule_names(), "split_vertex"));
  EXPECT_FALSE(has(registry.find("criteria2d")->rule_names(), "separate_faces"));
  EXPECT_FALSE(has(registry.find("criteria2d")->rule_names(), "split_vertex"));
  EXPECT_FALSE(has(registry.find("criteria3d")->rule_names(), "separate_volumes"));
  // A criteria pack still has its own script.
  EXPECT_TRUE(has(registry.find("criteria2d")->rule_names(), "split_along_largest_force"));
}

TEST(ImportedPacks, RegisteringAPackTwiceKeepsOne) {
  rift::PackRegistry registry;
  rift_register_pack_topology2d(registry);
  rift_register_pack_criteria2d(registry);
  rift_register_pack_topology2d(registry);
  rift_register_pack_criteria2d(registry);
  EXPECT_EQ(registry.packs().size(), 2u);
}

}  // namespace

// The simulator's state columns come from one table (rift/core/state_embeddings.hpp)
// that riftc reads too: these tests pin what the runtime does with it.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "rift/gmap/state_columns.hpp"
#include "rift/mesh/assemble.hpp"
#include "rift/mesh/generators.hpp"
#include "test_maps.hpp"

namespace rift {
namespace {

TEST(StateColumns, EveryDeclarationGetsItsOrbitAndPolicyInBothDimensions) {
  for (int n : {2, 3}) {
    GMap map(n);
    for (const state::Declaration& d : state::kDeclarations) {
      switch (d.kind) {
        case state::Kind::kVec3:
          state_embedding<Vec3>(map, d.name);
          break;
        case state::Kind::kReal:
          state_embedding<Real>(map, d.name);
          break;
        case state::Kind::kBool:
          state_embedding<Bool>(map, d.name);
          break;
        case state::Kind::kInt:
          state_embedding<std::int64_t>(map, d.name);
          break;
      }
      const ColumnBase* column = map.find_column(d.name);
      ASSERT_NE(column, nullptr) << d.name;
      EXPECT_EQ(column->policy(), state_policy(d)) << d.name;
      EXPECT_EQ(map.attachment_of(d.name)->orbit(), state_orbit(d, n)) << d.name;
    }
    EXPECT_EQ(map.attachment_of("velocity")->orbit(), Orbit::cell(0, n));
    EXPECT_EQ(map.find_column("velocity")->policy(), MergePolicy::kMean);
    EXPECT_EQ(map.find_column("vertex_mass")->policy(), MergePolicy::kSum);
    EXPECT_EQ(map.attachment_of("corner_mass")->orbit(), Orbit::all(n - 1).without(0));
    EXPECT_EQ(map.attachment_of("element_index")->orbit(), Orbit::all(n - 1));
  }
}

TEST(StateColumns, AMapsOwnColumnIsKeptWhenItAgrees) {
  GMap map = assemble_gmap(make_grid(GridKind::Quad, 2, 2));
  Embedding<Vec3> position = map.embedding<Vec3>("position");
  position[0] = Vec3(1, 2, 3);
  Embedding<Vec3> again = state_embedding<Vec3>(map, state::kPosition);
  EXPECT_EQ(again[0], Vec3(1, 2, 3));
  EXPECT_EQ(map.find_column("position")->policy(), MergePolicy::kMean);
  EXPECT_EQ(map.find_column("point_index")->policy(), MergePolicy::kKeepFirst);
}

TEST(StateColumns, AColumnThatDisagreesIsAnErrorNamingWhat) {
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  {
    GMap map(2);
    test::make_polygon(map, 3);
    map.add_embedding<Vec3>("velocity", Orbit{1, 2}, MergePolicy::kKeepFirst);
    const std::string m = message([&] { state_embedding<Vec3>(map, state::kVelocity); });
    EXPECT_NE(m.find("'velocity' merges by 'keep', not by 'mean'"), std::string::npos) << m;
  }
  {
    GMap map(2);
    test::make_polygon(map, 3);
    map.add_embedding<Real>("corner_mass", Orbit{1, 2}, MergePolicy::kKeepFirst);
    const std::string m = message([&] { state_embedding<Real>(map, state::kCornerMass); });
    EXPECT_NE(m.find("lives on <1,2>, not on <1>"), std::string::npos) << m;
  }
  {
    GMap map(2);
    test::make_polygon(map, 3);
    map.add_embedding<Real>("velocity", Orbit{1, 2}, MergePolicy::kMean);
    const std::string m = message([&] { state_embedding<Vec3>(map, state::kVelocity); });
    EXPECT_NE(m.find("'velocity' holds real values"), std::string::npos) << m;
  }
}

TEST(StateColumns, SewingTwoVerticesMergesTheirStateAsTheTableSays) {
  GMap map(2);
  const Dart a = test::make_polygon(map, 3);
  const Dart b = test::make_polygon(map, 3);
  Embedding<Vec3> velocity = state_embedding<Vec3>(map, state::kVelocity);
  Embedding<Bool> pinned = state_embedding<Bool>(map, state::kPinned);
  velocity[a] = Vec3(2, 0, 0);
  velocity[map.alpha(a, 0)] = Vec3(0, 4, 0);
  velocity[b] = Vec3(0, 0, 0);
  velocity[map.alpha(b, 0)] = Vec3(0, 0, 6);
  pinned[b] = true;
  ASSERT_TRUE(map.sew(a, b, 2));
  // The ends of the sewn edges are one vertex each now: velocities averaged,
  // pins or-ed.
  EXPECT_EQ(velocity[a], Vec3(1, 0, 0));
  EXPECT_EQ(velocity[map.alpha(a, 0)], Vec3(0, 2, 3));
  EXPECT_TRUE(pinned[a]);
  EXPECT_FALSE(pinned[map.alpha(a, 0)]);
  EXPECT_TRUE(map.is_valid());
}

}  // namespace
}  // namespace rift

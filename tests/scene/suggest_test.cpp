#include "rift/scene/suggest.hpp"

#include <gtest/gtest.h>

namespace rift {
namespace {

TEST(Suggest, EditDistance) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("dt", "dt"), 0u);
  EXPECT_EQ(edit_distance("stifness", "stiffness"), 1u);
  EXPECT_EQ(edit_distance("gravtiy", "gravity"), 1u);  // transposition
  EXPECT_EQ(edit_distance("abc", ""), 3u);
}

TEST(Suggest, ClosestPlausibleMatch) {
  const std::vector<std::string> keys{"integrator", "dt", "steps", "gravity"};
  EXPECT_EQ(closest_match("integator", keys), "integrator");
  EXPECT_EQ(closest_match("step", keys), "steps");
  EXPECT_EQ(closest_match("colour", keys), "");
  EXPECT_EQ(did_you_mean("gravty", keys), " (did you mean 'gravity'?)");
  EXPECT_EQ(did_you_mean("zzzzzz", keys), "");
}

}  // namespace
}  // namespace rift

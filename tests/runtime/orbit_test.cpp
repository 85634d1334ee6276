#include "rift/core/orbit.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace rift {
namespace {

TEST(Orbit, CellOrbitsFollowTheDimension) {
  EXPECT_EQ(Orbit::cell(0, 2), (Orbit{1, 2}));
  EXPECT_EQ(Orbit::cell(1, 2), (Orbit{0, 2}));
  EXPECT_EQ(Orbit::cell(2, 2), (Orbit{0, 1}));
  EXPECT_EQ(Orbit::cell(0, 3), (Orbit{1, 2, 3}));
  EXPECT_EQ(Orbit::cell(2, 3), (Orbit{0, 1, 3}));
  EXPECT_EQ(Orbit::cell(3, 3), (Orbit{0, 1, 2}));
  EXPECT_EQ(Orbit::all(3), (Orbit{0, 1, 2, 3}));
}

TEST(Orbit, SewingOrbitSkipsNeighbouringDimensions) {
  EXPECT_EQ(Orbit::sewing(2, 2), (Orbit{0}));
  EXPECT_EQ(Orbit::sewing(3, 3), (Orbit{0, 1}));
  EXPECT_EQ(Orbit::sewing(1, 3), (Orbit{3}));
  EXPECT_EQ(Orbit::sewing(0, 3), (Orbit{2, 3}));
  EXPECT_EQ(Orbit::sewing(0, 1), (Orbit{}));
}

TEST(Orbit, ParsesAndPrints) {
  EXPECT_EQ(Orbit::parse("<1,2>"), (Orbit{1, 2}));
  EXPECT_EQ(Orbit::parse(" < 0 , 3 > "), (Orbit{0, 3}));
  EXPECT_EQ(Orbit::parse("<>"), Orbit{});
  EXPECT_EQ((Orbit{0, 2, 3}).str(), "<0,2,3>");
  EXPECT_EQ(Orbit{}.str(), "<>");
  for (const char* bad : {"", "<", "1,2", "<1,>", "<,1>", "<1,1>", "<4>", "<1 2>", "<1>x"}) {
    EXPECT_FALSE(Orbit::parse(bad).has_value()) << bad;
  }
}

TEST(Orbit, FirstAndSecondDimensions) {
  EXPECT_EQ((Orbit{1, 3}).first(), 1);
  EXPECT_EQ((Orbit{1, 3}).second(), 3);
  EXPECT_EQ((Orbit{0, 2}).second(), 2);
  EXPECT_EQ((Orbit{1, 2, 3}).size(), 3);
  EXPECT_TRUE((Orbit{1, 2}).fits(2));
  EXPECT_FALSE((Orbit{1, 3}).fits(2));
}

TEST(Orbit, SizeCountsTheDimensionsOfEveryMask) {
  static_assert(Orbit::from_mask(0xFF).size() == 8);
  for (unsigned mask = 0; mask < 256; ++mask) {
    int dimensions = 0;
    for (int i = 0; i < 8; ++i)
      dimensions += static_cast<int>((mask >> i) & 1u);
    EXPECT_EQ(Orbit::from_mask(static_cast<std::uint8_t>(mask)).size(), dimensions) << mask;
  }
}

}  // namespace
}  // namespace rift

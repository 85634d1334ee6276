// FlatList (rift/core/flat_list.hpp): the scratch list of MatchCache's
// re-matches. Appends past the capacity keep every value in order, reserve
// keeps what is held, and clear keeps the room.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "rift/core/flat_list.hpp"

namespace rift {
namespace {

TEST(FlatList, AppendsPastEveryCapacityKeepTheValuesInOrder) {
  FlatList<std::uint32_t> list;
  std::vector<std::uint32_t> expected;
  std::size_t growths = 0;
  std::size_t capacity = list.capacity();
  for (std::uint32_t i = 0; i < 5000; ++i) {
    const std::uint32_t value = i * 2654435761u;
    list.push_back(value);
    expected.push_back(value);
    if (list.capacity() != capacity) ++growths, capacity = list.capacity();
    ASSERT_EQ(list.size(), expected.size());
  }
  EXPECT_GE(growths, 5u) << "the test did not cross several capacities";
  ASSERT_EQ(std::vector<std::uint32_t>(list.begin(), list.end()), expected);
  for (std::size_t i = 0; i < expected.size(); ++i)
    ASSERT_EQ(list[i], expected[i]) << "at " << i;
}

TEST(FlatList, ReserveKeepsTheValuesAndClearKeepsTheRoom) {
  FlatList<std::uint32_t> list;
  for (std::uint32_t i = 0; i < 10; ++i)
    list.push_back(i);
  list.reserve(1000);
  EXPECT_GE(list.capacity(), 1000u);
  ASSERT_EQ(list.size(), 10u);
  for (std::uint32_t i = 0; i < 10; ++i)
    EXPECT_EQ(list[i], i);
  const std::size_t room = list.capacity();
  list.clear();
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(list.begin(), list.end());
  EXPECT_EQ(list.capacity(), room);
  list.reserve(10);  // less than held room: nothing changes
  EXPECT_EQ(list.capacity(), room);
}

}  // namespace
}  // namespace rift

// Words of alpha links as group elements (compiler/check/alpha_word.hpp):
// the reductions the criterion-node check and the force-ownership check rely
// on, against words whose value on every G-map is known by hand.
#include "check/alpha_word.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace rift::check {
namespace {

using Word = std::vector<int>;

TEST(AlphaWord, InvolutionsAndCommutingLettersCancel) {
  EXPECT_EQ(reduced_word({0, 0}), Word{});
  EXPECT_EQ(reduced_word({0, 2, 0}), Word{2});          // 0 passes 2
  EXPECT_EQ(reduced_word({0, 2, 0, 2}), Word{});        // (alpha_0 alpha_2)^2 = 1
  EXPECT_EQ(reduced_word({0, 1, 0}), (Word{0, 1, 0}));  // 0 does not pass 1
  EXPECT_EQ(reduced_word({1, 0, 3, 0, 1}), Word{3});    // nested cancellations
}

TEST(AlphaWord, NormalFormsAreEqualExactlyForTheSameElement) {
  EXPECT_EQ(normal_form({2, 0}), normal_form({0, 2}));
  // 1 passes 3 to the front, then 0 passes 3; 0 never passes 1.
  EXPECT_EQ(normal_form({3, 1, 0}), (Word{1, 0, 3}));
  EXPECT_NE(normal_form({0, 1}), normal_form({1, 0}));  // a face walked both ways
  EXPECT_EQ(normal_form({0, 0, 1}), normal_form({1}));
  EXPECT_NE(normal_form({1, 2, 1}), normal_form({2, 1, 2}));
}

}  // namespace
}  // namespace rift::check

// What riftc tells the slot upkeep a rewrite changes (lower::RewritePlan's
// relinked_dims and darts_come_or_go, rift/generated/slot_upkeep.hpp): the
// upkeep skips every attachment whose orbit has none of the relinked
// dimensions when no dart comes or goes. A dimension counted that does not
// change costs time; one left out would leave an orbit with two slots, which
// the tearing tests' validity checks catch. These tests pin the analysis.
#include <gtest/gtest.h>

#include <string>

#include "generated_text.hpp"

namespace {

const char* kPack = R"(pack changes dimension 2;
embedding position : vec3 on <1,2>;

// Only the 2-links change: the labels' 0-links are given back as they were.
rule separate {
  left  { a : <0>; b : <0>; a -2- b; }
  right { a : <0>; b : <0>; a -2- a; b -2- b; }
}

// Sews two free edges: again only dimension 2.
rule sew {
  left  { a : <0>; b : <0>; a -2- a; b -2- b; }
  right { a : <0>; b : <0>; a -2- b; }
}

// Explicit arcs of two dimensions change partners: a and b, 1-linked and
// 2-free before, are 1-free and 2-linked after.
rule unlink_corner {
  left  { a : <0>; b : <0>; a -1- b; a -2- a; b -2- b; }
  right { a : <0>; b : <0>; a -1- a; b -1- b; a -2- b; }
}

// Darts created: everything may change.
rule tri {
  left  { n0 : <0,1>; }
  right { n0 : <0,_>; n1 : <_,2>; n2 : <1,2>; n0 -1- n1 -0- n2;
          n2.position = mean position over <0,1>(n0); }
}

// Darts deleted: everything may change.
rule remove {
  left  { f : <0,1>; f -2- f; }
  right { }
}
)";

std::string upkeep_call(const std::string& code, const std::string& rule) {
  const std::string body = rift::compiler_test::function_text(code, "bool apply_" + rule + "(");
  const std::size_t at = body.find("update_embedding_slots(");
  if (at == std::string::npos) return "(no upkeep)";
  const std::size_t open = body.find('{', at);
  return body.substr(open, body.find('}', open) + 1 - open);
}

TEST(RewriteChanges, TheUpkeepIsToldTheDimensionsWhoseLinksChange) {
  const std::string code =
      rift::compiler_test::generated_text("changes.rules", kPack, "changes.cpp");
  ASSERT_FALSE(code.empty());
  EXPECT_EQ(upkeep_call(code, "separate"), "{rift::Orbit::from_mask(4), false}");
  EXPECT_EQ(upkeep_call(code, "sew"), "{rift::Orbit::from_mask(4), false}");
  EXPECT_EQ(upkeep_call(code, "unlink_corner"), "{rift::Orbit::from_mask(6), false}");
  const std::string tri = upkeep_call(code, "tri");
  EXPECT_EQ(tri.substr(tri.find(", ")), ", true}") << tri;
  EXPECT_EQ(upkeep_call(code, "remove"), "(no upkeep)");  // nothing on the right
}

}  // namespace

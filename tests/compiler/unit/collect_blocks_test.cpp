// How riftc lays out a criterion's collect(): a lambda per block of cells
// that takes the embeddings' arrays once and loops over its cells, and a
// per-cell interrupt poll only in bodies that walk orbits of unbounded size
// (the block polls before it starts: rift/generated/collect_cells.hpp).
#include <gtest/gtest.h>

#include <string>

#include "generated_text.hpp"

namespace {

const char* kPack = R"(pack blocks dimension 2;
embedding position : vec3 on <1,2>;
embedding f_dart : vec3 on <> = vec3(0.0, 0.0, 0.0);
embedding face_weight : real on <0,1> = 0.0;

rule mark {
  hook a;
  left  { a : <0,1>; }
  right { a : <0,1>; }
}

// Folds over <1> (two darts) and <0,2> (four): bounded.
criterion corner_sums on <0,2>(a) (threshold : real > 0 = 1.0) {
  measure norm(sum f_dart over <1>(a) + sum f_dart over <0,2>(a)) > threshold;
  apply mark at a;
}

// A vertex's star: any number of faces.
criterion star on <1,2>(v) (threshold : real > 0 = 1.0) {
  measure norm(sum f_dart over <1,2>(v)) > threshold;
  apply mark at v;
}

// A face's darts: any number of edges.
criterion face on <0,1>(f) (threshold : real > 0 = 1.0) {
  measure f.face_weight * norm(sum f_dart over <0,1>(f)) > threshold;
  apply mark at f;
}
)";

std::string generated_cpp() {
  return rift::compiler_test::generated_text("blocks.rules", kPack, "blocks.cpp");
}

TEST(CollectBlocks, ReadersAreTakenPerBlockAndTheCellsLoopedInside) {
  const std::string code = generated_cpp();
  for (const char* name : {"CornerSums", "Star", "Face"}) {
    const std::string collect =
        rift::compiler_test::function_text(code, std::string(name) + "Criterion::collect(");
    ASSERT_FALSE(collect.empty()) << name << ":\n" << code;
    const std::size_t block = collect.find("std::span<const rift::Dart> cells");
    // f_dart lives on <>: read by dart, without a slot array or a test per read.
    const std::size_t reader = collect.find("= e_f_dart.reader<rift::ReadBy::kDart>();");
    const std::size_t loop = collect.find(" : cells) {");
    const std::size_t body = collect.find("[&]() RIFT_CELL_BODY {");
    ASSERT_NE(block, std::string::npos) << name << ":\n" << collect;
    ASSERT_NE(reader, std::string::npos) << name << ":\n" << collect;
    ASSERT_NE(loop, std::string::npos) << name << ":\n" << collect;
    ASSERT_NE(body, std::string::npos) << name << ":\n" << collect;
    EXPECT_LT(block, reader) << name << ": the readers are the block's locals";
    EXPECT_LT(reader, loop) << name << ": taken once per block, not per cell";
    EXPECT_LT(loop, body) << name;
  }
}

TEST(CollectBlocks, OnlyBodiesWalkingUnboundedOrbitsPollPerCell) {
  const std::string code = generated_cpp();
  const auto polls = [&](const char* name) {
    const std::string collect =
        rift::compiler_test::function_text(code, std::string(name) + "Criterion::collect(");
    EXPECT_FALSE(collect.empty()) << name;
    return collect.find("rift::throw_if_interrupted();") != std::string::npos;
  };
  EXPECT_FALSE(polls("CornerSums"));
  EXPECT_TRUE(polls("Star"));
  EXPECT_TRUE(polls("Face"));
}

}  // namespace

// How riftc lays out a criterion's collect(): a lambda per block of cells
// that takes the embeddings' arrays once and loops over its cells, and a
// per-cell interrupt poll only in bodies that walk orbits of unbounded size
// (the block polls before it starts: rift/generated/collect_cells.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "driver/compile.hpp"

namespace {

namespace fs = std::filesystem;

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
  const fs::path dir =
      fs::temp_directory_path() / ("riftc_collect_blocks_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  rift::driver::Options options;
  options.out_dir = dir.string();
  options.line_directives = false;
  const auto r = rift::driver::compile_text("blocks.rules", kPack, options);
  EXPECT_EQ(r.exit_code, 0) << r.diagnostics;
  std::ifstream in(dir / "blocks.cpp");
  std::ostringstream s;
  s << in.rdbuf();
  in.close();
  fs::remove_all(dir);
  return s.str();
}

/// The text of a generated function, from its signature to the next one.
std::string function(const std::string& code, const std::string& signature) {
  const std::size_t start = code.find(signature);
  if (start == std::string::npos) return {};
  return code.substr(start, code.find("\n}\n", start) - start);
}

TEST(CollectBlocks, ReadersAreTakenPerBlockAndTheCellsLoopedInside) {
  const std::string code = generated_cpp();
  for (const char* name : {"CornerSums", "Star", "Face"}) {
    const std::string collect = function(code, std::string(name) + "Criterion::collect(");
    ASSERT_FALSE(collect.empty()) << name << ":\n" << code;
    const std::size_t block = collect.find("std::span<const rift::Dart> cells");
    const std::size_t reader = collect.find("= e_f_dart.reader();");
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
    const std::string collect = function(code, std::string(name) + "Criterion::collect(");
    EXPECT_FALSE(collect.empty()) << name;
    return collect.find("rift::throw_if_interrupted();") != std::string::npos;
  };
  EXPECT_FALSE(polls("CornerSums"));
  EXPECT_TRUE(polls("Star"));
  EXPECT_TRUE(polls("Face"));
}

}  // namespace

// The parser: the AST it builds for each construct, operator precedence, and
// error recovery that reports several syntax errors of one file.
#include <gtest/gtest.h>

#include <string>

#include "ast/decl.hpp"
#include "diag/diagnostics.hpp"
#include "parse/parse_file.hpp"

namespace {

using rift::ast::Expr;

struct Parsed {
  rift::ast::File file;
  std::string diagnostics;
  std::size_t errors = 0;
};

Parsed parse(const std::string& text) {
  rift::diag::SourceManager sources;
  rift::diag::Diagnostics diags(sources);
  const int id = sources.add("t.rules", text);
  Parsed p;
  rift::parse::parse_file(sources, id, diags, p.file);
  p.diagnostics = diags.render();
  p.errors = diags.error_count();
  return p;
}

TEST(Parser, SceneParametersTagsAndDocComments) {
  const Parsed p = parse(
      "/// A pack.\npack t dimension 2;\n"
      "// not a doc\n/// A spring,\n///   damped.\n"
      "interaction s on <0> tagged (k : real > 0 \"N/m\", c : real >= 0 = 0.1, n : int) {\n"
      "  pattern { a : <>; b : <>; a -0- b; }\n  init k(a) = k;\n}\n"
      "/// not above anything\n\ncriterion e on <0,2>(a) (limit : real = 1.0) {}\n");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  EXPECT_EQ(p.file.description, "A pack.");
  ASSERT_EQ(p.file.interactions.size(), 1u);
  const auto& i = p.file.interactions[0];
  EXPECT_EQ(i.description, "A spring, damped.");
  EXPECT_TRUE(i.tagged);
  ASSERT_EQ(i.params.size(), 3u);
  EXPECT_EQ(i.params[0].bound, rift::ast::Param::Bound::Positive);
  EXPECT_EQ(i.params[0].description, "N/m");
  EXPECT_EQ(i.params[0].default_value, nullptr);
  EXPECT_EQ(i.params[1].bound, rift::ast::Param::Bound::NonNegative);
  ASSERT_NE(i.params[1].default_value, nullptr);
  EXPECT_EQ(i.params[2].type, rift::ast::Type::Int);
  ASSERT_EQ(i.inits.size(), 1u);
  EXPECT_EQ(i.inits[0].dart.text, "a");
  ASSERT_EQ(p.file.criteria.size(), 1u);
  EXPECT_EQ(p.file.criteria[0].description, "");
  ASSERT_EQ(p.file.criteria[0].params.size(), 1u);
}

TEST(Parser, PackHeaderAndEmbedding) {
  const Parsed p =
      parse("pack cloth dimension 3;\nembedding v : vec3 on <1,2,3> = vec3(0,0,0) merge mean;");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  EXPECT_EQ(p.file.pack.text, "cloth");
  EXPECT_EQ(p.file.dimension, 3);
  ASSERT_EQ(p.file.embeddings.size(), 1u);
  const auto& e = p.file.embeddings[0];
  EXPECT_EQ(e.type, rift::ast::Type::Vec3);
  EXPECT_EQ(e.orbit.dims, (std::vector<int>{1, 2, 3}));
  ASSERT_TRUE(e.merge.has_value());
  EXPECT_EQ(e.merge->text, "mean");
  ASSERT_TRUE(e.default_value);
  EXPECT_EQ(e.default_value->kind, Expr::Kind::Call);
}

TEST(Parser, RuleWithPatternsArcsHooksAndStatements) {
  const Parsed p = parse(R"(pack t dimension 2;
rule tri(k : real) {
  hook n0;
  left  { n0 : <0,1>; }
  right { n0 : <0,_>; n1 : <_,2>; n2 : <1,2>; n0 -1- n1 -0- n2; n2.p = n0.p * k; }
  let x = 1;
  when x > 0;
  update n0.p = n0.p;
})");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  ASSERT_EQ(p.file.rules.size(), 1u);
  const auto& r = p.file.rules[0];
  ASSERT_EQ(r.params.size(), 1u);
  EXPECT_EQ(r.params[0].type, rift::ast::Type::Real);
  ASSERT_EQ(r.hooks.size(), 1u);
  EXPECT_EQ(r.left.nodes.size(), 1u);
  ASSERT_EQ(r.right.nodes.size(), 3u);
  EXPECT_EQ(r.right.nodes[1].label.dims, (std::vector<int>{-1, 2}));
  ASSERT_EQ(r.right.arcs.size(), 2u);  // the chain gives two arcs
  EXPECT_EQ(r.right.arcs[0].a.text, "n0");
  EXPECT_EQ(r.right.arcs[0].b.text, "n1");
  EXPECT_EQ(r.right.arcs[0].dim, 1);
  EXPECT_EQ(r.right.arcs[1].a.text, "n1");
  EXPECT_EQ(r.right.arcs[1].b.text, "n2");
  EXPECT_EQ(r.right.arcs[1].dim, 0);
  EXPECT_EQ(r.right.assigns.size(), 1u);
  EXPECT_EQ(r.lets.size(), 1u);
  EXPECT_EQ(r.whens.size(), 1u);
  EXPECT_EQ(r.updates.size(), 1u);
}

TEST(Parser, PrecedenceAndAssociativity) {
  const Parsed p = parse("pack t dimension 2;\nparam x : real = 1 + 2 * 3 - 4;");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  const Expr& e = *p.file.params[0].value;  // (1 + (2 * 3)) - 4
  ASSERT_EQ(e.kind, Expr::Kind::Binary);
  EXPECT_EQ(e.op, "-");
  const Expr& lhs = *e.args[0];
  EXPECT_EQ(lhs.op, "+");
  EXPECT_EQ(lhs.args[1]->op, "*");
}

TEST(Parser, ConditionalExtendsToTheRight) {
  const Parsed p = parse("pack t dimension 2;\nparam x : real = if a < b or c then 1 else 2 + 3;");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  const Expr& e = *p.file.params[0].value;
  ASSERT_EQ(e.kind, Expr::Kind::Cond);
  EXPECT_EQ(e.args[0]->op, "or");
  EXPECT_EQ(e.args[2]->op, "+");
}

TEST(Parser, ReadsCollectionsAndIndexing) {
  const Parsed p = parse(
      "pack t dimension 2;\ninit m(a) = sum f over <1,2>(a@0@1) + a@2.p[1] + m3[0, 2] + max(1, "
      "2);");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  const Expr& e = *p.file.inits[0].value;
  const Expr& collect = *e.args[0]->args[0]->args[0];
  ASSERT_EQ(collect.kind, Expr::Kind::Collect);
  EXPECT_EQ(collect.op, "sum");
  EXPECT_EQ(collect.node, "a");
  EXPECT_EQ(collect.hops, (std::vector<int>{0, 1}));
  EXPECT_EQ(collect.orbit.dims, (std::vector<int>{1, 2}));
  const Expr& index = *e.args[0]->args[0]->args[1];
  ASSERT_EQ(index.kind, Expr::Kind::Index);
  EXPECT_EQ(index.args[0]->kind, Expr::Kind::Read);
  EXPECT_EQ(index.args[0]->hops, (std::vector<int>{2}));
  EXPECT_EQ(e.args[0]->args[1]->args.size(), 3u);  // m3[0, 2]
  EXPECT_EQ(e.args[1]->kind, Expr::Kind::Call);
}

TEST(Parser, InteractionAndCriterion) {
  const Parsed p = parse(R"(pack t dimension 2;
interaction s on <0> { pattern { a : <>; b : <>; a -0- b; } force a.f = b.p; energy 1.0; }
criterion c on <0,2>(d) { let m = 1.0; measure m > 2.0; apply r at d with k = 1.0, q = 2; }
)");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  ASSERT_EQ(p.file.interactions.size(), 1u);
  EXPECT_EQ(p.file.interactions[0].pattern.arcs.size(), 1u);
  EXPECT_EQ(p.file.interactions[0].forces.size(), 1u);
  EXPECT_TRUE(p.file.interactions[0].energy);
  ASSERT_EQ(p.file.criteria.size(), 1u);
  const auto& c = p.file.criteria[0];
  EXPECT_EQ(c.dart.text, "d");
  EXPECT_EQ(c.rule.text, "r");
  EXPECT_EQ(c.apply_args.size(), 2u);
  EXPECT_EQ(c.measure->op, ">");
}

TEST(Parser, RecoversToReportSeveralErrors) {
  const Parsed p = parse(R"(pack t dimension 2;
embedding a : vec3 on <1,2>
embedding b : on <0>;
rule r { left { x : <0,1> } right { x : <0,1>; } }
param k : real = 1 +;
rule ok { left { y : <0>; } right { y : <0>; } }
)");
  // Recovery from the missing ';' skips to the next ';', so the bad
  // embedding on line 3 is swallowed by the first error: three reports.
  EXPECT_EQ(p.errors, 3u) << p.diagnostics;
  EXPECT_NE(p.diagnostics.find("t.rules:4:27: error:"), std::string::npos) << p.diagnostics;
  EXPECT_NE(p.diagnostics.find("t.rules:5:21: error:"), std::string::npos) << p.diagnostics;
  // What follows the errors is still parsed.
  ASSERT_FALSE(p.file.rules.empty());
  EXPECT_EQ(p.file.rules.back().name.text, "ok");
}

TEST(Parser, LocationsPointAtTheToken) {
  const Parsed p = parse("pack t dimension 2;\nrule r {\n  left { a : <0,1>; }\n}");
  ASSERT_EQ(p.errors, 0u) << p.diagnostics;
  const auto& n = p.file.rules[0].left.nodes[0];
  EXPECT_EQ(n.name.loc.begin.line, 3);
  EXPECT_EQ(n.name.loc.begin.column, 10);
  EXPECT_EQ(n.label.loc.begin.column, 14);
  EXPECT_EQ(n.label.loc.end.column, 19);
}

}  // namespace

// The lexer: tokens, values, line/column tracking (columns count characters,
// not bytes), and located errors for bad input.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "diag/diagnostics.hpp"
#include "parse/lexer.hpp"

namespace {

using rift::grammar::Lexer;
using rift::grammar::Parser;
using Kind = Parser::symbol_kind_type;

/// A token copied out of the parser's symbol (symbols hold move-only values).
struct Token {
  Kind kind;
  rift::diag::Location location;
  std::string text;
  std::int64_t integer = 0;
  double real = 0.0;
};

struct Lexed {
  std::vector<Token> tokens;
  std::string diagnostics;
};

Lexed lex(const std::string& text) {
  rift::diag::SourceManager sources;
  rift::diag::Diagnostics diags(sources);
  const int id = sources.add("t.rules", text);
  Lexer lexer(sources.file(id).text, id, diags);
  Lexed out;
  for (int guard = 0; guard < 1000; ++guard) {
    Parser::symbol_type sym = lexer.next();
    Token t{sym.kind(), sym.location, {}, 0, 0.0};
    if (t.kind == Parser::symbol_kind::S_IDENT) t.text = sym.value.as<std::string>();
    if (t.kind == Parser::symbol_kind::S_INT) t.integer = sym.value.as<std::int64_t>();
    if (t.kind == Parser::symbol_kind::S_REAL) t.real = sym.value.as<double>();
    out.tokens.push_back(t);
    if (t.kind == Parser::symbol_kind::S_YYEOF) break;
  }
  out.diagnostics = diags.render();
  return out;
}

std::vector<Kind> kinds(const Lexed& l) {
  std::vector<Kind> k;
  for (const auto& t : l.tokens)
    k.push_back(t.kind);
  return k;
}

TEST(Lexer, LinkFollowingReadsAsLinkThenEmbedding) {
  const Lexed l = lex("a@0.position");
  using S = Parser::symbol_kind;
  EXPECT_EQ(kinds(l), (std::vector<Kind>{S::S_IDENT, S::S_AT_SIGN, S::S_INT, S::S_DOT, S::S_IDENT,
                                         S::S_YYEOF}));
  EXPECT_EQ(l.tokens[2].integer, 0);
  EXPECT_EQ(l.tokens[4].text, "position");
}

TEST(Lexer, RealLiterals) {
  const Lexed l = lex("1.5 .25 1e-3 3.0e2 7");
  using S = Parser::symbol_kind;
  ASSERT_EQ(kinds(l),
            (std::vector<Kind>{S::S_REAL, S::S_REAL, S::S_REAL, S::S_REAL, S::S_INT, S::S_YYEOF}));
  EXPECT_DOUBLE_EQ(l.tokens[0].real, 1.5);
  EXPECT_DOUBLE_EQ(l.tokens[1].real, 0.25);
  EXPECT_DOUBLE_EQ(l.tokens[2].real, 1e-3);
  EXPECT_DOUBLE_EQ(l.tokens[3].real, 300.0);
}

TEST(Lexer, KeywordsAreWholeWords) {
  const Lexed l = lex("rule rules _ _x <> <= -2-");
  using S = Parser::symbol_kind;
  EXPECT_EQ(kinds(l),
            (std::vector<Kind>{S::S_RULE, S::S_IDENT, S::S_UNDERSCORE, S::S_IDENT, S::S_LT, S::S_GT,
                               S::S_LE, S::S_MINUS, S::S_INT, S::S_MINUS, S::S_YYEOF}));
}

TEST(Lexer, TracksLinesAndColumnsInCharacters) {
  // "é" is two bytes but one column; the comment spans a line break.
  const Lexed l = lex("// é\n  /* ∑\n */ pack");
  ASSERT_EQ(l.tokens.size(), 2u);
  const rift::diag::Location loc = l.tokens[0].location;
  EXPECT_EQ(loc.begin.line, 3);
  EXPECT_EQ(loc.begin.column, 5);
  EXPECT_EQ(loc.end.column, 9);
  EXPECT_TRUE(l.diagnostics.empty());
}

TEST(Lexer, UnexpectedCharacterIsLocatedAndRecoverable) {
  const Lexed l = lex("a\n  é b");
  using S = Parser::symbol_kind;
  EXPECT_EQ(kinds(l), (std::vector<Kind>{S::S_IDENT, S::S_YYerror, S::S_IDENT, S::S_YYEOF}));
  EXPECT_EQ(l.diagnostics, "t.rules:2:3: error: unexpected character 'é'\n  é b\n  ^\n");
}

TEST(Lexer, NulByteInsideTheFileIsNotTheEnd) {
  const Lexed l = lex(std::string("a\0b", 3));
  using S = Parser::symbol_kind;
  EXPECT_EQ(kinds(l), (std::vector<Kind>{S::S_IDENT, S::S_YYerror, S::S_IDENT, S::S_YYEOF}));
  EXPECT_NE(l.diagnostics.find("unexpected byte 0x00"), std::string::npos);
}

TEST(Lexer, UnterminatedCommentEndsTheFileWithAnError) {
  const Lexed l = lex("pack /* never closed");
  ASSERT_EQ(l.tokens.size(), 2u);
  EXPECT_EQ(l.tokens[1].kind, Parser::symbol_kind::S_YYEOF);
  EXPECT_NE(l.diagnostics.find("t.rules:1:6: error: unterminated comment"), std::string::npos);
}

}  // namespace

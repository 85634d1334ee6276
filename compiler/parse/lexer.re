// re2c lexer of the rule language. The buffer is a std::string: its terminating
// NUL is the sentinel, and YYLIMIT tells a real end from a NUL byte inside the
// file (reported as an unexpected character, never read past).
#include "parse/lexer.hpp"

#include <cerrno>
#include <cstdlib>

namespace rift::grammar {

namespace {

bool is_continuation(unsigned char c) { return (c & 0xC0u) == 0x80u; }

}  // namespace

Lexer::Lexer(const std::string& text, int file_id, diag::Diagnostics& diags)
    : cursor_(text.c_str()),
      limit_(text.c_str() + text.size()),
      file_id_(file_id),
      diags_(diags) {}

void Lexer::advance() {
  for (const char* p = token_; p < cursor_; ++p) {
    const auto c = static_cast<unsigned char>(*p);
    if (c == '\n') {
      ++pos_.line;
      pos_.column = 1;
    } else if (!is_continuation(c)) {
      ++pos_.column;
    }
  }
}

diag::Location Lexer::token_location() const { return diag::Location{file_id_, token_pos_, pos_}; }

Parser::symbol_type Lexer::lex_error(const std::string& message) {
  diags_.error(token_location(), message);
  // YYerror makes the parser recover without printing a second message.
  return Parser::make_YYerror(token_location());
}

void Lexer::doc_line() {
  std::string text(token_ + 3, cursor_);
  const std::size_t first = text.find_first_not_of(" \t");
  const std::size_t last = text.find_last_not_of(" \t\r");
  text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  if (doc_line_ != token_pos_.line - 1) doc_.clear();
  if (!doc_.empty() && !text.empty()) doc_ += ' ';
  doc_ += text;
  doc_line_ = token_pos_.line;
}

std::string Lexer::doc_before(int line) const { return doc_line_ == line - 1 ? doc_ : std::string(); }

Parser::symbol_type Lexer::scan_block_comment() {
  // token_ .. cursor_ holds "/*"; the comment ends at the first "*/".
  for (const char* p = cursor_; p + 1 < limit_; ++p) {
    if (p[0] == '*' && p[1] == '/') {
      cursor_ = p + 2;
      advance();
      return next();
    }
  }
  // Point at the opening "/*", then skip to the end.
  const diag::Location open = token_location();
  cursor_ = limit_;
  advance();
  diags_.error(diag::Location{file_id_, open.begin, open.end}, "unterminated comment");
  return Parser::make_END(token_location());
}

Parser::symbol_type Lexer::next() {
  for (;;) {
    token_ = cursor_;
    token_pos_ = pos_;
    const char* YYCURSOR = cursor_;
    const char* YYMARKER = marker_;
    const char* const YYLIMIT = limit_;
#define RIFT_TOKEN() (cursor_ = YYCURSOR, marker_ = YYMARKER, advance(), token_location())

    /*!re2c
      re2c:api:style = free-form;
      re2c:define:YYCTYPE = "unsigned char";
      re2c:define:YYCURSOR = YYCURSOR;
      re2c:define:YYMARKER = YYMARKER;
      re2c:define:YYLIMIT = YYLIMIT;
      re2c:yyfill:enable = 0;
      re2c:eof = 0;
      re2c:flags:utf-8 = 0;

      digit = [0-9];
      exp = [eE] [+-]? digit+;
      ident = [A-Za-z_] [A-Za-z0-9_]*;

      $ { RIFT_TOKEN(); return Parser::make_END(token_location()); }

      [ \t\r\n]+ { RIFT_TOKEN(); continue; }
      "///" [^\n\x00]* { RIFT_TOKEN(); doc_line(); continue; }
      "//" [^\n\x00]* { RIFT_TOKEN(); continue; }
      "/*" { RIFT_TOKEN(); return scan_block_comment(); }

      "pack"        { return Parser::make_PACK(RIFT_TOKEN()); }
      "dimension"   { return Parser::make_DIMENSION(RIFT_TOKEN()); }
      "include"     { return Parser::make_INCLUDE(RIFT_TOKEN()); }
      "import"      { return Parser::make_IMPORT(RIFT_TOKEN()); }
      "embedding"   { return Parser::make_EMBEDDING(RIFT_TOKEN()); }
      "on"          { return Parser::make_ON(RIFT_TOKEN()); }
      "merge"       { return Parser::make_MERGE(RIFT_TOKEN()); }
      "param"       { return Parser::make_PARAM(RIFT_TOKEN()); }
      "init"        { return Parser::make_INIT(RIFT_TOKEN()); }
      "rule"        { return Parser::make_RULE(RIFT_TOKEN()); }
      "hook"        { return Parser::make_HOOK(RIFT_TOKEN()); }
      "left"        { return Parser::make_LEFT(RIFT_TOKEN()); }
      "right"       { return Parser::make_RIGHT(RIFT_TOKEN()); }
      "when"        { return Parser::make_WHEN(RIFT_TOKEN()); }
      "let"         { return Parser::make_LET(RIFT_TOKEN()); }
      "update"      { return Parser::make_UPDATE(RIFT_TOKEN()); }
      "interaction" { return Parser::make_INTERACTION(RIFT_TOKEN()); }
      "pattern"     { return Parser::make_PATTERN(RIFT_TOKEN()); }
      "tagged"      { return Parser::make_TAGGED(RIFT_TOKEN()); }
      "force"       { return Parser::make_FORCE(RIFT_TOKEN()); }
      "energy"      { return Parser::make_ENERGY(RIFT_TOKEN()); }
      "semidefinite" { return Parser::make_SEMIDEFINITE(RIFT_TOKEN()); }
      "jacobian"    { return Parser::make_JACOBIAN(RIFT_TOKEN()); }
      "criterion"   { return Parser::make_CRITERION(RIFT_TOKEN()); }
      "measure"     { return Parser::make_MEASURE(RIFT_TOKEN()); }
      "apply"       { return Parser::make_APPLY(RIFT_TOKEN()); }
      "at"          { return Parser::make_AT(RIFT_TOKEN()); }
      "with"        { return Parser::make_WITH(RIFT_TOKEN()); }
      "script"      { return Parser::make_SCRIPT(RIFT_TOKEN()); }
      "set"         { return Parser::make_SET(RIFT_TOKEN()); }
      "for"         { return Parser::make_FOR(RIFT_TOKEN()); }
      "each"        { return Parser::make_EACH(RIFT_TOKEN()); }
      "in"          { return Parser::make_IN(RIFT_TOKEN()); }
      "of"          { return Parser::make_OF(RIFT_TOKEN()); }
      "where"       { return Parser::make_WHERE(RIFT_TOKEN()); }
      // functions (docs/language.md, "Functions")
      "def"         { return Parser::make_DEF(RIFT_TOKEN()); }
      "return"      { return Parser::make_RETURN(RIFT_TOKEN()); }
      "->" { return Parser::make_ARROW(RIFT_TOKEN()); }
      "if"          { return Parser::make_IF(RIFT_TOKEN()); }
      "then"        { return Parser::make_THEN(RIFT_TOKEN()); }
      "else"        { return Parser::make_ELSE(RIFT_TOKEN()); }
      "true"        { return Parser::make_TRUE(RIFT_TOKEN()); }
      "false"       { return Parser::make_FALSE(RIFT_TOKEN()); }
      "over"        { return Parser::make_OVER(RIFT_TOKEN()); }
      "sum"         { return Parser::make_SUM(RIFT_TOKEN()); }
      "mean"        { return Parser::make_MEAN(RIFT_TOKEN()); }
      "count"       { return Parser::make_COUNT(RIFT_TOKEN()); }
      "min"         { return Parser::make_MIN(RIFT_TOKEN()); }
      "max"         { return Parser::make_MAX(RIFT_TOKEN()); }
      "real"        { return Parser::make_T_REAL(RIFT_TOKEN()); }
      "int"         { return Parser::make_T_INT(RIFT_TOKEN()); }
      "bool"        { return Parser::make_T_BOOL(RIFT_TOKEN()); }
      "vec3"        { return Parser::make_T_VEC3(RIFT_TOKEN()); }
      "mat3"        { return Parser::make_T_MAT3(RIFT_TOKEN()); }
      "and" | "&&"  { return Parser::make_AND(RIFT_TOKEN()); }
      "or" | "||"   { return Parser::make_OR(RIFT_TOKEN()); }
      "not" | "!"   { return Parser::make_NOT(RIFT_TOKEN()); }

      "_" { return Parser::make_UNDERSCORE(RIFT_TOKEN()); }
      ident {
        const diag::Location loc = RIFT_TOKEN();
        return Parser::make_IDENT(std::string(token_, cursor_), loc);
      }

      digit+ {
        const diag::Location loc = RIFT_TOKEN();
        errno = 0;
        const long long value = std::strtoll(std::string(token_, cursor_).c_str(), nullptr, 10);
        if (errno == ERANGE) {
          diags_.error(loc, "integer literal is too large");
          return Parser::make_INT(0, loc);
        }
        return Parser::make_INT(value, loc);
      }
      // "2." is not a real: `a@0.position` must lex as a@ 0 . position.
      digit+ "." digit+ exp? | "." digit+ exp? | digit+ exp {
        const diag::Location loc = RIFT_TOKEN();
        const double value = std::strtod(std::string(token_, cursor_).c_str(), nullptr);
        return Parser::make_REAL(value, loc);
      }

      ["] [^"\n\x00]* ["] {
        const diag::Location loc = RIFT_TOKEN();
        return Parser::make_STRING(std::string(token_ + 1, cursor_ - 1), loc);
      }
      ["] [^"\n\x00]* {
        RIFT_TOKEN();
        return lex_error("unterminated string");
      }

      ";"  { return Parser::make_SEMI(RIFT_TOKEN()); }
      ":"  { return Parser::make_COLON(RIFT_TOKEN()); }
      ","  { return Parser::make_COMMA(RIFT_TOKEN()); }
      "."  { return Parser::make_DOT(RIFT_TOKEN()); }
      "@"  { return Parser::make_AT_SIGN(RIFT_TOKEN()); }
      "="  { return Parser::make_ASSIGN(RIFT_TOKEN()); }
      "{"  { return Parser::make_LBRACE(RIFT_TOKEN()); }
      "}"  { return Parser::make_RBRACE(RIFT_TOKEN()); }
      "("  { return Parser::make_LPAREN(RIFT_TOKEN()); }
      ")"  { return Parser::make_RPAREN(RIFT_TOKEN()); }
      "["  { return Parser::make_LBRACKET(RIFT_TOKEN()); }
      "]"  { return Parser::make_RBRACKET(RIFT_TOKEN()); }
      "<=" { return Parser::make_LE(RIFT_TOKEN()); }
      ">=" { return Parser::make_GE(RIFT_TOKEN()); }
      "==" { return Parser::make_EQ(RIFT_TOKEN()); }
      "!=" { return Parser::make_NE(RIFT_TOKEN()); }
      "<"  { return Parser::make_LT(RIFT_TOKEN()); }
      ">"  { return Parser::make_GT(RIFT_TOKEN()); }
      "+=" { return Parser::make_PLUS_ASSIGN(RIFT_TOKEN()); }
      "+"  { return Parser::make_PLUS(RIFT_TOKEN()); }
      "-"  { return Parser::make_MINUS(RIFT_TOKEN()); }
      "*"  { return Parser::make_STAR(RIFT_TOKEN()); }
      "/"  { return Parser::make_SLASH(RIFT_TOKEN()); }

      // A whole UTF-8 sequence is reported as one character.
      [\xC2-\xF4] [\x80-\xBF]* {
        RIFT_TOKEN();
        return lex_error("unexpected character '" + std::string(token_, cursor_) + "'");
      }
      * {
        RIFT_TOKEN();
        const auto c = static_cast<unsigned char>(*token_);
        if (c >= 0x21 && c < 0x7F) return lex_error(std::string("unexpected character '") + char(c) + "'");
        static const char* hex = "0123456789ABCDEF";
        return lex_error(std::string("unexpected byte 0x") + hex[c >> 4] + hex[c & 15]);
      }
    */
#undef RIFT_TOKEN
  }
}

}  // namespace rift::grammar

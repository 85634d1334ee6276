// The shared token reader: line tracking, comments, and conversions that fail
// with a MeshError naming the line rather than with a std exception.
#include "rift/io/text_cursor.hpp"

#include <gtest/gtest.h>

namespace rift::io {
namespace {

TEST(TextCursor, TokensCarryTheirLines) {
  TextCursor in("f", "a b\n\n  c # d e\r\nf", 1, '#');
  EXPECT_EQ(in.next().text, "a");
  const Token b = in.next();
  EXPECT_EQ(b.text, "b");
  EXPECT_EQ(b.line, 1);
  const Token c = in.next();
  EXPECT_EQ(c.text, "c");
  EXPECT_EQ(c.line, 3);
  EXPECT_TRUE(in.next_on_line().empty());  // the comment ends line 3
  const Token f = in.next();
  EXPECT_EQ(f.text, "f");
  EXPECT_EQ(f.line, 4);
  EXPECT_TRUE(in.at_end());
  const Token end = in.next();
  EXPECT_TRUE(end.empty());
  EXPECT_EQ(end.line, 4);  // the end of the input is reported at the last token
}

TEST(TextCursor, FirstLineOffsetsEveryLine) {
  TextCursor in("f", "\n\n7", 40);
  EXPECT_EQ(in.next().line, 42);
}

TEST(TextCursor, PeekDoesNotConsume) {
  TextCursor in("f", "x\ny");
  EXPECT_EQ(in.peek().text, "x");
  EXPECT_EQ(in.next().text, "x");
  EXPECT_EQ(in.line(), 1);
  EXPECT_EQ(in.peek().line, 2);
  EXPECT_EQ(in.line(), 1);
}

TEST(TextCursor, TakeLineKeepsEmptyLines) {
  TextCursor in("f", "first line \r\n\nthird");
  EXPECT_EQ(in.take_line().text, "first line");
  EXPECT_EQ(in.take_line().text, "");
  const Token third = in.take_line();
  EXPECT_EQ(third.text, "third");
  EXPECT_EQ(third.line, 3);
  EXPECT_TRUE(in.take_line().empty());
}

TEST(TextCursor, Numbers) {
  TextCursor in("f", "");
  EXPECT_EQ(in.to_real({"+1.5e2", 1}, "x"), 150.0);
  EXPECT_EQ(in.to_real({"-0.25", 1}, "x"), -0.25);
  EXPECT_EQ(in.to_integer({"-12", 1}, "i"), -12);
  EXPECT_EQ(in.to_integer({"+7", 1}, "i"), 7);
  EXPECT_EQ(in.to_count({"2147483647", 1}, "n"), 2147483647u);
}

void expect_error(const std::function<void()>& f, const std::string& text) {
  try {
    f();
    ADD_FAILURE() << "no error, expected " << text;
  } catch (const MeshError& e) {
    EXPECT_EQ(std::string(e.what()), text);
  }
}

TEST(TextCursor, BadNumbersAreMeshErrorsAtTheirLine) {
  TextCursor in("m.txt", "");
  expect_error(
      [&] {
        in.to_real({"nan", 3}, "x");
      },
      "m.txt:3: error: x 'nan' is not a finite number");
  expect_error([&] { in.to_real({"1e400", 4}, "x"); }, "m.txt:4: error: x '1e400' is out of range");
  expect_error(
      [&] {
        in.to_real({"1,5", 5}, "x");
      },
      "m.txt:5: error: expected x (a number), found '1,5'");
  expect_error(
      [&] {
        in.to_real({"+", 5}, "x");
      },
      "m.txt:5: error: expected x (a number), found '+'");
  expect_error(
      [&] {
        in.to_integer({"1.0", 6}, "n");
      },
      "m.txt:6: error: expected n (an integer), found '1.0'");
  expect_error(
      [&] {
        in.to_integer({"99999999999999999999", 7}, "n");
      },
      "m.txt:7: error: n '99999999999999999999' is out of range");
  expect_error([&] { in.to_count({"-1", 8}, "n"); }, "m.txt:8: error: n is negative ('-1')");
  expect_error(
      [&] {
        in.to_count({"4294967296", 9}, "n");
      },
      "m.txt:9: error: n '4294967296' is too large");
}

TEST(TextCursor, ExpectAtTheEnd) {
  TextCursor in("m.txt", "1\n2\n");
  in.next();
  in.next();
  expect_error([&] { in.expect("a third value"); },
               "m.txt:2: error: unexpected end of file, expected a third value");
}

TEST(TextCursor, QuotedShortensAndHidesControlCharacters) {
  EXPECT_EQ(quote_text("ab\x01"), "'ab?'");
  EXPECT_EQ(quote_text(std::string(50, 'x')), "'" + std::string(40, 'x') + "...'");
}

}  // namespace
}  // namespace rift::io

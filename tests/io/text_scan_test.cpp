// The internal tokenizer shared by the text readers.

#include "io/text_scan.h"

#include <gtest/gtest.h>

#include <limits>

namespace subdiv::detail {

TEST(LineScanner, IntegersAtTheLimitsAndBeyond) {
  long long v = 0;
  EXPECT_TRUE(LineScanner("9223372036854775807").integer(v));
  EXPECT_EQ(v, std::numeric_limits<long long>::max());
  EXPECT_TRUE(LineScanner("-9223372036854775808").integer(v));
  EXPECT_EQ(v, std::numeric_limits<long long>::min());
  EXPECT_FALSE(LineScanner("9223372036854775808").integer(v));
  EXPECT_FALSE(LineScanner("-9223372036854775809").integer(v));
  EXPECT_FALSE(LineScanner("99999999999999999999").integer(v));
  EXPECT_TRUE(LineScanner("  +42 ").integer(v));
  EXPECT_EQ(v, 42);
  EXPECT_FALSE(LineScanner("-").integer(v));
  EXPECT_FALSE(LineScanner("12a").integer(v));
  EXPECT_FALSE(LineScanner("1.5").integer(v));
}

TEST(LineScanner, IntegerStopsAtTheGivenSeparator) {
  LineScanner s("12/-3//7 8");
  long long a = 0, b = 0, c = 0, d = 0;
  ASSERT_TRUE(s.integer(a, '/'));
  ASSERT_TRUE(s.consume('/'));
  ASSERT_TRUE(s.integer(b, '/'));
  ASSERT_TRUE(s.consume('/'));
  ASSERT_TRUE(s.consume('/'));
  ASSERT_TRUE(s.integer(c));
  ASSERT_TRUE(s.integer(d));
  EXPECT_EQ(a, 12);
  EXPECT_EQ(b, -3);
  EXPECT_EQ(c, 7);
  EXPECT_EQ(d, 8);
  EXPECT_TRUE(s.at_end());
  EXPECT_FALSE(LineScanner("12/3").integer(a));  // '/' only where allowed
}

TEST(LineScanner, NumbersAndTokens) {
  LineScanner s("1.5 -2e-3 +7 nan x\r");
  double a, b, c, d, e;
  ASSERT_TRUE(s.number(a));
  ASSERT_TRUE(s.number(b));
  ASSERT_TRUE(s.number(c));
  ASSERT_TRUE(s.number(d));
  EXPECT_EQ(a, 1.5);
  EXPECT_EQ(b, -2e-3);
  EXPECT_EQ(c, 7.0);
  EXPECT_TRUE(d != d);
  EXPECT_FALSE(s.number(e));
  EXPECT_EQ(s.token(), "x");
  EXPECT_TRUE(s.at_end());
  EXPECT_FALSE(LineScanner("1.5.2").number(a));
}

TEST(LineReader, CountsLinesAndKeepsTheLastWithoutNewline) {
  LineReader r("a\n\nb\r\nc");
  std::string_view line;
  std::vector<std::string_view> lines;
  while (r.next(line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[2], "b\r");
  EXPECT_EQ(lines[3], "c");
  EXPECT_EQ(r.line_number(), 4u);
}

TEST(Printable, ShortensAndMasks) {
  EXPECT_EQ(printable("ok"), "ok");
  EXPECT_EQ(printable(std::string_view("a\0b\xff", 4)), "a?b?");
  EXPECT_EQ(printable(std::string(50, 'x')), std::string(40, 'x') + "...");
}

}  // namespace subdiv::detail

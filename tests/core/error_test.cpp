#include "subdiv/core/error.h"

#include <gtest/gtest.h>

namespace subdiv {

TEST(ParseError, NamesFileAndLine) {
  const ParseError e("mesh.obj", 12, "bad x coordinate 'abc'");
  EXPECT_STREQ(e.what(), "mesh.obj:12: bad x coordinate 'abc'");
  EXPECT_EQ(e.path(), "mesh.obj");
  EXPECT_EQ(e.line(), 12u);
}

TEST(ParseError, OmitsUnknownLine) {
  EXPECT_STREQ(ParseError("mesh.ply", 0, "truncated").what(), "mesh.ply: truncated");
  EXPECT_STREQ(ParseError("", 3, "x").what(), "<input>:3: x");
}

TEST(ParseError, IsAnIoErrorAndAnError) {
  try {
    throw ParseError("a", 1, "b");
  } catch (const IoError& e) {
    SUCCEED();
    return;
  }
  FAIL() << "ParseError must derive from IoError";
}

}  // namespace subdiv

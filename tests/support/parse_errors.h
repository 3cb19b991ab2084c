#pragma once
// Checking that a reader throws ParseError with a given message fragment.

#include <gtest/gtest.h>

#include <string>

#include "subdiv/core/error.h"

namespace subdiv::test {

/// The ParseError message `f` throws, or a text saying it threw something
/// else or nothing.
template <typename F>
std::string parse_error_message(F&& f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("WRONG EXCEPTION TYPE: ") + e.what();
  }
  return "NO EXCEPTION";
}

}  // namespace subdiv::test

#define EXPECT_PARSE_ERROR(expr, fragment)                                                          \
  do {                                                                                              \
    const std::string message_ = ::subdiv::test::parse_error_message([&] { (void)(expr); });        \
    EXPECT_NE(message_.find(fragment), std::string::npos) << "message: " << message_;               \
  } while (false)

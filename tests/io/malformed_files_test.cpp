// Malformed files fail fast with a ParseError naming the problem, without
// allocating in proportion to what a lying header claims.

#include <gtest/gtest.h>

#include <chrono>

#include "subdiv/core/error.h"
#include "subdiv/io/mesh_io.h"
#include "support/test_meshes.h"

namespace subdiv {
namespace {

std::string error_reading(const std::string& name) {
  try {
    read_mesh(test::data_path(name));
  } catch (const ParseError& e) {
    return e.what();
  }
  return "<no error>";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(MalformedFiles, ZeroIndex) {
  EXPECT_TRUE(contains(error_reading("zero_index.obj"), "zero_index.obj:4: vertex index 0 is invalid"));
}

TEST(MalformedFiles, IndexOutOfRange) {
  EXPECT_TRUE(contains(error_reading("index_out_of_range.obj"),
                       "index_out_of_range.obj:5: face 1 refers to vertex 9 but the file has 3 vertices"));
  const std::string off = error_reading("index_out_of_range.off");
  EXPECT_TRUE(contains(off, "index_out_of_range.off:6")) << off;
  EXPECT_TRUE(contains(off, "7")) << off;
}

TEST(MalformedFiles, Truncated) {
  EXPECT_TRUE(contains(error_reading("truncated_vertex.obj"), "truncated_vertex.obj:3: missing z coordinate"));
}

TEST(MalformedFiles, Garbage) {
  EXPECT_TRUE(contains(error_reading("garbage.obj"), "garbage.obj:3: unreadable line"));
}

TEST(MalformedFiles, LyingPlyHeaderFailsFastWithoutAllocating) {
  const auto start = std::chrono::steady_clock::now();
  const std::string e = error_reading("lying_header.ply");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(contains(e, "4000000000")) << e;
  EXPECT_LT(seconds, 1.0);
}

TEST(MalformedFiles, LyingStlCountFailsFastWithoutAllocating) {
  const auto start = std::chrono::steady_clock::now();
  const std::string e = error_reading("lying_count.stl");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(contains(e, "lying_count.stl:1: not an STL file")) << e;
  EXPECT_TRUE(contains(e, "4000000000")) << e;
  EXPECT_LT(seconds, 1.0);
}

TEST(MalformedFiles, StlFacetWithFourVertices) {
  const std::string e = error_reading("facet_four_vertices.stl");
  EXPECT_TRUE(contains(e, "facet_four_vertices.stl:7: facet at line 2 has more than three vertices")) << e;
}

}  // namespace
}  // namespace subdiv

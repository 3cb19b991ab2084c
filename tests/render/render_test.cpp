// Pictures of surfaces: the image has the asked size, the surface lands
// inside its projected bounding box and the background is everywhere else,
// different surfaces give different pictures, and the same input gives the
// same bytes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "camera.h"
#include "png.h"
#include "rasterizer.h"
#include "render_scene.h"
#include "subdiv/core/error.h"
#include "subdiv/mesh/triangulate.h"
#include "subdiv/refine/refine.h"
#include "subdiv/rules/scheme.h"

namespace subdiv::render {
namespace {

PolygonMesh unit_cube() {
  PolygonMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : std::vector<std::vector<Index>>{
           {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}})
    m.add_face(f);
  return m;
}

bool is_background(const Image& image, int x, int y, const Rgb& bg) {
  const std::uint8_t* p = &image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3];
  const auto channel = [](float c) { return static_cast<int>(c * 255.0F + 0.5F); };
  return p[0] == channel(bg.r) && p[1] == channel(bg.g) && p[2] == channel(bg.b);
}

std::pair<int, int> png_size(const std::string& png) {
  EXPECT_GE(png.size(), 24U);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  return {static_cast<int>(be32(16)), static_cast<int>(be32(20))};
}

TEST(Render, PngHasTheRequestedSize) {
  RenderStyle style;
  style.width = 320;
  style.height = 200;
  const Image image = rasterize(surface_scene(unit_cube(), {}, {}), style);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 200);
  EXPECT_EQ(png_size(encode_png(image)), std::make_pair(320, 200));
}

TEST(Render, SurfaceInsideItsProjectedBoundsAndBackgroundElsewhere) {
  const PolygonMesh cube = unit_cube();
  for (const ViewDirection view : {ViewDirection{30, 20}, ViewDirection{-120, 60}, ViewDirection{0, 90}}) {
    RenderStyle style;
    style.width = 300;
    style.height = 240;
    style.view = view;
    style.background = {0.0F, 0.0F, 0.0F};
    const Scene scene = surface_scene(cube, {}, {});
    const Image image = rasterize(scene, style);
    const Camera camera = frame_sphere(scene.centre, scene.radius, view, style.width, style.height);
    double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
    for (const Vec3& p : cube.positions) {
      const auto [x, y] = project(camera, p, style.width, style.height);
      left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
    }
    ASSERT_GT(left, 0.0);
    ASSERT_LT(right, style.width);
    int inside = 0, surface_inside = 0, surface_outside = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        // A pixel's centre is at +0.5; a one-pixel margin for the smoothing.
        const bool in = x + 0.5 >= left - 1.0 && x + 0.5 <= right + 1.0 && y + 0.5 >= top - 1.0 && y + 0.5 <= bottom + 1.0;
        const bool drawn = !is_background(image, x, y, style.background);
        inside += in;
        surface_inside += in && drawn;
        surface_outside += !in && drawn;
      }
    EXPECT_EQ(surface_outside, 0) << "view " << view.azimuth << "," << view.elevation;
    // A convex box covers well over half of its projected bounding box.
    EXPECT_GT(surface_inside, inside / 2) << "view " << view.azimuth << "," << view.elevation;
  }
}

TEST(Render, TwoSchemesGiveDifferentPictures) {
  RefineOptions options;
  options.levels = 3;
  const PolygonMesh triangles = triangulate(unit_cube());
  const PolygonMesh cc = refine(triangles, *find_scheme("catmull-clark"), options);
  const PolygonMesh loop = refine(triangles, *find_scheme("loop"), options);
  RenderStyle style;
  style.width = 200;
  style.height = 200;
  const Image a = rasterize(surface_scene(cc, {}, {}), style);
  const Image b = rasterize(surface_scene(loop, {}, {}), style);
  int differing = 0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) differing += a.rgb[i] != b.rgb[i];
  EXPECT_GT(differing, 100);
}

TEST(Render, SameInputGivesTheSameBytes) {
  RefineOptions options;
  options.levels = 2;
  const PolygonMesh surface = refine(unit_cube(), *find_scheme("catmull-clark"), options);
  RenderStyle style;
  style.width = 257;
  style.height = 131;
  const EdgeStyle edges{.wireframe = true, .features = true};
  Scene first = surface_scene(surface, {}, edges);
  add_cage(first, unit_cube());
  Scene second = surface_scene(surface, {}, edges);
  add_cage(second, unit_cube());
  EXPECT_EQ(encode_png(rasterize(first, style)), encode_png(rasterize(second, style)));
}

TEST(Render, FeaturesAndCageDrawLinesInTheirColours) {
  PolygonMesh open = unit_cube();
  open.face_offsets.pop_back();  // drop the last face: a boundary loop
  open.face_indices.resize(static_cast<std::size_t>(open.face_offsets.back()));
  open.tags.creases.push_back({1, 2, kInfiniteSharpness});
  const Scene scene = surface_scene(open, {}, EdgeStyle{.wireframe = false, .features = true});
  int boundary = 0, sharp = 0;
  for (const LineSet& set : scene.lines) {
    if (set.colour.b == kBoundaryColour.b && set.colour.r == kBoundaryColour.r) boundary += static_cast<int>(set.ends.size() / 6);
    if (set.colour.r == kSharpColour.r && set.colour.g == kSharpColour.g) sharp += static_cast<int>(set.ends.size() / 6);
  }
  EXPECT_EQ(boundary, 4);
  EXPECT_EQ(sharp, 1);
}

TEST(Render, RefusesEmptyMeshesAndBadSizes) {
  EXPECT_THROW(surface_scene(PolygonMesh{}, {}, {}), InvalidInputError);
  RenderStyle style;
  style.width = 0;
  EXPECT_THROW(rasterize(surface_scene(unit_cube(), {}, {}), style), InvalidInputError);
  style.width = kMaxImageSide + 1;
  EXPECT_THROW(rasterize(surface_scene(unit_cube(), {}, {}), style), InvalidInputError);
}

}  // namespace
}  // namespace subdiv::render

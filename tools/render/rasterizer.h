#pragma once
// Draws a Scene into an image with Mesa's off-screen renderer (OSMesa,
// software rasterization: no display, no GPU), supersampled for smooth
// edges. The same scene and style give the same pixels.

#include <cstdint>
#include <vector>

#include "camera.h"
#include "render_scene.h"

namespace subdiv::render {

/// The image's size, view and colours.
struct RenderStyle {
  int width = 800;
  int height = 600;
  ViewDirection view;
  Rgb background{1.0F, 1.0F, 1.0F};
  Rgb surface{0.72F, 0.76F, 0.82F};   // front faces
  Rgb back{0.85F, 0.55F, 0.50F};      // back faces, where a face shows its inside
  int supersample = 2;                // samples per pixel along each axis
};

/// The largest width or height accepted.
inline constexpr int kMaxImageSide = 8192;

/// 8-bit RGB pixels, top row first.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

/// The scene drawn as RenderStyle asks. Throws InvalidInputError for a size
/// outside 1 .. kMaxImageSide or a supersampled size beyond what the
/// renderer takes, and Error when Mesa cannot create its context.
Image rasterize(const Scene& scene, const RenderStyle& style);

}  // namespace subdiv::render

#pragma once
// Pictures side by side: rendered images in a grid, each with a caption
// under it (the PNG form of `subdiv compare`).

#include <string>
#include <vector>

#include "rasterizer.h"

namespace subdiv::render {

/// A picture and the lines of text under it.
struct Captioned {
  Image image;
  std::vector<std::string> lines;
};

/// The pictures in rows of `columns` (all the same size as the first), on
/// a white sheet, as PNG bytes. Throws InvalidInputError for no pictures or
/// pictures of different sizes, Error when Cairo fails.
std::string picture_grid_png(const std::vector<Captioned>& pictures, int columns);

}  // namespace subdiv::render

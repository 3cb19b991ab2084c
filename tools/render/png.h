#pragma once
// PNG encoding of a rendered image (through Cairo, which the plots use too).
// The same pixels give the same bytes.

#include <string>

#include "rasterizer.h"

namespace subdiv::render {

/// The image as PNG bytes. Throws Error when Cairo fails.
std::string encode_png(const Image& image);

}  // namespace subdiv::render

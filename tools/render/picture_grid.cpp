#include "picture_grid.h"

#include <algorithm>
#include <cstdint>
#include <memory>

#include <cairo.h>

#include "subdiv/core/error.h"

namespace subdiv::render {

namespace {

constexpr int kGap = 8;
constexpr double kFontSize = 14.0;
constexpr int kLineHeight = 18;

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// The system's sans-serif font where fontconfig finds one, else Cairo's
// built-in stroke font, which needs no installed fonts.
const char* font_family(cairo_t* cr) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_text_extents_t e{};
  cairo_text_extents(cr, "0", &e);
  const bool usable = cairo_status(cr) == CAIRO_STATUS_SUCCESS &&
                      cairo_scaled_font_status(cairo_get_scaled_font(cr)) == CAIRO_STATUS_SUCCESS && e.x_advance > 0.0;
  return usable ? "sans-serif" : "@cairo:sans-serif";
}

}  // namespace

std::string picture_grid_png(const std::vector<Captioned>& pictures, int columns) {
  if (pictures.empty()) throw InvalidInputError("no pictures to put in a grid");
  const int width = pictures.front().image.width, height = pictures.front().image.height;
  for (const Captioned& p : pictures)
    if (p.image.width != width || p.image.height != height)
      throw InvalidInputError("the grid's pictures differ in size");
  std::size_t lines = 0;
  for (const Captioned& p : pictures) lines = std::max(lines, p.lines.size());
  const int count = static_cast<int>(pictures.size());
  columns = std::clamp(columns, 1, count);
  const int rows = (count + columns - 1) / columns;
  const int cell_height = height + static_cast<int>(lines) * kLineHeight + kGap;
  const int sheet_width = columns * (width + kGap) + kGap, sheet_height = rows * cell_height + kGap;

  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> sheet(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, sheet_width, sheet_height), &cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(sheet.get()), &cairo_destroy);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
    throw Error(std::string("cannot create the picture grid: ") + cairo_status_to_string(cairo_status(cr.get())));
  cairo_set_source_rgb(cr.get(), 1.0, 1.0, 1.0);
  cairo_paint(cr.get());
  const char* family = font_family(cr.get());
  cairo_select_font_face(cr.get(), family, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr.get(), kFontSize);
  for (int i = 0; i < count; ++i) {
    const Captioned& p = pictures[static_cast<std::size_t>(i)];
    const int x = kGap + (i % columns) * (width + kGap), y = kGap + (i / columns) * cell_height;
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> tile(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height), &cairo_surface_destroy);
    cairo_surface_flush(tile.get());
    unsigned char* data = cairo_image_surface_get_data(tile.get());
    const int stride = cairo_image_surface_get_stride(tile.get());
    for (int row = 0; row < height; ++row) {
      auto* out = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(row) * stride);
      for (int col = 0; col < width; ++col) {
        const std::uint8_t* px = &p.image.rgb[(static_cast<std::size_t>(row) * width + col) * 3];
        out[col] = 0xFF000000U | (std::uint32_t{px[0]} << 16) | (std::uint32_t{px[1]} << 8) | px[2];
      }
    }
    cairo_surface_mark_dirty(tile.get());
    cairo_set_source_surface(cr.get(), tile.get(), x, y);
    cairo_paint(cr.get());
    cairo_set_source_rgb(cr.get(), 0.1, 0.1, 0.1);
    for (std::size_t l = 0; l < p.lines.size(); ++l) {
      cairo_move_to(cr.get(), x + 4, y + height + static_cast<int>(l + 1) * kLineHeight - 4);
      cairo_show_text(cr.get(), p.lines[l].c_str());
    }
  }
  cairo_surface_flush(sheet.get());
  std::string bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(sheet.get(), append_bytes, &bytes);
  if (status != CAIRO_STATUS_SUCCESS)
    throw Error(std::string("cannot encode the picture grid: ") + cairo_status_to_string(status));
  return bytes;
}

}  // namespace subdiv::render

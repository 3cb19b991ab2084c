#include "plots.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>
#include <fontconfig/fontconfig.h>

#include "subdiv/core/error.h"

namespace subdiv::cli {

namespace {

constexpr double kPi = std::numbers::pi;

bool rendered = false;  // whether Cairo and fontconfig hold global state

// The system's sans-serif font through fontconfig when it renders, else
// Cairo's built-in stroke font ("@cairo:"), which needs no installed fonts
// (but makes SVG text much larger).
const char* font_family() {
  static const char* const family = [] {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 8, 8);
    cairo_t* cr = cairo_create(surface);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_text_extents_t e{};
    cairo_text_extents(cr, "0", &e);
    const bool usable = cairo_status(cr) == CAIRO_STATUS_SUCCESS &&
                        cairo_scaled_font_status(cairo_get_scaled_font(cr)) == CAIRO_STATUS_SUCCESS &&
                        e.x_advance > 0.0;
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
    return usable ? "sans-serif" : "@cairo:sans-serif";
  }();
  return family;
}

struct Rgb {
  double r, g, b;
};
constexpr Rgb kBlack{0.0, 0.0, 0.0};
constexpr Rgb kGrid{0.88, 0.88, 0.88};
constexpr Rgb kAxis{0.2, 0.2, 0.2};
constexpr Rgb kOthers{0.27, 0.51, 0.71};  // every |lambda_i|
constexpr Rgb kLambda1{0.80, 0.10, 0.15};
constexpr Rgb kSquared{0.93, 0.55, 0.0};
constexpr Rgb kFolded{0.90, 0.0, 0.0};

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// A drawing surface of width x height (pixels for PNG, points for SVG) on a
// white background; finish() returns the encoded bytes.
class Canvas {
 public:
  Canvas(ImageFormat format, int width, int height) : format_(format) {
    rendered = true;
    surface_ = format == ImageFormat::svg ? cairo_svg_surface_create_for_stream(append_bytes, &bytes_, width, height)
                                          : cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    cr_ = cairo_create(surface_);
    cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
    cairo_paint(cr_);
    cairo_select_font_face(cr_, font_family(), CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  ~Canvas() {
    if (cr_) cairo_destroy(cr_);
    if (surface_) cairo_surface_destroy(surface_);
  }

  cairo_t* cr() const { return cr_; }

  std::string finish() {
    const cairo_status_t drawing = cairo_status(cr_);
    cairo_destroy(cr_);
    cr_ = nullptr;
    if (drawing != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(drawing));
    cairo_surface_flush(surface_);
    cairo_status_t status = CAIRO_STATUS_SUCCESS;
    if (format_ == ImageFormat::png) status = cairo_surface_write_to_png_stream(surface_, append_bytes, &bytes_);
    cairo_surface_finish(surface_);  // SVG: writes the document
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface_);
    cairo_surface_destroy(surface_);
    surface_ = nullptr;
    if (status != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(status));
    return std::move(bytes_);
  }

 private:
  ImageFormat format_;
  std::string bytes_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

enum class Align { left, centre, right };

// Text with its baseline at y, placed horizontally by `align` around x;
// text longer than max_width is set smaller to fit.
void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size, Align align = Align::left,
               Rgb colour = kBlack, double max_width = 0.0) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  if (max_width > 0.0 && e.x_advance > max_width) {
    cairo_set_font_size(cr, size * max_width / e.x_advance);
    cairo_text_extents(cr, text.c_str(), &e);
  }
  const double width = e.x_advance;
  const double left = align == Align::left ? x : align == Align::centre ? x - width / 2 : x - width;
  set_colour(cr, colour);
  cairo_move_to(cr, left, y);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);
}

// A tick step of 1, 2 or 5 times a power of ten giving at most `max_ticks`
// intervals over `span`.
double nice_step(double span, int max_ticks) {
  const double raw = span / max_ticks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

std::string tick_label(double v, double step) {
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  const double scaled = step * std::pow(10.0, decimals);
  if (std::fabs(scaled - std::round(scaled)) > 1e-6) ++decimals;
  return fmt::format("{:.{}f}", v, decimals);
}

// Hue around the wheel, alternating lightness so that neighbouring sectors
// differ even for large k.
Rgb sector_colour(int sector, int sectors) {
  const double h = 6.0 * std::fmod(static_cast<double>(sector) / std::max(sectors, 1), 1.0);
  const double s = 0.45, v = sector % 2 == 0 ? 0.97 : 0.82;
  const double c = v * s, x = c * (1.0 - std::fabs(std::fmod(h, 2.0) - 1.0)), m = v - c;
  const int i = std::clamp(static_cast<int>(h), 0, 5);
  const std::array<Rgb, 6> base{Rgb{c, x, 0}, Rgb{x, c, 0}, Rgb{0, c, x}, Rgb{0, x, c}, Rgb{x, 0, c}, Rgb{c, 0, x}};
  return {base[static_cast<std::size_t>(i)].r + m, base[static_cast<std::size_t>(i)].g + m,
          base[static_cast<std::size_t>(i)].b + m};
}

bool finite(double v) { return std::isfinite(v); }

}  // namespace

ImageFormat image_format_from_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".svg") return ImageFormat::svg;
  if (ext == ".png") return ImageFormat::png;
  if (ext.empty()) throw InvalidInputError(path + ": no file extension to choose the plot format (use .svg or .png)");
  throw InvalidInputError(path + ": unknown plot format '" + ext + "' (use .svg or .png)");
}

void check_plot_path(const std::string& path) {
  image_format_from_path(path);
  const std::filesystem::path p(path);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InvalidInputError(path + ": directory '" + dir.string() + "' does not exist");
  if (std::filesystem::is_directory(p, ec)) throw InvalidInputError(path + ": is a directory");
}

std::string render_spectrum_plot(const SpectrumPlot& plot, ImageFormat format) {
  int k_min = std::numeric_limits<int>::max(), k_max = std::numeric_limits<int>::min();
  double y_top = 1.0;
  for (const SpectrumColumn& c : plot.columns) {
    k_min = std::min(k_min, c.k);
    k_max = std::max(k_max, c.k);
    for (const double m : c.magnitudes)
      if (finite(m)) y_top = std::max(y_top, m);
    if (c.lambda1_squared && finite(*c.lambda1_squared)) y_top = std::max(y_top, *c.lambda1_squared);
  }
  if (plot.columns.empty()) throw InvalidInputError("spectrum plot: no configuration to plot");

  constexpr int kWidth = 900, kHeight = 560;
  constexpr double left = 80, right = kWidth - 200, top = 70, bottom = kHeight - 70;
  const double y_step = nice_step(y_top, 10);
  y_top = std::ceil(y_top / y_step - 1e-9) * y_step;
  const double x_lo = k_min - 0.5, x_hi = k_max + 0.5;
  auto px = [&](double k) { return left + (k - x_lo) / (x_hi - x_lo) * (right - left); };
  auto py = [&](double v) { return bottom - v / y_top * (bottom - top); };

  Canvas canvas(format, kWidth, kHeight);
  cairo_t* cr = canvas.cr();
  draw_text(cr, (left + right) / 2, 36, plot.title, 18, Align::centre);

  // Grid, axes, ticks.
  cairo_set_line_width(cr, 1.0);
  for (int i = 0; i * y_step <= y_top + 1e-9; ++i) {
    const double v = i * y_step, y = py(v);
    set_colour(cr, kGrid);
    cairo_move_to(cr, left, y);
    cairo_line_to(cr, right, y);
    cairo_stroke(cr);
    draw_text(cr, left - 8, y + 4, tick_label(v, y_step), 12, Align::right, kAxis);
  }
  const int k_step = static_cast<int>(nice_step(std::max(1, k_max - k_min), 16));
  for (int k = k_min; k <= k_max; ++k) {
    if ((k - k_min) % std::max(k_step, 1) != 0) continue;
    set_colour(cr, kAxis);
    cairo_move_to(cr, px(k), bottom);
    cairo_line_to(cr, px(k), bottom + 5);
    cairo_stroke(cr);
    draw_text(cr, px(k), bottom + 20, std::to_string(k), 12, Align::centre, kAxis);
  }
  set_colour(cr, kAxis);
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_stroke(cr);
  draw_text(cr, (left + right) / 2, bottom + 45, plot.x_label, 14, Align::centre);
  cairo_save(cr);
  cairo_translate(cr, 28, (top + bottom) / 2);
  cairo_rotate(cr, -kPi / 2);
  draw_text(cr, 0, 0, "|lambda_i|, i >= 1", 14, Align::centre);
  cairo_restore(cr);

  // Every magnitude as a small dot, then lambda_1^2 dashed and lambda_1 on top.
  set_colour(cr, kOthers, 0.8);
  for (const SpectrumColumn& c : plot.columns)
    for (const double m : c.magnitudes) {
      if (!finite(m)) continue;
      cairo_new_sub_path(cr);
      cairo_arc(cr, px(c.k), py(m), 3.0, 0, 2 * kPi);
    }
  cairo_fill(cr);

  auto series = [&](auto value, Rgb colour, double width, bool dashed, double marker) {
    set_colour(cr, colour);
    cairo_set_line_width(cr, width);
    if (dashed) {
      const double dashes[] = {7.0, 5.0};
      cairo_set_dash(cr, dashes, 2, 0);
    }
    bool drawing = false;
    for (const SpectrumColumn& c : plot.columns) {
      const std::optional<double> v = value(c);
      if (!v || !finite(*v)) {
        drawing = false;
        continue;
      }
      if (drawing)
        cairo_line_to(cr, px(c.k), py(*v));
      else
        cairo_move_to(cr, px(c.k), py(*v));
      drawing = true;
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    for (const SpectrumColumn& c : plot.columns) {
      const std::optional<double> v = value(c);
      if (!v || !finite(*v)) continue;
      cairo_new_sub_path(cr);
      cairo_arc(cr, px(c.k), py(*v), marker, 0, 2 * kPi);
    }
    cairo_fill(cr);
  };
  series([](const SpectrumColumn& c) { return c.lambda1_squared; }, kSquared, 1.8, true, 2.5);
  series([](const SpectrumColumn& c) { return c.lambda1; }, kLambda1, 2.2, false, 4.5);

  // Legend.
  const double lx = right + 20;
  double ly = top + 20;
  set_colour(cr, kOthers, 0.8);
  cairo_arc(cr, lx + 15, ly - 4, 3.0, 0, 2 * kPi);
  cairo_fill(cr);
  draw_text(cr, lx + 32, ly, "|lambda_i|", 13);
  ly += 26;
  set_colour(cr, kLambda1);
  cairo_set_line_width(cr, 2.2);
  cairo_move_to(cr, lx, ly - 4);
  cairo_line_to(cr, lx + 30, ly - 4);
  cairo_stroke(cr);
  cairo_arc(cr, lx + 15, ly - 4, 4.5, 0, 2 * kPi);
  cairo_fill(cr);
  draw_text(cr, lx + 38, ly, "lambda_1", 13);
  ly += 26;
  set_colour(cr, kSquared);
  cairo_set_line_width(cr, 1.8);
  const double dashes[] = {7.0, 5.0};
  cairo_set_dash(cr, dashes, 2, 0);
  cairo_move_to(cr, lx, ly - 4);
  cairo_line_to(cr, lx + 30, ly - 4);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  draw_text(cr, lx + 38, ly, "lambda_1^2", 13);
  return canvas.finish();
}

std::string render_characteristic_map_plot(const CharacteristicMapPlot& plot, ImageFormat format) {
  const std::size_t n = plot.points.size();
  if (plot.face_sector.size() != plot.faces.size() || plot.face_orientation.size() != plot.faces.size())
    throw InvalidInputError("characteristic map plot: per-face arrays do not match the face count");
  if (plot.faces.empty()) throw InvalidInputError("characteristic map plot: no faces");
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  int sectors = 1;
  for (std::size_t f = 0; f < plot.faces.size(); ++f) {
    for (const int v : plot.faces[f]) {
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        throw InvalidInputError(fmt::format("characteristic map plot: face {} uses vertex {} of {}", f, v, n));
      const auto [x, y] = plot.points[static_cast<std::size_t>(v)];
      if (!finite(x) || !finite(y))
        throw InvalidInputError(fmt::format("characteristic map plot: vertex {} is not finite", v));
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    sectors = std::max(sectors, plot.face_sector[f] + 1);
  }

  constexpr int kWidth = 760, kHeight = 840;
  constexpr double left = 30, right = kWidth - 30, top = 100, bottom = kHeight - 60;
  // One scale for both axes: the map's shape is what is being judged.
  const double span = std::max({x1 - x0, y1 - y0, 1e-300});
  const double scale = std::min(right - left, bottom - top) / span;
  const double cx = (left + right) / 2 - scale * (x0 + x1) / 2, cy = (top + bottom) / 2 + scale * (y0 + y1) / 2;
  auto to_page = [&](int v) {
    const auto [x, y] = plot.points[static_cast<std::size_t>(v)];
    return std::array<double, 2>{cx + scale * x, cy - scale * y};  // y up
  };
  Canvas canvas(format, kWidth, kHeight);
  cairo_t* cr = canvas.cr();
  draw_text(cr, kWidth / 2.0, 38, plot.title, 18, Align::centre);
  draw_text(cr, kWidth / 2.0, 64, plot.subtitle, 13, Align::centre, kAxis);
  if (!plot.note.empty()) draw_text(cr, kWidth / 2.0, 84, plot.note, 11, Align::centre, kAxis, kWidth - 20.0);

  auto face_path = [&](const std::vector<int>& face) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto [x, y] = to_page(face[i]);
      if (i == 0)
        cairo_move_to(cr, x, y);
      else
        cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
  };
  // The majority orientation is the reference, as in the regularity verdict
  // (characteristic_map()): faces against it, and folded or degenerate
  // faces (0), are marked, so a reversed or degenerate first face does not
  // paint the whole map red.
  const auto positive = std::count(plot.face_orientation.begin(), plot.face_orientation.end(), 1);
  const auto negative = std::count(plot.face_orientation.begin(), plot.face_orientation.end(), -1);
  const int reference = positive == 0 && negative == 0 ? 0 : positive >= negative ? 1 : -1;
  auto is_marked = [&](std::size_t f) {
    return plot.face_orientation[f] == 0 || plot.face_orientation[f] != reference;
  };
  int marked = 0;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t f = 0; f < plot.faces.size(); ++f) {
    if (is_marked(f)) continue;
    face_path(plot.faces[f]);
    set_colour(cr, sector_colour(plot.face_sector[f], sectors));
    cairo_fill_preserve(cr);
    set_colour(cr, kAxis, 0.6);
    cairo_set_line_width(cr, 0.4);
    cairo_stroke(cr);
  }
  // Faces whose Jacobian sign differs from the majority's go on top.
  for (std::size_t f = 0; f < plot.faces.size(); ++f) {
    if (!is_marked(f)) continue;
    ++marked;
    face_path(plot.faces[f]);
    set_colour(cr, kFolded, 0.75);
    cairo_fill_preserve(cr);
    set_colour(cr, kBlack);
    cairo_set_line_width(cr, 1.2);
    cairo_stroke(cr);
  }
  // The centre's image, the origin.
  if (x0 <= 0 && 0 <= x1 && y0 <= 0 && 0 <= y1) {
    set_colour(cr, kBlack);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, cx - 6, cy);
    cairo_line_to(cr, cx + 6, cy);
    cairo_move_to(cr, cx, cy - 6);
    cairo_line_to(cr, cx, cy + 6);
    cairo_stroke(cr);
  }
  const std::string legend =
      marked == 0 ? fmt::format("{} faces coloured by sector, all of one orientation (the Jacobian has one sign)",
                                plot.faces.size())
                  : fmt::format("{} faces coloured by sector; red, outlined: {} folded, degenerate or reversed faces",
                                plot.faces.size(), marked);
  draw_text(cr, kWidth / 2.0, kHeight - 25, legend, 12, Align::centre, kAxis, kWidth - 20.0);
  return canvas.finish();
}

void release_plot_caches() {
  if (!rendered) return;
  release_text_caches();
}

void release_text_caches() {
  cairo_debug_reset_static_data();
  FcFini();
  rendered = false;
}

}  // namespace subdiv::cli

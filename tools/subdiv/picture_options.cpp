#include "picture_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>

#include <fmt/format.h>

#include "subdiv/core/error.h"

namespace subdiv::cli {

namespace {

render::ViewDirection parse_view(const std::string& text) {
  render::ViewDirection view;
  char comma = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "%lf %c %lf%n", &view.azimuth, &comma, &view.elevation, &consumed) != 3 ||
      comma != ',' || consumed != static_cast<int>(text.size()) || !std::isfinite(view.azimuth) ||
      !(view.elevation >= -90.0 && view.elevation <= 90.0))
    throw InvalidInputError("--view: expected AZIMUTH,ELEVATION in degrees (elevation in -90..90), not '" + text + "'");
  return view;
}

std::pair<int, int> parse_size(const std::string& text) {
  int width = 0, height = 0, consumed = 0;
  if (std::sscanf(text.c_str(), "%dx%d%n", &width, &height, &consumed) != 2 ||
      consumed != static_cast<int>(text.size()) || width < 1 || height < 1 || width > render::kMaxImageSide ||
      height > render::kMaxImageSide)
    throw InvalidInputError(fmt::format("--size: expected WIDTHxHEIGHT in pixels, each 1..{}, not '{}'",
                                        render::kMaxImageSide, text));
  return {width, height};
}

render::Rgb parse_colour(const std::string& text) {
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "white") return {1.0F, 1.0F, 1.0F};
  if (lower == "black") return {0.0F, 0.0F, 0.0F};
  if (lower == "grey" || lower == "gray") return {0.5F, 0.5F, 0.5F};
  unsigned r = 0, g = 0, b = 0;
  int consumed = 0;
  if (lower.size() == 7 && std::sscanf(lower.c_str(), "#%2x%2x%2x%n", &r, &g, &b, &consumed) == 3 && consumed == 7)
    return {static_cast<float>(r) / 255.0F, static_cast<float>(g) / 255.0F, static_cast<float>(b) / 255.0F};
  throw InvalidInputError("--background: expected #rrggbb, white, black or grey, not '" + text + "'");
}

}  // namespace

void add_picture_options(CLI::App& cmd, PictureOptionValues& values, const std::string& default_size) {
  values.size = default_size;
  cmd.add_option("--view", values.view, "Camera direction AZIMUTH,ELEVATION in degrees (y up; 0,0 looks from +z)")
      ->capture_default_str();
  cmd.add_option("--size", values.size, "Image size WIDTHxHEIGHT in pixels")->capture_default_str();
  cmd.add_option("--background", values.background, "Background colour: #rrggbb, white, black or grey")
      ->capture_default_str();
  cmd.add_option("--samples", values.samples, "Samples per pixel along each axis (smooths edges)")
      ->capture_default_str()
      ->check(CLI::Range(1, 4));
}

render::RenderStyle picture_style(const PictureOptionValues& values) {
  render::RenderStyle style;
  std::tie(style.width, style.height) = parse_size(values.size);
  style.view = parse_view(values.view);
  style.background = parse_colour(values.background);
  style.supersample = values.samples;
  return style;
}

}  // namespace subdiv::cli

#pragma once
// The options of the commands that draw pictures (render, compare --png):
// camera direction, image size, background and supersampling.

#include <string>

#include <CLI/CLI.hpp>

#include "../render/rasterizer.h"

namespace subdiv::cli {

struct PictureOptionValues {
  std::string view = "30,20";
  std::string size;  // WIDTHxHEIGHT; the command's default
  std::string background = "#ffffff";
  int samples = 2;
};

/// Registers --view, --size (default `default_size`), --background and
/// --samples on `cmd`.
void add_picture_options(CLI::App& cmd, PictureOptionValues& values, const std::string& default_size);

/// The style the options ask for; throws InvalidInputError naming the
/// option for a malformed value.
render::RenderStyle picture_style(const PictureOptionValues& values);

}  // namespace subdiv::cli

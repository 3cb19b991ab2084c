#pragma once
// Plots for `subdiv analyze`, drawn with Cairo into memory (SVG or PNG
// bytes) from plain data, so that callers choose how to write them.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace subdiv::cli {

enum class ImageFormat { svg, png };

/// The format named by the path's extension (.svg or .png, any case).
/// Throws InvalidInputError for any other extension.
ImageFormat image_format_from_path(const std::string& path);

/// Throws InvalidInputError unless `path` has a plot extension and its
/// directory exists, so that bad paths fail before any work is done.
void check_plot_path(const std::string& path);

/// One column of the spectrum plot: the configuration's k and its
/// eigenvalue magnitudes |lambda_1|, |lambda_2|, ... (lambda_0 left out).
struct SpectrumColumn {
  int k = 0;
  std::vector<double> magnitudes;
  /// |lambda_1|, highlighted, and |lambda_1|^2, drawn dashed; absent when
  /// the configuration has no subdominant eigenvalue.
  std::optional<double> lambda1;
  std::optional<double> lambda1_squared;
};

struct SpectrumPlot {
  std::string title;
  std::string x_label = "valence k";
  std::vector<SpectrumColumn> columns;
};

/// The characteristic map's control net in the plane.
struct CharacteristicMapPlot {
  std::string title;
  std::string subtitle;
  std::string note;  ///< a third title line, set smaller when long
  std::vector<std::array<double, 2>> points;
  std::vector<std::vector<int>> faces;
  std::vector<int> face_sector;       ///< colour of each face
  std::vector<int> face_orientation;  ///< faces unlike the majority are marked
};

/// The image bytes. Throws InvalidInputError for malformed data (indices
/// out of range, mismatched sizes) and Error when Cairo fails.
std::string render_spectrum_plot(const SpectrumPlot& plot, ImageFormat format);
std::string render_characteristic_map_plot(const CharacteristicMapPlot& plot, ImageFormat format);

/// Frees Cairo's and fontconfig's process-wide caches, which otherwise stay
/// allocated until exit (and read as leaks under LeakSanitizer). Call once,
/// after the last plot, when no Cairo object is alive; a no-op when nothing
/// was rendered.
void release_plot_caches();

/// The same for text drawn elsewhere (the captions of compare's picture
/// grid): frees the caches unconditionally. Call once, when no Cairo object
/// is alive.
void release_text_caches();

}  // namespace subdiv::cli

// subdiv analyze -s SCHEME [-k A..B]: the scheme's local behaviour at
// interior, boundary or corner configurations (Zorin's survey, sections 2
// and 5): spectrum, Reif's condition, characteristic map, C1 verdict and
// curvature, as a table or JSON, with optional plots.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "analysis_report.h"
#include "gcc_report.h"
#include "commands.h"
#include "scheme_option.h"
#include "subdiv/io/file_io.h"
#include "plots.h"
#include "quasi_4_8_analysis.h"
#include "subdiv/analysis/analyze.h"
#include "subdiv/core/error.h"

namespace subdiv::cli {

namespace {

constexpr int kMaxK = 64;
constexpr std::size_t kMagnitudesPerColumn = 8;

struct AnalyzeCommandOptions {
  std::string scheme;
  std::string k;
  bool boundary = false;
  std::string corner;
  bool json = false;
  std::string plot_spectrum;
  std::pair<int, std::string> plot_charmap;  // K FILE
  bool plot_charmap_given = false;
  bool no_charmap = false;
  std::optional<double> angle_degrees;
  std::string boundary_rules = "standard";
  std::optional<double> flatness;
  std::optional<double> tension;
  DegreeOptionValues degree;
  std::optional<int> warmup;  // quasi-4-8: binary steps before the matrix
};

int parse_int(std::string_view text, const std::string& what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    throw InvalidInputError(what + ": '" + std::string(text) + "' is not an integer");
  return value;
}

int smallest_k(const Configuration& c) { return c.kind == Configuration::Kind::interior ? 3 : 1; }

void check_k(int k, const Configuration& c, const std::string& what) {
  if (k < smallest_k(c))
    throw InvalidInputError(fmt::format("{}: {} configurations need k >= {}, not {}", what,
                                        c.kind == Configuration::Kind::interior   ? "interior"
                                        : c.kind == Configuration::Kind::boundary ? "boundary"
                                                                                  : "corner",
                                        smallest_k(c), k));
  if (k > kMaxK) throw InvalidInputError(fmt::format("{}: k is at most {}, not {}", what, kMaxK, k));
}

// "K" or "A..B".
std::pair<int, int> parse_k_range(const std::string& text, const Configuration& c) {
  const std::string what = "-k " + text;
  const auto dots = text.find("..");
  if (const auto dash = text.find('-', 1); dots == std::string::npos && dash != std::string::npos)
    throw InvalidInputError(fmt::format("{}: a range is written {}..{}", what, text.substr(0, dash), text.substr(dash + 1)));
  const int a = parse_int(text.substr(0, dots), what);
  const int b = dots == std::string::npos ? a : parse_int(text.substr(dots + 2), what);
  if (a > b) throw InvalidInputError(fmt::format("{}: empty range ({} > {})", what, a, b));
  check_k(a, c, what);
  check_k(b, c, what);
  return {a, b};
}

SpectrumColumn spectrum_column(const ConfigurationAnalysis& a) {
  SpectrumColumn column;
  column.k = a.matrix.configuration.k;
  const std::vector<std::complex<double>> all = a.spectrum.expanded();
  // Distinct magnitudes after lambda_0: copies of one value would overprint.
  for (std::size_t i = 1; i < all.size() && column.magnitudes.size() < kMagnitudesPerColumn; ++i) {
    const double m = std::abs(all[i]);
    if (column.magnitudes.empty() || std::fabs(column.magnitudes.back() - m) > 1e-9 * std::max(1.0, m))
      column.magnitudes.push_back(m);
  }
  if (a.leading.size() > 1) {
    column.lambda1 = std::abs(a.leading[1]);
    column.lambda1_squared = *column.lambda1 * *column.lambda1;
  }
  return column;
}

std::string kind_label(const Configuration& c) {
  switch (c.kind) {
    case Configuration::Kind::interior:
      return "interior configurations";
    case Configuration::Kind::boundary:
      return "boundary configurations";
    case Configuration::Kind::corner:
      return std::string(to_string(c.corner)) + " corners";
  }
  return "";
}

CharacteristicMapPlot characteristic_map_plot(std::string_view scheme, const ConfigurationAnalysis& a) {
  const CharacteristicMap& map = *a.characteristic_map;
  CharacteristicMapPlot plot;
  plot.title = fmt::format("{}: characteristic map, {}", scheme, a.matrix.configuration.name());
  plot.subtitle = fmt::format("regular: {}, injective: {}, {} levels", map.regular ? "yes" : "no",
                              map.injective ? "yes" : "no", map.levels);
  plot.note = map.note;
  for (const Vec3& p : map.image.positions) plot.points.push_back({p.x, p.y});
  for (Index f = 0; f < map.image.face_count(); ++f) {
    const auto face = map.image.face(f);
    plot.faces.emplace_back(face.begin(), face.end());
  }
  plot.face_sector = map.face_sector;
  plot.face_orientation = map.face_orientation;
  return plot;
}

// Curve schemes have one regular configuration: no k, no boundary rules.
int run_curve_analysis(const CurveScheme& curve, const AnalyzeCommandOptions& opt) {
  if (!opt.k.empty() || opt.boundary || !opt.corner.empty() || opt.angle_degrees || !opt.plot_spectrum.empty() ||
      opt.plot_charmap_given || opt.boundary_rules != "standard" || opt.flatness)
    throw InvalidInputError(std::string(curve.name) +
                            " is a curve scheme: it has one regular configuration and no -k, --boundary, --corner, "
                            "--angle, --boundary-rules, --flatness or plots");
  const CurveAnalysis a = analyze_curve(curve);
  const std::string text = opt.json ? curve_analysis_json(curve.name, a) : format_curve_analysis(curve.name, a);
  std::fwrite(text.data(), 1, text.size(), stdout);
  return kExitOk;
}

int run_analyze(const AnalyzeCommandOptions& opt) {
  if (const CurveScheme* curve = find_curve_scheme(opt.scheme); curve && !find_scheme(opt.scheme)) {
    return run_curve_analysis(with_tension(*curve, opt.tension), opt);
  }
  const Scheme selected = with_degree_options(with_tension(scheme_named(opt.scheme), opt.tension), opt.degree);
  const Scheme* scheme = &selected;
  if (scheme->split == SplitRule::quasi_4_8) {  // no canonical ring meshes: the n-gon experiment
    if (opt.boundary || !opt.corner.empty() || opt.json || !opt.plot_spectrum.empty() || opt.plot_charmap_given ||
        opt.boundary_rules != "standard" || opt.flatness)
      throw InvalidInputError(
          "quasi-4-8 is analysed on n-regular neighbourhoods only: -k and --warmup, no --boundary, --corner, "
          "--json, --boundary-rules, --flatness or plots");
    Configuration interior;
    const auto [first, last] = parse_k_range(opt.k.empty() ? "3..12" : opt.k, interior);
    return run_quasi_4_8_analysis(first, last, opt.warmup.value_or(8));
  }
  if (opt.warmup) throw InvalidInputError("--warmup applies to quasi-4-8");
  if (opt.flatness && opt.boundary_rules != "piecewise-smooth")
    throw InvalidInputError("--flatness applies to --boundary-rules piecewise-smooth");

  Configuration base;
  if (opt.boundary) base.kind = Configuration::Kind::boundary;
  if (!opt.corner.empty()) {
    base.kind = Configuration::Kind::corner;
    base.corner = opt.corner == "concave" ? CornerType::concave : CornerType::convex;
  }
  if (opt.angle_degrees) {
    const double degrees = *opt.angle_degrees;
    if (base.kind != Configuration::Kind::corner) throw InvalidInputError("--angle applies to --corner configurations");
    if ((base.corner == CornerType::convex) != (degrees < 180.0))
      throw InvalidInputError(fmt::format("--angle {}: a {} corner's angle must be {} 180 degrees", degrees, opt.corner,
                                          base.corner == CornerType::convex ? "below" : "above"));
    base.angle = degrees * std::numbers::pi / 180.0;
  }
  if (selected.steps && base.kind != Configuration::Kind::interior)
    throw InvalidInputError(std::string(selected.name) +
                            " is analysed at interior configurations only (its boundary keeps or Chaikin-cuts the "
                            "boundary polygon; see docs/schemes.md)");
  const std::string k_text = !opt.k.empty() ? opt.k : base.kind == Configuration::Kind::interior ? "3..12" : "1..12";
  const auto [k_first, k_last] = parse_k_range(k_text, base);

  // Bad plot arguments fail before any analysis runs.
  int charmap_k = 0;
  if (!opt.plot_spectrum.empty()) check_plot_path(opt.plot_spectrum);
  if (opt.plot_charmap_given) {
    charmap_k = opt.plot_charmap.first;
    check_k(charmap_k, base, "--plot-charmap " + std::to_string(charmap_k));
    check_plot_path(opt.plot_charmap.second);
  }

  AnalysisOptions options;
  options.characteristic_map = !opt.no_charmap;
  options.rules.boundary_rules =
      opt.boundary_rules == "piecewise-smooth" ? BoundaryRules::piecewise_smooth : BoundaryRules::standard;
  options.rules.flatness = opt.flatness;
  std::vector<ConfigurationAnalysis> results;
  for (int k = k_first; k <= k_last; ++k) {
    Configuration c = base;
    c.k = k;
    results.push_back(analyze(*scheme, c, options));
  }

  // Render everything before writing anything.
  struct ReleaseCaches {
    ~ReleaseCaches() { release_plot_caches(); }
  } release_caches_on_exit;
  std::vector<std::pair<std::string, std::string>> plots;  // path, bytes
  if (!opt.plot_spectrum.empty()) {
    SpectrumPlot plot;
    plot.title = fmt::format("{}: eigenvalue magnitudes, {}", scheme->name, kind_label(base));
    plot.x_label = base.kind == Configuration::Kind::interior ? "valence k" : "faces k";
    for (const ConfigurationAnalysis& a : results)
      if (!a.spectrum.values.empty()) plot.columns.push_back(spectrum_column(a));
    if (plot.columns.empty())
      throw InvalidInputError(opt.plot_spectrum + ": no configuration has a spectrum to plot (" +
                              results.front().reason + ")");
    plots.emplace_back(opt.plot_spectrum, render_spectrum_plot(plot, image_format_from_path(opt.plot_spectrum)));
  }
  if (opt.plot_charmap_given) {
    const ConfigurationAnalysis* chosen = nullptr;
    for (const ConfigurationAnalysis& a : results)
      if (a.matrix.configuration.k == charmap_k && a.characteristic_map) chosen = &a;
    ConfigurationAnalysis own;
    if (!chosen) {
      Configuration c = base;
      c.k = charmap_k;
      AnalysisOptions with_map = options;
      with_map.characteristic_map = true;
      own = analyze(*scheme, c, with_map);
      chosen = &own;
    }
    if (!chosen->characteristic_map)
      throw InvalidInputError(fmt::format("{}: {} has no characteristic map at {}: {}", opt.plot_charmap.second,
                                          scheme->name, chosen->matrix.configuration.name(), chosen->reason));
    const std::string& path = opt.plot_charmap.second;
    plots.emplace_back(path, render_characteristic_map_plot(characteristic_map_plot(scheme->name, *chosen),
                                                            image_format_from_path(path)));
  }
  for (const auto& [path, bytes] : plots) write_file_atomically(path, bytes);

  std::string text = opt.json ? analysis_json(scheme->name, results) : format_analysis_table(scheme->name, results);
  if (std::holds_alternative<DegreeParameters>(scheme->parameters)) {  // gcc and midpoint: the paper's theorems
    if (opt.json) {
      nlohmann::json doc = nlohmann::json::parse(text);
      doc["chen_prautzsch"] = gcc_report_json(*scheme, results);
      text = doc.dump(2) + "\n";
    } else {
      text += format_gcc_report(*scheme, results);
    }
  }
  std::fwrite(text.data(), 1, text.size(), stdout);
  if (!opt.json && (scheme->split == SplitRule::dual || scheme->split == SplitRule::midedge))
    std::printf("(%s: interior k is an extraordinary face of k sides in a ring of quads)\n", to_string(scheme->split));
  if (!opt.json)
    for (const auto& [path, bytes] : plots) std::printf("wrote %s (%zu bytes)\n", path.c_str(), bytes.size());
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace

Command add_analyze_command(CLI::App& app) {
  auto opt = std::make_shared<AnalyzeCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "analyze", "Analyse a scheme at extraordinary configurations: spectrum, Reif's condition, C1, curvature");
  cmd->add_option("-s,--scheme", opt->scheme, "Scheme (see 'subdiv schemes')")->required();
  cmd->add_option("-k", opt->k, "Valence K or range A..B (default 3..12 interior, 1..12 boundary and corner; k <= 64)")
      ->type_name("K|A..B");
  auto* boundary = cmd->add_flag("--boundary", opt->boundary, "Boundary vertices with k faces (k >= 1)");
  cmd->add_option("--corner", opt->corner, "Corner vertices with k faces, convex or concave (k >= 1)")
      ->check(CLI::IsMember({"convex", "concave"}))
      ->excludes(boundary);
  cmd->add_option("--angle", opt->angle_degrees, "The corners' angle in degrees (default 90 convex, 270 concave)")
      ->check(CLI::Range(0.0, 360.0).description("in (0, 360)"));
  cmd->add_option("--boundary-rules", opt->boundary_rules,
                  "Rules next to boundaries and corners: standard or piecewise-smooth (gamma(theta), flatness)")
      ->check(CLI::IsMember({"standard", "piecewise-smooth"}))
      ->capture_default_str();
  cmd->add_option("--flatness", opt->flatness,
                  "Flatness parameter s at concave corners (piecewise-smooth; default 1 - (1/4)/lambda_3, 0 = off)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--tension", opt->tension, "butterfly, kobbelt and the four-point curve scheme: the tension w (default 1/16)");
  add_degree_options(*cmd, opt->degree);
  cmd->add_option("--warmup", opt->warmup, "quasi-4-8: binary steps before the matrix is read (default 8)")
      ->check(CLI::Range(0, 10));
  cmd->add_flag("--json", opt->json, "Print JSON (spectra, limit and tangent masks, layout) instead of the table");
  cmd->add_option("--plot-spectrum", opt->plot_spectrum, "Plot eigenvalue magnitudes against k (.svg or .png)")
      ->type_name("FILE");
  CLI::Option* charmap =
      cmd->add_option("--plot-charmap", opt->plot_charmap, "Plot the characteristic map at k = K (.svg or .png)")
          ->type_name("K FILE");
  cmd->add_flag("--no-charmap", opt->no_charmap,
                "Skip the characteristic map in the table (faster; the verdict is then inconclusive)");
  cmd->footer(
      "Columns: configuration, n and rings (the smallest invariant neighbourhood),\n"
      "lambda_1, lambda_2, |lambda_3| (leading eigenvalues after lambda_0 = 1), lambda_1^2,\n"
      "Reif (eigenvalue condition), regular/injective (characteristic map), verdict,\n"
      "curvature (Zorin's Proposition 6). The limit-position and tangent masks and the\n"
      "full spectra are in the --json output.\n"
      "Examples:\n"
      "  subdiv analyze -s loop -k 3..8\n"
      "  subdiv analyze -s catmull-clark --boundary -k 1..5 --json\n"
      "  subdiv analyze -s loop --boundary -k 3..9 --boundary-rules piecewise-smooth\n"
      "  subdiv analyze -s cubic-bspline    (curve schemes: cubic-bspline, chaikin, four-point)\n"
      "  subdiv analyze -s gcc --alpha 0.3 --beta 0.4 -k 3..16   (with the paper's closed forms)\n"
      "  subdiv analyze -s midpoint --degree 6 -k 3..8\n"
      "  subdiv analyze -s quasi-4-8 -k 3..12 --warmup 8   (n-regular neighbourhoods)\n"
      "  subdiv analyze -s catmull-clark --plot-spectrum /tmp/cc.svg --plot-charmap 5 /tmp/cc5.png");
  return [opt, charmap] {
    opt->plot_charmap_given = charmap->count() > 0;
    return run_analyze(*opt);
  };
}

}  // namespace subdiv::cli

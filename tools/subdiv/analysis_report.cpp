#include "analysis_report.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace subdiv::cli {

namespace {

const char* kind_name(Configuration::Kind kind) {
  switch (kind) {
    case Configuration::Kind::interior:
      return "interior";
    case Configuration::Kind::boundary:
      return "boundary";
    case Configuration::Kind::corner:
      return "corner";
  }
  return "?";
}

const char* yes_no(bool b) { return b ? "yes" : "no"; }

nlohmann::json regular_json(const RegularSmoothness& r) {
  return {{"verdict", to_string(r.verdict)}, {"reason", r.reason},     {"critical", r.critical},
          {"lower", r.lower},                 {"upper", r.upper},       {"lower_length", r.lower_length},
          {"upper_length", r.upper_length},   {"window", r.window},     {"digits", r.digits}};
}

// The leading eigenvalue i (0 = the dominant one), or nothing when the
// analysis stopped before the spectrum.
const std::complex<double>* leading(const ConfigurationAnalysis& a, std::size_t i) {
  return i < a.leading.size() ? &a.leading[i] : nullptr;
}

nlohmann::json complex_json(std::complex<double> z) { return {{"re", z.real()}, {"im", z.imag()}}; }

nlohmann::json vector_json(const Eigen::VectorXd& v) {
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) out.push_back(v[i]);
  return out;
}

nlohmann::json configuration_json(const ConfigurationAnalysis& a) {
  const Configuration& c = a.matrix.configuration;
  nlohmann::json j;
  j["name"] = c.name();
  j["kind"] = kind_name(c.kind);
  j["k"] = c.k;
  if (c.kind == Configuration::Kind::corner) j["corner"] = to_string(c.corner);
  // Refinement steps per analysis step: S and its spectrum span that many.
  j["period"] = a.matrix.period;
  j["rings"] = a.matrix.rings;
  j["matrix_size"] = a.matrix.S.rows();
  j["invariant"] = a.matrix.invariant;
  if (!a.matrix.invariant) j["invariance_note"] = a.matrix.invariance_note;
  // The spectrum is taken one ring wider than the invariant neighbourhood.
  j["spectrum_rings"] = a.wide_matrix.rings;
  j["spectrum_matrix_size"] = a.wide_matrix.S.rows();

  nlohmann::json lead = nlohmann::json::array();
  for (const auto& z : a.leading) lead.push_back(complex_json(z));
  j["leading_eigenvalues"] = lead;
  nlohmann::json spectrum = nlohmann::json::array();
  for (const Eigenvalue& e : a.spectrum.values)
    spectrum.push_back({{"re", e.value.real()},
                        {"im", e.value.imag()},
                        {"magnitude", std::abs(e.value)},
                        {"algebraic", e.algebraic},
                        {"geometric", e.geometric},
                        {"frequencies", e.frequencies}});
  j["spectrum"] = spectrum;

  // Masks are over `matrix`'s neighbourhood, in the order of `layout`.
  j["limit_mask"] = a.limit_mask ? vector_json(*a.limit_mask) : nlohmann::json(nullptr);
  j["tangent_masks"] =
      a.tangent_masks ? nlohmann::json::array({vector_json((*a.tangent_masks)[0]), vector_json((*a.tangent_masks)[1])})
                      : nlohmann::json(nullptr);
  nlohmann::json layout = nlohmann::json::array();
  for (const Vec3& p : a.matrix.layout) layout.push_back({p.x, p.y});
  j["layout"] = layout;
  j["ring_of"] = a.matrix.ring_of;

  j["eigenvalue_condition"] = a.eigenvalue_condition;
  if (a.characteristic_map) {
    const CharacteristicMap& m = *a.characteristic_map;
    j["characteristic_map"] = {{"regular", m.regular},
                               {"injective", m.injective},
                               {"note", m.note},
                               {"levels", m.levels},
                               {"faces", m.image.face_count()}};
  } else {
    j["characteristic_map"] = nullptr;
  }
  j["verdict"] = to_string(a.verdict);
  j["reason"] = a.reason;
  j["regular"] = regular_json(a.regular);
  j["curvature"] = to_string(a.curvature);
  return j;
}

}  // namespace

std::string format_complex(std::complex<double> z) {
  if (z.imag() == 0.0) return fmt::format("{:.6f}", z.real());
  return fmt::format("{:.6f}{:+.6f}i", z.real(), z.imag());
}

std::string format_analysis_table(std::string_view scheme, const std::vector<ConfigurationAnalysis>& results) {
  constexpr std::size_t kColumns = 12;
  using Row = std::array<std::string, kColumns>;
  // Text columns are left-aligned, numbers right-aligned.
  constexpr std::array<bool, kColumns> kLeft{true,  false, false, false, false, false,
                                             false, true,  true,  true,  true,  true};
  std::vector<Row> rows{{"configuration", "n", "rings", "lambda_1", "lambda_2", "|lambda_3|", "lambda_1^2", "Reif",
                         "regular", "injective", "verdict", "curvature"}};
  for (const ConfigurationAnalysis& a : results) {
    const auto* l1 = leading(a, 1);
    const auto* l2 = leading(a, 2);
    const auto* l3 = leading(a, 3);
    const auto& map = a.characteristic_map;
    rows.push_back({a.matrix.configuration.name(), std::to_string(a.matrix.S.rows()), std::to_string(a.matrix.rings),
                    l1 ? format_complex(*l1) : "-", l2 ? format_complex(*l2) : "-",
                    l3 ? fmt::format("{:.6f}", std::abs(*l3)) : "-", l1 ? format_complex(*l1 * *l1) : "-",
                    yes_no(a.eigenvalue_condition), map ? yes_no(map->regular) : "-",
                    map ? yes_no(map->injective) : "-", to_string(a.verdict), to_string(a.curvature)});
  }
  std::array<std::size_t, kColumns> width{};
  for (const Row& r : rows)
    for (std::size_t c = 0; c < kColumns; ++c) width[c] = std::max(width[c], r[c].size());

  std::string out = fmt::format("scheme {}\n", scheme);
  if (!results.empty() && results.front().matrix.period > 1)
    out = fmt::format("scheme {} (period {}: S spans {} refinement steps)\n", scheme, results.front().matrix.period,
                      results.front().matrix.period);
  for (const Row& r : rows) {
    std::string line;
    for (std::size_t c = 0; c < kColumns; ++c) {
      if (c > 0) line += "  ";
      line += kLeft[c] ? fmt::format("{:<{}}", r[c], width[c]) : fmt::format("{:>{}}", r[c], width[c]);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out += line + "\n";
  }
  // Every configuration's verdict rests on the same regular rules.
  if (!results.empty()) out += fmt::format("\n{}\n", results.front().regular.reason);
  bool first = true;
  for (const ConfigurationAnalysis& a : results) {
    if (a.verdict == SmoothnessVerdict::c1) continue;
    if (first) out += "\n";
    first = false;
    out += fmt::format("{}: {}", a.matrix.configuration.name(), a.configuration_reason);
    if (a.regular.verdict != SmoothnessVerdict::c1)
      out += fmt::format("; regular rules {} (above)", to_string(a.regular.verdict));
    out += "\n";
  }
  return out;
}

std::string analysis_json(std::string_view scheme, const std::vector<ConfigurationAnalysis>& results) {
  nlohmann::json doc;
  doc["scheme"] = std::string(scheme);
  nlohmann::json configurations = nlohmann::json::array();
  for (const ConfigurationAnalysis& a : results) configurations.push_back(configuration_json(a));
  doc["configurations"] = configurations;
  return doc.dump(2) + "\n";
}

namespace {

std::string format_vector(const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out += fmt::format("{}{:.6g}", i ? " " : "", std::abs(v[i]) < 1e-12 ? 0.0 : v[i]);
  return out;
}

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

}  // namespace

std::string format_curve_analysis(std::string_view scheme, const CurveAnalysis& a) {
  std::string out = fmt::format("scheme {} (curve)\n", scheme);
  out += fmt::format("masks over {} points; eigenvalues over {}:", a.S.rows(), a.wide_S.rows());
  for (const std::complex<double>& z : a.spectrum.expanded()) out += " " + format_complex(z);
  out += "\n";
  out += fmt::format("verdict: {} ({})\n", to_string(a.verdict), a.reason);
  if (a.leading.size() > 2 && a.c1) {
    const double l1 = a.leading[1].real();
    out += fmt::format("curvature: |lambda_2| = {:.6g} {} lambda_1^2 = {:.6g}\n", std::abs(a.leading[2]),
                       std::abs(a.leading[2]) < l1 * l1 - 1e-12   ? "<"
                       : std::abs(a.leading[2]) > l1 * l1 + 1e-12 ? ">"
                                                                  : "=",
                       l1 * l1);
  }
  if (a.limit_mask) out += "limit mask: " + format_vector(*a.limit_mask) + "\n";
  if (a.tangent_mask) out += "tangent mask: " + format_vector(*a.tangent_mask) + "\n";
  return out;
}

std::string curve_analysis_json(std::string_view scheme, const CurveAnalysis& a) {
  nlohmann::json j;
  j["scheme"] = std::string(scheme);
  j["curve"] = true;
  j["matrix_size"] = a.S.rows();
  nlohmann::json values = nlohmann::json::array();
  for (const std::complex<double>& z : a.spectrum.expanded()) values.push_back({{"re", z.real()}, {"im", z.imag()}});
  j["eigenvalues"] = values;
  j["verdict"] = to_string(a.verdict);
  j["reason"] = a.reason;
  j["regular"] = regular_json(a.regular);
  if (a.limit_mask) j["limit_mask"] = as_vector(*a.limit_mask);
  if (a.tangent_mask) j["tangent_mask"] = as_vector(*a.tangent_mask);
  return j.dump(2) + "\n";
}

}  // namespace subdiv::cli

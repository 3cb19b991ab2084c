#include "compare_page.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "embedded_page.h"
#include "subdiv/core/error.h"

namespace subdiv::compare {

namespace {

// Base64 of the bytes of `values` (little-endian on every supported host,
// as JavaScript's typed arrays read them on the same hosts).
template <typename T>
std::string base64(const std::vector<T>& values) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  const std::size_t n = values.size() * sizeof(T);
  std::string out;
  out.reserve((n + 2) / 3 * 4);
  for (std::size_t i = 0; i < n; i += 3) {
    const std::uint32_t b0 = bytes[i];
    const std::uint32_t b1 = i + 1 < n ? bytes[i + 1] : 0U;
    const std::uint32_t b2 = i + 2 < n ? bytes[i + 2] : 0U;
    const std::uint32_t word = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(word >> 18) & 63U];
    out += kAlphabet[(word >> 12) & 63U];
    out += i + 1 < n ? kAlphabet[(word >> 6) & 63U] : '=';
    out += i + 2 < n ? kAlphabet[word & 63U] : '=';
  }
  return out;
}

std::string data_url(std::string_view script) {
  return "data:text/javascript;base64," + base64(std::vector<char>(script.begin(), script.end()));
}

std::vector<float> float_positions(const PolygonMesh& mesh) {
  std::vector<float> out;
  out.reserve(mesh.positions.size() * 3);
  for (const Vec3& p : mesh.positions)
    out.insert(out.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  return out;
}

// The faces drawn (not holes) as fans of triangles, and their edges once each.
std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> triangles_and_edges(const PolygonMesh& mesh) {
  if (mesh.vertex_count() >= std::numeric_limits<std::int32_t>::max())
    throw InvalidInputError("too many vertices for the page: " + std::to_string(mesh.vertex_count()));
  std::vector<char> hole(static_cast<std::size_t>(mesh.face_count()), 0);
  for (const Index f : mesh.tags.holes)
    if (f >= 0 && f < mesh.face_count()) hole[static_cast<std::size_t>(f)] = 1;
  std::vector<std::uint32_t> triangles;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (Index f = 0; f < mesh.face_count(); ++f) {
    if (hole[static_cast<std::size_t>(f)]) continue;
    const auto face = mesh.face(f);
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      triangles.insert(triangles.end(), {static_cast<std::uint32_t>(face[0]), static_cast<std::uint32_t>(face[i]),
                                         static_cast<std::uint32_t>(face[i + 1])});
    for (std::size_t i = 0; i < face.size(); ++i) {
      const auto a = static_cast<std::uint32_t>(face[i]);
      const auto b = static_cast<std::uint32_t>(face[(i + 1) % face.size()]);
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<std::uint32_t> flat;
  flat.reserve(2 * edges.size());
  for (const auto& [a, b] : edges) flat.insert(flat.end(), {a, b});
  return {std::move(triangles), std::move(flat)};
}

// JSON placed inside a <script> element: every '<' (which JSON holds only
// inside strings) as \u003c, so that no "</script" or "<!--" ends it.
std::string script_safe_json(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

std::string html_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// The template with each @NAME@ replaced by its value, in one pass (so that
// values holding '@' are left as they are).
std::string filled(std::string_view page, const std::vector<std::pair<std::string_view, std::string>>& values) {
  std::string out;
  std::size_t at = 0;
  while (at < page.size()) {
    const std::size_t open = page.find('@', at);
    if (open == std::string_view::npos) break;
    const std::size_t close = page.find('@', open + 1);
    if (close == std::string_view::npos) break;
    const std::string_view name = page.substr(open + 1, close - open - 1);
    const auto value = std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == name; });
    if (value == values.end()) {
      out.append(page.substr(at, open + 1 - at));
      at = open + 1;
      continue;
    }
    out.append(page.substr(at, open - at));
    out += value->second;
    at = close + 1;
  }
  out.append(page.substr(std::min(at, page.size())));
  return out;
}

}  // namespace

std::string comparison_page(const std::string& title, const PolygonMesh& cage, const std::vector<Panel>& panels) {
  nlohmann::json data;
  // The camera frames the cage's bounding sphere (every panel refines it).
  Vec3 low{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Vec3 high = -1.0 * low;
  for (const Vec3& p : cage.positions) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const Vec3 centre = cage.positions.empty() ? Vec3{} : 0.5 * (low + high);
  double radius = 0.0;
  for (const Vec3& p : cage.positions) radius = std::max(radius, norm(p - centre));
  data["centre"] = {centre.x, centre.y, centre.z};
  data["radius"] = radius;
  data["cage"] = {{"positions", base64(float_positions(cage))}, {"edges", base64(triangles_and_edges(cage).second)}};
  data["panels"] = nlohmann::json::array();
  for (const Panel& panel : panels) {
    const auto [triangles, edges] = triangles_and_edges(panel.mesh);
    if (triangles.empty()) throw InvalidInputError(panel.title + ": no face to draw");
    data["panels"].push_back({{"title", panel.title},
                              {"caption", panel.caption},
                              {"positions", base64(float_positions(panel.mesh))},
                              {"triangles", base64(triangles)},
                              {"edges", base64(edges)}});
  }
  const nlohmann::json imports = {
      {"imports", {{"three", data_url(kThreeModule)}, {"three/addons/controls/OrbitControls.js", data_url(kOrbitControls)}}}};
  return filled(kPageHtml, {{"TITLE", html_escaped(title)},
                            {"IMPORTMAP", imports.dump()},
                            {"DATA", script_safe_json(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))},
                            {"SCRIPT", std::string(kPageScript)}});
}

}  // namespace subdiv::compare

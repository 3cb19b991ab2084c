// Composite schemes: an upsampling and averaging operators, composed into
// the vertex masks of one smoothing step (rules/composite.h).
//
// Sources: P. Oswald, P. Schroeder, "Composite primal/dual sqrt3-subdivision
// schemes", CAGD 20(3), 2003 (the idea: upsampling, then a cascade of
// averages); the operator set and the presets' coefficients as OpenMesh's
// CompositeT documents them (../shared/notes/rules-found.md). The
// operators' definitions here are written from their descriptions, on
// closed triangle meshes: every average has weights summing to one, and the
// upsampling by zeros (old vertices times the split's arity squared, new
// vertices 0) is what makes the composition affine again. The presets are
// checked against the native schemes (tests/rules/composite_test.cpp).

#include "subdiv/rules/composite.h"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <unordered_map>

#include "subdiv/core/error.h"
#include "subdiv/rules/linear.h"

namespace subdiv {

double CompositeCoefficient::at(int n) const noexcept {
  switch (kind) {
    case Kind::none: return 0.0;
    case Kind::constant: return value;
    case Kind::loop: {
      const double a = 1.5 + std::cos(2.0 * std::numbers::pi / n);
      return 0.5 * a * a - 1.0;
    }
    case Kind::sqrt3: return 2.0 / 3.0 * (1.0 + std::cos(2.0 * std::numbers::pi / n));
  }
  return 0.0;
}

bool is_composite_spec(std::string_view name) noexcept { return name.starts_with("composite:"); }

namespace {

constexpr std::string_view kCitation =
    "P. Oswald, P. Schroeder: Composite primal/dual sqrt3-subdivision schemes, CAGD 20(3), 2003; operators as "
    "OpenMesh's CompositeT";

// --- parsing ----------------------------------------------------------------

struct OperatorKind {
  std::string_view name;
  CompositeElement from, to;
  bool coefficient;
};

constexpr OperatorKind kOperators[] = {
    {"VF", CompositeElement::vertex, CompositeElement::face, false},
    {"FF", CompositeElement::face, CompositeElement::face, false},
    {"FFc", CompositeElement::face, CompositeElement::face, true},
    {"FV", CompositeElement::face, CompositeElement::vertex, false},
    {"FVc", CompositeElement::face, CompositeElement::vertex, true},
    {"VV", CompositeElement::vertex, CompositeElement::vertex, false},
    {"VVc", CompositeElement::vertex, CompositeElement::vertex, true},
    {"VE", CompositeElement::vertex, CompositeElement::edge, false},
    {"VdE", CompositeElement::vertex, CompositeElement::edge, false},
    {"VdEc", CompositeElement::vertex, CompositeElement::edge, true},
    {"EV", CompositeElement::edge, CompositeElement::vertex, false},
    {"EVc", CompositeElement::edge, CompositeElement::vertex, true},
    {"EF", CompositeElement::edge, CompositeElement::face, false},
    {"FE", CompositeElement::face, CompositeElement::edge, false},
    {"EdE", CompositeElement::edge, CompositeElement::edge, false},
    {"EdEc", CompositeElement::edge, CompositeElement::edge, true},
};

const char* element_name(CompositeElement e) {
  switch (e) {
    case CompositeElement::vertex: return "vertices";
    case CompositeElement::edge: return "edges";
    case CompositeElement::face: return "faces";
  }
  return "?";
}

CompositeCoefficient parse_coefficient(std::string_view text, const std::string& where) {
  CompositeCoefficient c;
  if (text == "loop") c.kind = CompositeCoefficient::Kind::loop;
  else if (text == "sqrt3") c.kind = CompositeCoefficient::Kind::sqrt3;
  else {
    c.kind = CompositeCoefficient::Kind::constant;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), c.value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(c.value))
      throw ParameterError(where + ": the coefficient '" + std::string(text) +
                           "' is not a number, 'loop' or 'sqrt3'");
  }
  return c;
}

CompositeOperator parse_operator(std::string_view token, const std::string& where) {
  std::string_view name = token, argument;
  const auto open = token.find('(');
  if (open != std::string_view::npos) {
    if (!token.ends_with(")")) throw ParameterError(where + ": '" + std::string(token) + "' lacks its closing ')'");
    name = token.substr(0, open);
    argument = token.substr(open + 1, token.size() - open - 2);
  }
  for (const OperatorKind& k : kOperators) {
    if (k.name != name) continue;
    if (k.coefficient != (open != std::string_view::npos))
      throw ParameterError(where + ": " + std::string(name) +
                           (k.coefficient ? " takes a coefficient, as " + std::string(name) + "(0.5)"
                                          : " takes no coefficient"));
    CompositeOperator op{std::string(name), k.from, k.to, {}};
    if (k.coefficient) op.c = parse_coefficient(argument, where + ": " + std::string(name));
    return op;
  }
  throw ParameterError(where + ": unknown operator '" + std::string(name) +
                       "' (upsampling Tvv3 or Tvv4 first, then VF, FF, FFc, FV, FVc, VV, VVc, VE, VdE, VdEc, EV, EVc, "
                       "EF, FE, EdE, EdEc)");
}

std::shared_ptr<const CompositeProgram> parse(std::string_view spec) {
  auto program = std::make_shared<CompositeProgram>();
  program->spec = std::string(spec);
  const std::string where = "scheme '" + program->spec + "'";
  if (!is_composite_spec(spec)) throw ParameterError(where + ": a composite scheme starts with 'composite:'");
  std::string_view rest = spec.substr(std::string_view("composite:").size());
  std::vector<std::string_view> tokens;
  while (true) {
    const auto comma = rest.find(',');
    tokens.push_back(rest.substr(0, comma));
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (tokens.front() == "Tvv4") {
    program->split = SplitRule::triangle;
    program->upsampling = 4.0;
  } else if (tokens.front() == "Tvv3") {
    program->split = SplitRule::sqrt3;
    program->upsampling = 3.0;
  } else {
    throw ParameterError(where + ": it starts with an upsampling, Tvv3 (the sqrt3 split) or Tvv4 (the triangle split), "
                         "not '" + std::string(tokens.front()) + "'");
  }
  CompositeElement state = CompositeElement::vertex;
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    if (tokens[i].empty()) throw ParameterError(where + ": an empty operator (two commas, or one at the end)");
    CompositeOperator op = parse_operator(tokens[i], where);
    if (op.from != state)
      throw ParameterError(where + ": " + op.name + " reads " + element_name(op.from) + ", but the values are on " +
                           element_name(state) + " there");
    state = op.to;
    program->operators.push_back(std::move(op));
  }
  if (program->operators.empty()) throw ParameterError(where + ": no averaging operator after the upsampling");
  if (state != CompositeElement::vertex)
    throw ParameterError(where + ": the sequence ends on " + element_name(state) + "; it must end on vertices");
  return program;
}

// --- composing the averages -------------------------------------------------

// A value as a combination of the split mesh's vertices (their values after
// the upsampling); entries sorted by vertex, one per vertex.
using Combination = std::vector<std::pair<Index, double>>;

void add_scaled(Combination& out, const Combination& in, double w) {
  for (const auto& [v, x] : in) out.emplace_back(v, w * x);
}

void merge(Combination& c) {
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (n > 0 && c[n - 1].first == c[i].first) c[n - 1].second += c[i].second;
    else c[n++] = c[i];
  }
  c.resize(n);
}

// The values of every element after k operators, computed on demand and
// kept: value(k, kind, x) reads value(k - 1, ...) of its neighbours.
class Composer {
 public:
  Composer(const MeshTopology& t, const CompositeProgram& program, const SplitMap& split)
      : t_(t), program_(program), split_(split) {}

  std::size_t kept() const noexcept { return memo_.size(); }

  const Combination& value(std::size_t k, CompositeElement kind, Index x) {
    const std::uint64_t key = (static_cast<std::uint64_t>(k) * 3 + static_cast<std::uint64_t>(kind)) << 40 |
                              static_cast<std::uint64_t>(x);
    if (auto it = memo_.find(key); it != memo_.end()) return it->second;
    Combination c = compute(k, x);
    merge(c);
    return memo_.emplace(key, std::move(c)).first->second;
  }

 private:
  // The upsampled values: old vertices (the split's vertex points) times the
  // factor, new vertices zero.
  Combination upsampled(Index v) const {
    if (v < split_.vertex_points) return {};
    return {{v, program_.upsampling}};
  }

  Index face_across(Index c) const {
    const Index across = t_.corner_across(c);
    return across == kInvalidIndex ? kInvalidIndex : t_.corner_face(across);
  }

  // Mean of value(k, from, x) over xs.
  Combination mean(std::size_t k, CompositeElement from, const std::vector<Index>& xs) {
    Combination out;
    if (xs.empty()) return out;
    for (const Index x : xs) add_scaled(out, value(k, from, x), 1.0 / static_cast<double>(xs.size()));
    return out;
  }

  // (1 - c) `neighbours` + c times x's own value after `in` operators: the
  // c-variants (FFc, VVc, EdEc) of the plain means.
  Combination blend_with_own(Combination neighbours, std::size_t in, CompositeElement from, Index x, double c) {
    for (auto& e : neighbours) e.second *= 1.0 - c;
    add_scaled(neighbours, value(in, from, x), c);
    return neighbours;
  }

  // The kind of element x is the one operator k writes (vertices for k = 0).
  Combination compute(std::size_t k, Index x) {
    if (k == 0) return upsampled(x);
    const CompositeOperator& op = program_.operators[k - 1];
    const std::size_t in = k - 1;
    std::vector<Index> xs;
    auto face_corners = [&](Index f) {
      std::vector<Index> cs;
      for (Index c = t_.face_first_corner(f); c < t_.face_first_corner(f) + t_.face_size(f); ++c) cs.push_back(c);
      return cs;
    };
    const std::string& n = op.name;
    if (n == "VF") {
      for (const Index v : t_.face_vertices(x)) xs.push_back(v);
      return mean(in, op.from, xs);
    }
    if (n == "EF") {
      for (const Index c : face_corners(x)) xs.push_back(t_.corner_edge(c));
      return mean(in, op.from, xs);
    }
    if (n == "FF" || n == "FFc") {
      for (const Index c : face_corners(x))
        if (const Index f = face_across(c); f != kInvalidIndex) xs.push_back(f);
      Combination out = mean(in, op.from, xs);
      if (n == "FF") return out;
      return blend_with_own(std::move(out), in, op.from, x, op.c.at(t_.face_size(x)));
    }
    if (n == "FV") {
      for (const Index c : t_.vertex_corners(x)) xs.push_back(t_.corner_face(c));
      return mean(in, op.from, xs);
    }
    if (n == "EV") {
      for (const Index e : t_.vertex_edges(x)) xs.push_back(e);
      return mean(in, op.from, xs);
    }
    if (n == "VV" || n == "VVc") {
      for (const Index e : t_.vertex_edges(x)) xs.push_back(t_.other_vertex(e, x));
      Combination out = mean(in, op.from, xs);
      if (n == "VV") return out;
      return blend_with_own(std::move(out), in, op.from, x, op.c.at(t_.valence(x)));
    }
    if (n == "FVc" || n == "EVc") {
      // Per face F at x (its corner c): F or its edge leaving x, weighted c;
      // the flap across the edge opposite x, or that edge, 1 - c.
      const auto corners = t_.vertex_corners(x);
      const double c = op.c.at(t_.valence(x));
      Combination out;
      const double share = corners.empty() ? 0.0 : 1.0 / static_cast<double>(corners.size());
      for (const Index corner : corners) {
        const Index opposite = t_.corner_next(corner);  // its outgoing edge is the one opposite x
        if (n == "EVc") {
          add_scaled(out, value(in, op.from, t_.corner_edge(corner)), share * c);
          add_scaled(out, value(in, op.from, t_.corner_edge(opposite)), share * (1.0 - c));
          continue;
        }
        const Index face = t_.corner_face(corner), flap = face_across(opposite);
        if (flap == kInvalidIndex) {
          add_scaled(out, value(in, op.from, face), share);
          continue;
        }
        add_scaled(out, value(in, op.from, face), share * c);
        add_scaled(out, value(in, op.from, flap), share * (1.0 - c));
      }
      return out;
    }
    if (n == "VE") {
      for (const Index v : t_.edge_vertices(x)) xs.push_back(v);
      return mean(in, op.from, xs);
    }
    if (n == "FE") {
      for (const Index c : t_.edge_corners(x)) xs.push_back(t_.corner_face(c));
      return mean(in, op.from, xs);
    }
    if (n == "VdE") {
      for (const Index v : t_.edge_vertices(x)) xs.push_back(v);
      for (const Index c : t_.edge_corners(x)) xs.push_back(t_.corner_vertex(t_.corner_prev(c)));
      return mean(in, op.from, xs);
    }
    if (n == "VdEc") {
      // c on each end and (1/2 - c) on each opposite vertex; an edge without
      // two faces (only at the analysis's outer boundary) takes its ends' mean.
      const auto sides = t_.edge_corners(x);
      const auto ends = t_.edge_vertices(x);
      if (sides.size() != 2) return mean(in, op.from, {ends[0], ends[1]});
      const double c = op.c.at(2);
      Combination out;
      for (const Index v : ends) add_scaled(out, value(in, op.from, v), c);
      for (const Index s : sides) add_scaled(out, value(in, op.from, t_.corner_vertex(t_.corner_prev(s))), 0.5 - c);
      return out;
    }
    if (n == "EdE" || n == "EdEc") {
      for (const Index s : t_.edge_corners(x)) {
        xs.push_back(t_.corner_edge(t_.corner_next(s)));
        xs.push_back(t_.corner_edge(t_.corner_prev(s)));
      }
      Combination out = mean(in, op.from, xs);
      if (n == "EdE") return out;
      return blend_with_own(std::move(out), in, op.from, x, op.c.at(2));
    }
    throw ParameterError(program_.spec + ": operator " + n + " has no definition");
  }

  const MeshTopology& t_;
  const CompositeProgram& program_;
  const SplitMap& split_;
  std::unordered_map<std::uint64_t, Combination> memo_;
};

// The composer of this thread for this level: neighbouring vertices share
// most intermediate averages, so one composer serves a level's vertices
// (LevelView::level_id tells levels apart; a view without one gets a fresh
// composer). Its memo is dropped once it holds kMostKept values, which
// bounds the memory a large level takes.
Composer& composer_for(const LevelView& level, const CompositeProgram& program) {
  constexpr std::size_t kMostKept = std::size_t{1} << 12;
  thread_local std::uint64_t id = 0;
  thread_local std::unique_ptr<Composer> composer;
  if (level.level_id == 0 || level.level_id != id || !composer || composer->kept() > kMostKept) {
    composer = std::make_unique<Composer>(level.topology, program, *level.level_split);
    id = level.level_id;
  }
  return *composer;
}

const CompositeProgram& program_of(const LevelView& level) {
  const auto* parameters = std::get_if<CompositeParameters>(&level.parameters);
  if (!parameters || !parameters->program) throw ParameterError("a composite step without its program");
  return *parameters->program;
}

// The smoothing step's vertex mask: the averages composed over the split
// mesh (level.topology), the split's old vertices upsampled. On a closed
// level the weights must sum to one; the ring meshes of the analysis have
// an outer boundary, beyond the neighbourhood it reads, where they need not.
void averaged_vertex(const LevelView& level, Index v, VertexRule, MaskBuilder& mask) {
  const CompositeProgram& program = program_of(level);
  if (!level.level_split) throw ParameterError(program.spec + ": its averages need the level's split");
  Composer& composer = composer_for(level, program);
  const Combination& c = composer.value(program.operators.size(), CompositeElement::vertex, v);
  double sum = 0.0;
  for (const auto& [u, w] : c) {
    mask.add(u, w);
    sum += w;
  }
  if (std::fabs(sum - 1.0) > 1e-9 && level.topology.boundary_loops().empty())
    throw ParameterError("scheme '" + program.spec + "': its weights sum to " + std::to_string(sum) + " at a vertex of valence " +
                         std::to_string(level.topology.valence(v)) +
                         ", not 1: the averages after the upsampling must reach the old vertices evenly");
}

// Tvv3's split with affine placeholder points (the averages read only the
// old vertices): face centroids, old vertices kept.
void centroid_point(const LevelView& level, Index f, MaskBuilder& mask) {
  const auto vs = level.topology.face_vertices(f);
  for (const Index v : vs) mask.add(v, 1.0 / static_cast<double>(vs.size()));
}
void kept_vertex(const LevelView&, Index v, VertexRule, MaskBuilder& mask) { mask.add(v, 1.0); }
void end_point(const LevelView&, Index, Index v, MaskBuilder& mask) { mask.add(v, 1.0); }

const Scheme& sqrt3_upsampling() {
  static const Scheme scheme{.name = "Tvv3",
                             .summary = "the sqrt3 split, face centroids as placeholders",
                             .split = SplitRule::sqrt3,
                             .masks = {.face_point = centroid_point, .vertex_point = kept_vertex,
                                       .boundary_point = end_point}};
  return scheme;
}

std::vector<Scheme> steps_of(const SchemeParameters& parameters) {
  const auto& program = *std::get<CompositeParameters>(parameters).program;
  Scheme averages{.name = "composite averages",
                  .summary = "the averaging operators of a composite scheme, composed",
                  .split = SplitRule::identity,
                  .masks = {.vertex_point = averaged_vertex},
                  .parameters = parameters};
  return {program.split == SplitRule::sqrt3 ? sqrt3_upsampling() : linear_scheme(), std::move(averages)};
}

Scheme make_scheme(std::shared_ptr<const CompositeProgram> program, std::string_view name, std::string_view summary) {
  const int operators = static_cast<int>(program->operators.size());
  Scheme scheme{.name = name,
                .summary = summary,
                .citation = kCitation,
                .split = program->split,
                .traits = {.needs_triangles = true,
                           .needs_closed_mesh = true,
                           .period = program->split == SplitRule::sqrt3 ? 2 : 1,
                           .analysis_rings = (operators + 1) / 2},
                .steps = steps_of,
                .parameters = CompositeParameters{std::move(program)}};
  return scheme;
}

}  // namespace

const Scheme& composite_scheme(std::string_view spec) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<Scheme>, std::less<>> made;
  const std::lock_guard lock(mutex);
  if (auto it = made.find(spec); it != made.end()) return *it->second;
  auto program = parse(spec);
  const std::string_view name = program->spec;  // owned by the program, which the scheme keeps
  auto scheme = std::make_unique<Scheme>(make_scheme(program, name, "composite scheme (user-defined averages)"));
  return *made.emplace(std::string(spec), std::move(scheme)).first->second;
}

const Scheme& composite_loop_scheme() {
  static const Scheme scheme = make_scheme(parse("composite:Tvv4,VdE,EVc(loop),VdE,EVc(loop)"), "composite-loop",
                                           "composite: Tvv4, VdE, EVc(loop), VdE, EVc(loop); Loop's scheme as averages");
  return scheme;
}

const Scheme& composite_sqrt3_scheme() {
  static const Scheme scheme =
      make_scheme(parse("composite:Tvv3,VF,FF,FVc(sqrt3),VF,FF,FVc(sqrt3)"), "composite-sqrt3",
                  "composite: Tvv3, then two primal/dual cycles VF, FF, FVc(sqrt3); C1 at valences 3..16 (the "
                  "project's reading of Oswald and Schroeder)");
  return scheme;
}

const Scheme& composite_sqrt3_kobbelt_scheme() {
  static const Scheme scheme = make_scheme(parse("composite:Tvv3,VF,FF,FVc(sqrt3)"), "composite-sqrt3-kobbelt",
                                           "composite: Tvv3, VF, FF, FVc(sqrt3); Kobbelt's sqrt3 as averages");
  return scheme;
}

}  // namespace subdiv

// Closest points: samples on a uniform grid of cells give each query its
// candidate ptex faces and starting parameters; a projected Newton iteration
// on the squared distance then converges inside each candidate face.

#include "subdiv/eval/closest_point.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "subdiv/core/error.h"
#include "tessellation_grid.h"

namespace subdiv {

namespace {

constexpr int kMaxCandidates = 16;
constexpr int kMaxNewtonSteps = 50;
constexpr long long kMaxRing = 8;  // cells searched around a query before all samples are

struct Sample {
  Vec3 position;
  SurfaceLocation location;
};

// Samples bucketed in cubic cells of a uniform grid.
class SampleGrid {
 public:
  explicit SampleGrid(std::vector<Sample> samples) : samples_(std::move(samples)) {
    lo_ = hi_ = samples_.front().position;
    for (const Sample& s : samples_)
      for (int a = 0; a < 3; ++a) {
        lo_[a] = std::min(lo_[a], s.position[a]);
        hi_[a] = std::max(hi_[a], s.position[a]);
      }
    // About two samples per cell over the box's volume, never degenerate.
    const double extent = std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z, 1e-300});
    cell_ = std::max(extent / std::cbrt(static_cast<double>(samples_.size()) / 2.0), extent * 1e-9);
    for (std::size_t i = 0; i < samples_.size(); ++i) cells_[key(cell_of(samples_[i].position))].push_back(i);
  }

  // The samples within `factor` times the nearest sample's distance to p,
  // nearest first: rings of cells around p's cell while a ring can still
  // hold a nearer one; every sample where p lies outside the box or the
  // rings grow wide (sparse surfaces).
  std::vector<const Sample*> nearest(Vec3 p, double factor) const {
    std::vector<const Sample*> found;
    double best = std::numeric_limits<double>::infinity();
    const auto take = [&](const Sample& s) {
      found.push_back(&s);
      best = std::min(best, norm(s.position - p));
    };
    bool searched = false;
    if (inside_box(p)) {
      const std::array<long long, 3> centre = cell_of(p);
      for (long long ring = 0; ring <= kMaxRing; ++ring) {
        for (long long dx = -ring; dx <= ring; ++dx)
          for (long long dy = -ring; dy <= ring; ++dy)
            for (long long dz = -ring; dz <= ring; ++dz) {
              if (std::max({std::llabs(dx), std::llabs(dy), std::llabs(dz)}) != ring) continue;
              const auto it = cells_.find(key({centre[0] + dx, centre[1] + dy, centre[2] + dz}));
              if (it == cells_.end()) continue;
              for (const std::size_t i : it->second) take(samples_[i]);
            }
        // Cells beyond this ring are at least ring cells away from p.
        if (std::isfinite(best) && static_cast<double>(ring) * cell_ >= factor * best) {
          searched = true;
          break;
        }
      }
    }
    if (!searched) {
      found.clear();
      best = std::numeric_limits<double>::infinity();
      for (const Sample& s : samples_) take(s);
    }
    std::erase_if(found, [&](const Sample* s) { return norm(s->position - p) > factor * best; });
    std::sort(found.begin(), found.end(),
              [&](const Sample* a, const Sample* b) { return norm(a->position - p) < norm(b->position - p); });
    return found;
  }

 private:
  std::array<long long, 3> cell_of(Vec3 p) const {
    std::array<long long, 3> c{};
    for (int a = 0; a < 3; ++a) {
      const double x = std::clamp((p[a] - lo_[a]) / cell_, -1e9, 1e9);
      c[static_cast<std::size_t>(a)] = static_cast<long long>(std::floor(x));
    }
    return c;
  }
  bool inside_box(Vec3 p) const {
    for (int a = 0; a < 3; ++a)
      if (!(p[a] >= lo_[a] && p[a] <= hi_[a])) return false;
    return true;
  }
  static std::uint64_t key(std::array<long long, 3> c) {
    const auto bits = [](long long x) { return static_cast<std::uint64_t>(x + (1LL << 20)) & ((1ULL << 21) - 1); };
    return bits(c[0]) | bits(c[1]) << 21 | bits(c[2]) << 42;
  }

  std::vector<Sample> samples_;
  Vec3 lo_, hi_;
  double cell_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

double clamp_unit(double x) { return std::clamp(x, 0.0, 1.0); }

// (u, v) kept in the ptex face: the unit square, or the triangle.
void keep_inside(double& u, double& v, bool triangle) {
  u = clamp_unit(u);
  v = clamp_unit(v);
  if (triangle && u + v > 1.0) {
    const double excess = 0.5 * (u + v - 1.0);
    u = clamp_unit(u - excess);
    v = 1.0 - u;
  }
}

// Newton on f(u, v) = |S(u, v) - p|^2 / 2 from (u, v), projected into the
// face, with step halving until f decreases.
ClosestPoint descend(const LimitEvaluator& evaluator, Vec3 p, SurfaceLocation at) {
  const bool triangle = evaluator.triangles();
  LimitPoint s = evaluator.evaluate(at.face, at.u, at.v);
  double f = 0.5 * dot(s.position - p, s.position - p);
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    const Vec3 d = s.position - p;
    const double gu = dot(s.du, d), gv = dot(s.dv, d);
    const double huu = dot(s.du, s.du) + dot(s.duu, d), huv = dot(s.du, s.dv) + dot(s.duv, d),
                 hvv = dot(s.dv, s.dv) + dot(s.dvv, d);
    const double det = huu * hvv - huv * huv;
    double du = 0.0, dv = 0.0;
    if (huu > 0.0 && det > 0.0) {
      du = -(hvv * gu - huv * gv) / det;
      dv = -(huu * gv - huv * gu) / det;
    } else {  // not convex here: a gradient step of the Gauss-Newton scale
      const double scale = dot(s.du, s.du) + dot(s.dv, s.dv);
      if (!(scale > 0.0)) break;
      du = -gu / scale;
      dv = -gv / scale;
    }
    bool improved = false;
    for (double shrink = 1.0; shrink > 1e-6; shrink *= 0.5) {
      double u = at.u + shrink * du, v = at.v + shrink * dv;
      keep_inside(u, v, triangle);
      const LimitPoint trial = evaluator.evaluate(at.face, u, v);
      const double g = 0.5 * dot(trial.position - p, trial.position - p);
      if (g < f) {
        const double moved = std::abs(u - at.u) + std::abs(v - at.v);
        at.u = u;
        at.v = v;
        s = trial;
        f = g;
        improved = moved > 1e-15;
        break;
      }
    }
    if (!improved) break;
  }
  return {at, s.position, norm(s.position - p)};
}

}  // namespace

std::vector<ClosestPoint> closest_points(const PolygonMesh& mesh, const LimitEvaluator& evaluator,
                                         std::span<const Vec3> points, int samples_per_edge) {
  if (samples_per_edge < 2 || samples_per_edge > 64 || samples_per_edge % 2 != 0)
    throw InvalidInputError("closest points: samples per edge " + std::to_string(samples_per_edge) +
                            " is not an even number in [2, 64]");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i]))
      throw InvalidInputError("closest points: point " + std::to_string(i + 1) + " is not finite");
  if (points.empty()) return {};
  const detail::TessellationGrid grid = detail::tessellation_grid(mesh, evaluator, samples_per_edge);
  const std::vector<LimitPoint> sampled = evaluator.evaluate(grid.locations);
  std::vector<Sample> samples(sampled.size());
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = {sampled[i].position, grid.locations[i]};
  const SampleGrid cells(std::move(samples));

  std::vector<ClosestPoint> out(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 16), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      const Vec3 p = points[i];
      // One start per ptex face: its nearest sample.
      std::vector<const Sample*> starts;
      for (const Sample* s : cells.nearest(p, 1.5)) {
        if (std::none_of(starts.begin(), starts.end(),
                         [&](const Sample* t) { return t->location.face == s->location.face; }))
          starts.push_back(s);
        if (static_cast<int>(starts.size()) == kMaxCandidates) break;
      }
      ClosestPoint best{starts.front()->location, starts.front()->position, norm(starts.front()->position - p)};
      for (const Sample* s : starts) {
        const ClosestPoint c = descend(evaluator, p, s->location);
        if (c.distance < best.distance) best = c;
      }
      out[i] = best;
    }
  });
  return out;
}

}  // namespace subdiv

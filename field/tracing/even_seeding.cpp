#include "field/tracing/even_seeding.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>
#include <stdexcept>

#include "field/tracing/nearby_points.h"

namespace hsb {
namespace {

// The local separation and the order of seeds, both from the magnitude.
class Importance {
 public:
  Importance(const BodyLattice& pool, const EvenSeedingOptions& options)
      : options_(options), reference_(options.reference_magnitude.value_or(median_magnitude(pool))) {}

  double reference() const { return reference_; }
  bool active() const { return options_.importance && reference_ > 0.0; }

  // d(x) of the rule in even_seeding.h.
  double separation(double magnitude) const {
    if (!active()) return options_.separation;
    const double ratio = magnitude > 0.0 ? std::sqrt(reference_ / magnitude) : kSparsest;
    return options_.separation * std::clamp(ratio, kDensest, kSparsest);
  }

  // Half-octave bands of magnitude, the largest first (0 for the median).
  int band(double magnitude) const {
    if (!active()) return 0;
    if (!(magnitude > 0.0)) return kBands + 1;
    return -std::clamp(int(std::floor(2.0 * std::log2(magnitude / reference_))), -kBands, kBands);
  }

 private:
  static constexpr double kDensest = 0.5, kSparsest = 2.0;
  static constexpr int kBands = 4;
  const EvenSeedingOptions& options_;
  double reference_ = 0.0;
};

// isolated: a seed whose trajectory would be a single point (a degenerate
// or weak spot), offered again after every other seed, so a field's
// isotropic parts get their lone glyphs only where no line passes.
enum class Origin { given = 0, neighbour = 1, pool = 2, isolated = 3 };

struct Candidate {
  Vec3 point;
  double magnitude;
  Origin origin;
  int band;
  std::size_t order;  // first come, first taken
};

// The seed taken first sorts last (std::priority_queue takes the largest).
struct TakenLater {
  bool operator()(const Candidate& a, const Candidate& b) const {
    const auto rank = [](const Candidate& c) {
      return std::make_tuple(c.origin == Origin::isolated, c.origin != Origin::given, c.band, int(c.origin), c.order);
    };
    return rank(a) > rank(b);
  }
};

// Cuts each half of `t` where it comes back within `radius` of its own
// earlier part (more than four radii of arc away, so a curve's own
// neighbouring points never count): a closed tensor line becomes one ring.
// A forward half that comes back to its seed is that ring whole, closed
// at the seed (its backward half would go round again); cut there as
// anywhere else, it stopped a radius short and left a gap in the ring.
void stop_at_own_approach(Trajectory& t, double radius) {
  NearbyPoints own(std::max(radius, 1e-300));
  const std::size_t seed = t.seed_index;
  own.add(t.points[seed], 0.0);
  const auto walk = [&](int direction) -> std::size_t {  // the index of the last point kept
    double arc = 0.0;
    std::size_t i = seed;
    for (;;) {
      const std::size_t next = direction > 0 ? i + 1 : i - 1;
      if (direction > 0 ? next >= t.points.size() : i == 0) return i;
      arc += (t.points[next] - t.points[i]).norm();
      const double tag = direction * arc;
      const double gap = 4.0 * radius;
      if (own.nearest(t.points[next], radius, [&](double other) { return std::fabs(other - tag) > gap; }) < radius)
        return i;
      own.add(t.points[next], tag);
      i = next;
    }
  };
  const std::size_t last = walk(+1);
  if (last + 1 < t.points.size()) {
    const Vec3 seed_point = t.points[seed];
    if ((t.points[last + 1] - seed_point).norm() < radius) {
      t.points.resize(last + 1);
      t.points.push_back(seed_point);
      t.points.erase(t.points.begin(), t.points.begin() + std::ptrdiff_t(seed));
      t.seed_index = 0;
      t.forward_stop = t.backward_stop = StopReason::closed;
      return;
    }
    t.points.resize(last + 1);
    t.forward_stop = StopReason::too_close;
  }
  const std::size_t first = walk(-1);
  if (first > 0) {
    t.points.erase(t.points.begin(), t.points.begin() + std::ptrdiff_t(first));
    t.seed_index -= first;
    t.backward_stop = StopReason::too_close;
  }
}

// Unit directions across the line with tangent `t` (or across nothing, for
// a line of one point: the axes).
std::vector<Vec3> across(const Vec3& t, const std::optional<Vec3>& plane_normal) {
  std::vector<Vec3> directions;
  if (t.squaredNorm() == 0.0) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 axis = Vec3::Unit(k);
      if (plane_normal && std::fabs(axis.dot(*plane_normal)) > 0.5) continue;
      directions.push_back(axis);
      directions.push_back(-axis);
    }
    return directions;
  }
  if (plane_normal) {
    const Vec3 side = plane_normal->cross(t);
    if (side.squaredNorm() > 0.0) {
      directions.push_back(side.normalized());
      directions.push_back(-side.normalized());
    }
    return directions;
  }
  const Vec3 u = t.unitOrthogonal(), v = t.cross(u).normalized();
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3.0;
    directions.push_back(std::cos(a) * u + std::sin(a) * v);
  }
  return directions;
}

}  // namespace

EvenTrajectories evenly_spaced_trajectories(const DirectionSampler& sampler, const MagnitudeSampler& magnitude,
                                            const std::vector<Vec3>& given, const BodyLattice& pool,
                                            const TrajectoryOptions& trajectory, const EvenSeedingOptions& options) {
  if (!(options.separation > 0.0) || !std::isfinite(options.separation))
    throw std::invalid_argument("even seeding: the separation must be finite and > 0");
  const Importance importance(pool, options);
  EvenTrajectories result;
  result.reference_magnitude = importance.reference();

  std::priority_queue<Candidate, std::vector<Candidate>, TakenLater> queue;
  std::size_t order = 0;
  const auto offer = [&](const Vec3& p, double m, Origin origin) {
    queue.push({p, m, origin, importance.band(m), order++});
  };
  for (const Vec3& p : given)
    if (const std::optional<double> m = magnitude(p)) offer(p, *m, Origin::given);
  for (std::size_t i = 0; i < pool.points.size(); ++i) offer(pool.points[i], pool.magnitudes[i], Origin::pool);

  NearbyPoints lines(options.separation);
  // A line keeps the separation it started with as it runs into sparser
  // parts (d(x) larger): a seed taken d from its neighbours must not find
  // its first step already "too close" by a larger d.
  double seed_separation = options.separation;
  const DirectionSampler stopping = [&](const Vec3& x) {
    DirectionSample s = sampler(x);
    if (!s.ok) return s;
    const double test = options.stop_ratio * std::min(seed_separation, importance.separation(s.magnitude));
    if (lines.nearest(x, test) < test) {
      s.ok = false;
      s.stop = StopReason::too_close;
    }
    return s;
  };

  while (!queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    const double d = importance.separation(c.magnitude);
    if (lines.nearest(c.point, d) < d) continue;
    if (result.trajectories.size() >= options.max_lines) {
      result.reached_max_lines = true;
      break;
    }
    seed_separation = d;
    Trajectory t = trace_directions(stopping, c.point, trajectory);
    if (t.points.size() < 2 && c.origin != Origin::isolated) {
      if (options.lone_glyphs) offer(c.point, c.magnitude, Origin::isolated);
      continue;
    }
    stop_at_own_approach(t, options.stop_ratio * importance.separation(c.magnitude));
    for (const Vec3& p : t.points) lines.add(p);

    // Seeds beside it, a local d across it, every d along it.
    double arc = 0.0, next = 0.0;
    for (std::size_t i = 0; i < t.points.size(); ++i) {
      if (i > 0) arc += (t.points[i] - t.points[i - 1]).norm();
      if (arc < next) continue;
      const std::optional<double> here = magnitude(t.points[i]);
      if (!here) continue;
      const double local = importance.separation(*here);
      next = arc + local;
      const Vec3 tangent = t.points.size() < 2 ? Vec3::Zero()
                                               : (t.points[std::min(i + 1, t.points.size() - 1)] -
                                                  t.points[i > 0 ? i - 1 : 0]).normalized();
      for (const Vec3& side : across(tangent, options.plane_normal)) {
        const Vec3 q = t.points[i] + local * side;
        if (const std::optional<double> m = magnitude(q)) offer(q, *m, Origin::neighbour);
      }
    }
    result.seeds.push_back(c.point);
    result.trajectories.push_back(std::move(t));
  }
  return result;
}

}  // namespace hsb

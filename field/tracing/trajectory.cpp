#include "field/tracing/trajectory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "field/sampling/field.h"
#include "field/tensor/eigensystem.h"
#include "field/tensor/tensor_measures.h"

namespace hsb {

double Trajectory::length() const {
  double total = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) total += (points[i] - points[i - 1]).norm();
  return total;
}

bool eigenvector_defined(const Vec3& l, EigenFamily family, double tolerance) {
  // An eigenvector is only defined while its eigenvalue is separated from
  // its neighbours in the ordering; λ1 ≥ λ2 ≥ λ3, so the nearest other
  // eigenvalue is always an adjacent one.
  const int k = static_cast<int>(family);
  double gap = std::numeric_limits<double>::infinity();
  if (k > 0) gap = std::min(gap, l(k - 1) - l(k));
  if (k < 2) gap = std::min(gap, l(k) - l(k + 1));
  const double scale = l.cwiseAbs().maxCoeff();
  return scale > 0.0 && gap >= tolerance * scale;
}

DirectionSample eigen_direction(const TensorField& field, const Vec3& x,
                                const TrajectoryOptions& options) {
  DirectionSample result;
  const std::optional<Sym3> s = field.sample(x);
  if (!s) {
    result.stop = StopReason::boundary;
    return result;
  }
  if (options.inside && !options.inside(x)) {
    result.stop = StopReason::left_region;
    return result;
  }
  if (s->frobenius_norm() < options.min_magnitude) {
    result.stop = StopReason::low_magnitude;
    return result;
  }

  const Eigensystem es = decompose(*s);
  const int k = static_cast<int>(options.family);
  const Vec3& l = es.values;
  if (options.measure && !(options.measure(l) >= options.min_measure)) {
    result.stop = StopReason::left_region;
    return result;
  }
  result.magnitude = options.family_magnitude ? std::fabs(l(k)) : l.cwiseAbs().maxCoeff();
  if (options.family_magnitude && std::fabs(l(k)) < options.min_family_value) {
    result.stop = StopReason::low_magnitude;
    return result;
  }
  if (options.tensorlines && l(0) > 0.0) {
    // Where e1 is undefined its weight c_l is (nearly) 0: no stop.
    result.linearity = westin_measures(l).linear;
    result.deflection = s->matrix() / l(0);
  } else if (!eigenvector_defined(l, options.family, options.degeneracy_tolerance)) {
    result.stop = StopReason::degenerate;
    return result;
  }

  result.ok = true;
  result.direction = es.vectors.col(k);
  return result;
}

DirectionSample flow_direction(const VectorField& field, const Vec3& x, const TrajectoryOptions& options) {
  DirectionSample result;
  const std::optional<Vec3> v = field.sample(x);
  if (!v) return result;  // stop: boundary
  if (options.inside && !options.inside(x)) {
    result.stop = StopReason::left_region;
    return result;
  }
  const double speed = v->norm();
  result.magnitude = speed;
  if (!(speed > 0.0) || speed < options.min_magnitude) {
    result.stop = StopReason::low_magnitude;
    return result;
  }
  result.ok = true;
  result.direction = *v / speed;
  return result;
}

namespace {

// Halving the step this many times puts the last point within about
// step·1e-6 of the domain boundary.
constexpr int kMaxHalvings = 20;

// Where a line ends on an edge (the domain's, or its region's) it creeps
// up to it by halving the step; elsewhere it ends at once.
bool is_edge(StopReason stop) { return stop == StopReason::boundary || stop == StopReason::left_region; }

struct HalfTrajectory {
  std::vector<Vec3> points;  // excluding the seed
  StopReason stop = StopReason::max_length;
};

// Integrates one direction from the seed. `first` is the (ok) sample at the
// seed, `sign` +1 forward or −1 backward.
HalfTrajectory trace_half(const DirectionSampler& sampler, const Vec3& seed,
                          const DirectionSample& first, double sign,
                          const TrajectoryOptions& options) {
  Vec3 travel = sign * first.direction;
  // A sample along the curve: an eigenvector turned to agree with the
  // direction of travel (it has no sign, and this is what keeps the curve
  // from turning back on itself); a flow's vector taken as it is, reversed
  // going backwards.
  const auto oriented = [&](const Vec3& v) -> Vec3 {
    if (options.signed_directions) return sign * v;
    return v.dot(travel) < 0.0 ? Vec3(-v) : v;
  };
  // The direction a sample sends the line in, arriving along v_in: the
  // eigenvector, or the tensorline's blend of it with v_in and D̂ v_in.
  const auto heading = [&](const DirectionSample& d, const Vec3& v_in) -> Vec3 {
    const Vec3 e = oriented(d.direction);
    if (!options.tensorlines || d.linearity >= 1.0) return e;
    const Vec3 v = d.linearity * e +
                   (1.0 - d.linearity) * ((1.0 - options.puncture) * v_in + options.puncture * (d.deflection * v_in));
    const double length = v.norm();
    return length > 1e-12 ? Vec3(v / length) : e;
  };
  HalfTrajectory half;
  const double min_step = options.step * std::ldexp(1.0, -kMaxHalvings);
  const double max_turn_cos = options.max_turn >= 180.0 ? -2.0 : std::cos(options.max_turn * M_PI / 180.0);
  Vec3 x = seed;
  DirectionSample at_x = first;  // always ok: the k1 of the next step
  double h = options.step;
  double travelled = 0.0;

  for (int steps = 0;;) {
    if (steps >= options.max_steps) {
      half.stop = StopReason::max_steps;
      return half;
    }
    // Land exactly on max_length. The slack keeps rounding in `travelled`
    // from leaving a last step of a few ulps.
    const double remaining = options.max_length - travelled;
    const bool last_step = remaining <= h * (1.0 + 1e-9);
    const double step = last_step ? remaining : h;
    if (step <= 0.0) {  // max_length = 0
      half.stop = StopReason::max_length;
      return half;
    }

    // RK4. The end point is sampled too: it is the next step's k1, and
    // sampling it here means every accepted point lies inside the domain.
    const Vec3 k1 = heading(at_x, travel);
    DirectionSample failed;
    Vec3 ks[3];
    const double offsets[3] = {0.5 * step, 0.5 * step, step};
    Vec3 previous = k1;
    bool ok = true;
    for (int stage = 0; stage < 3; ++stage) {
      const DirectionSample d = sampler(x + offsets[stage] * previous);
      if (!d.ok) {
        failed = d;
        ok = false;
        break;
      }
      ks[stage] = heading(d, previous);
      previous = ks[stage];
    }
    // A flow that turns back within one step has a stagnation point there
    // (a sink, or a source going backwards): with unit-speed steps the
    // curve would only oscillate across it. Stop short of it.
    if (ok && options.signed_directions &&
        (ks[0].dot(travel) < 0.0 || ks[1].dot(travel) < 0.0 || ks[2].dot(travel) < 0.0)) {
      half.stop = StopReason::low_magnitude;
      return half;
    }
    Vec3 x_new = x;
    DirectionSample at_new;
    if (ok) {
      x_new = x + (step / 6.0) * (k1 + 2.0 * ks[0] + 2.0 * ks[1] + ks[2]);
      at_new = sampler(x_new);
      if (!at_new.ok && is_edge(at_new.stop)) {
        failed = at_new;
        ok = false;
      }
    }

    if (!ok) {
      if (!is_edge(failed.stop)) {
        // A degenerate or weak region: the direction is meaningless from
        // here on, and shortening the step would not make it meaningful.
        half.stop = failed.stop;
        return half;
      }
      // Creep up on the edge instead of stopping a whole step short.
      h = 0.5 * step;
      if (h < min_step) {
        half.stop = failed.stop;
        return half;
      }
      continue;
    }

    const Vec3 delta = x_new - x;
    if (delta.norm() > 0.0 && delta.normalized().dot(travel) < max_turn_cos) {
      half.stop = StopReason::sharp_turn;
      return half;
    }
    if (delta.norm() > 0.0) travel = delta.normalized();
    x = x_new;
    half.points.push_back(x);
    travelled += step;
    ++steps;

    if (last_step) {
      half.stop = StopReason::max_length;
      return half;
    }
    if (!at_new.ok) {  // the new point is degenerate or weak: keep it, end there
      half.stop = at_new.stop;
      return half;
    }
    if (options.signed_directions && oriented(at_new.direction).dot(travel) < 0.0) {
      half.stop = StopReason::low_magnitude;  // stagnation just ahead, as above
      return half;
    }
    // A streamline back at its seed after going round: closed. (Only for
    // flows: a tensor line that comes back is rare, and flipping makes
    // "back" ambiguous.) Within half a step, and only once it has been
    // several steps away, so the first steps never count.
    if (options.signed_directions && travelled > 4.0 * options.step &&
        (x - seed).norm() < 0.5 * options.step) {
      half.stop = StopReason::closed;
      return half;
    }
    at_x = at_new;
    // Recover the full step after a boundary-induced halving, so grazing
    // the boundary does not leave the rest of the curve crawling.
    h = std::min(2.0 * h, options.step);
  }
}

}  // namespace

Trajectory trace_directions(const DirectionSampler& sampler, const Vec3& seed,
                            const TrajectoryOptions& options) {
  if (!(options.step > 0.0) || !std::isfinite(options.step))
    throw std::invalid_argument("trajectory: step must be finite and > 0");
  if (!(options.max_length >= 0.0))
    throw std::invalid_argument("trajectory: max_length must be >= 0");

  Trajectory result;
  result.family = options.family;
  result.points.push_back(seed);
  const DirectionSample first = sampler(seed);
  if (!first.ok) {
    result.backward_stop = result.forward_stop = first.stop;
    return result;
  }

  const bool forwards = options.direction != TraceDirection::backward;
  const HalfTrajectory forward = forwards ? trace_half(sampler, seed, first, 1.0, options) : HalfTrajectory{};
  // A closed curve is complete: going backwards would go round again.
  const bool backwards = options.direction != TraceDirection::forward && forward.stop != StopReason::closed;
  const HalfTrajectory backward = backwards ? trace_half(sampler, seed, first, -1.0, options) : HalfTrajectory{};

  result.points.assign(backward.points.rbegin(), backward.points.rend());
  result.seed_index = result.points.size();
  result.points.push_back(seed);
  result.points.insert(result.points.end(), forward.points.begin(), forward.points.end());
  result.backward_stop = backwards ? backward.stop : forward.stop == StopReason::closed ? StopReason::closed
                                                                                       : StopReason::max_length;
  result.forward_stop = forwards ? forward.stop : StopReason::max_length;
  return result;
}

Trajectory trace_trajectory(const TensorField& field, const Vec3& seed,
                            const TrajectoryOptions& options) {
  return trace_directions(
      [&](const Vec3& x) { return eigen_direction(field, x, options); }, seed, options);
}

Trajectory trace_streamline(const VectorField& field, const Vec3& seed, const TrajectoryOptions& options) {
  TrajectoryOptions signed_options = options;
  signed_options.signed_directions = true;
  return trace_directions([&](const Vec3& x) { return flow_direction(field, x, signed_options); }, seed,
                          signed_options);
}

}  // namespace hsb

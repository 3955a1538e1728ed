#pragma once
// Stress trajectories (tensor lines), curves tangent to one eigenvector
// family, dx/ds = e_k(x); and streamlines of a vector field, dx/ds = v/|v|.
// One integrator serves both (design §10): eigenvectors have no sign, so
// each sample is flipped to agree with the direction of travel; a flow's
// vectors are signed and never flipped, so a streamline never turns back
// at a sink.

#include <functional>
#include <vector>

#include "field/sampling/field.h"

namespace hsb {

enum class EigenFamily { major = 0, medium = 1, minor = 2 };

// Why one end of a trajectory stopped.
// too_close: evenly spaced seeding stopped it beside another trajectory
// (or its own earlier part). left_region: the measure the options keep
// above a floor fell below it (a fibre's edge, FA < 0.3), or the line left
// the mask. sharp_turn: the next step would have turned more than max_turn.
enum class StopReason {
  boundary, max_length, degenerate, low_magnitude, max_steps, closed, too_close, left_region, sharp_turn
};
constexpr std::size_t kStopReasons = 9;

// Which way from the seed a curve is traced.
enum class TraceDirection { both, forward, backward };

struct TrajectoryOptions {
  EigenFamily family = EigenFamily::major;
  double step = 0.01;        // RK4 step, in arc length
  double max_length = 10.0;  // per direction from the seed
  // Stop where the followed eigenvalue's gap to its nearest neighbour is
  // below this fraction of max|λ| (the eigenvector is undefined there).
  double degeneracy_tolerance = 1e-3;
  // Stop where the tensor's Frobenius norm falls below this (0: never).
  double min_magnitude = 0.0;
  int max_steps = 100000;  // per direction; a guard, not a control
  TraceDirection direction = TraceDirection::both;
  // Eigenvectors are sign-free; a flow's vectors are not (streamlines).
  bool signed_directions = false;
  // Tracing several families in one picture: each line's magnitude is its
  // own eigenvalue's |λ_k| (not max |λ|), and it stops where that falls
  // below this (a tension line ends where the tension fades; 0: never).
  bool family_magnitude = false;
  double min_family_value = 0.0;
  // The region lines stay in (a diffusion fibre's FA > 0.3): a measure of
  // the eigenvalues that must stay at or above `min_measure` (none:
  // anywhere). The line creeps up to where it falls below, as to the
  // domain's boundary, and stops there.
  std::function<double(const Vec3& eigenvalues)> measure;
  double min_measure = 0.0;
  // The mask lines stay in (region.mask; none: anywhere), with the same
  // creep up to its edge.
  std::function<bool(const Vec3& x)> inside;
  // The sharpest turn, in degrees, between one step and the next (a line
  // that would jump from one fibre bundle to another where they cross);
  // 180: no limit.
  double max_turn = 180.0;
  // Weinstein's tensorlines (Weinstein, Kindlmann and Lundberg 1999)
  // instead of the bare eigenvector, for the major family: each step goes
  //   v = c_l e1 + (1 − c_l)((1 − w) v_in + w D̂ v_in),  normalised,
  // with c_l Westin's linear measure, v_in the incoming direction and
  // D̂ = D/λ1. Where the tensor is linear (a fibre) that is e1; where it is
  // planar or isotropic (a crossing, a partial volume) e1 means nothing,
  // and the line goes on the way it came, bent by D towards the tensor's
  // plane by the puncture weight w (0: straight on; 1: deflected by D
  // alone). So a line crosses such a region instead of stopping at its
  // degenerate eigenvalues or turning into the other bundle.
  bool tensorlines = false;
  double puncture = 0.5;
};

struct Trajectory {
  // Ordered from the backward end through the seed to the forward end.
  std::vector<Vec3> points;
  EigenFamily family = EigenFamily::major;  // the eigenvector it follows (tensor lines)
  std::size_t seed_index = 0;
  StopReason backward_stop = StopReason::max_length;
  StopReason forward_stop = StopReason::max_length;

  double length() const;
  // Round a loop: its last point comes back to its first (both ends
  // stopped as `closed`), and glyphs go evenly round it with no seam.
  bool closed() const { return forward_stop == StopReason::closed && backward_stop == StopReason::closed; }
};

// What integration sees at one point: the followed eigenvector (unit,
// arbitrary sign), or the reason integration must stop there.
struct DirectionSample {
  bool ok = false;
  Vec3 direction = Vec3::Zero();
  StopReason stop = StopReason::boundary;
  // How strong the field is here (the largest |λ|, or a flow's speed):
  // evenly spaced seeding draws lines closer where it is large.
  double magnitude = 0.0;
  // For tensorlines: c_l and D/λ1 here (TrajectoryOptions::tensorlines).
  double linearity = 1.0;
  Mat3 deflection = Mat3::Zero();
};
using DirectionSampler = std::function<DirectionSample(const Vec3&)>;

// Whether `family`'s eigenvector is defined for eigenvalues l (λ1 ≥ λ2 ≥
// λ3): its eigenvalue stands apart from the adjacent ones by at least
// `tolerance` of the largest |λ|.
bool eigenvector_defined(const Vec3& l, EigenFamily family, double tolerance);

// The eigenvector of `options.family` at `x`: stops at the domain boundary,
// at degenerate eigenvalues, below the magnitude threshold and outside the
// options' region.
DirectionSample eigen_direction(const TensorField& field, const Vec3& x,
                                const TrajectoryOptions& options);

// The direction of the vector field at `x` (unit): stops at the domain
// boundary and where the speed falls below options.min_magnitude or to
// zero (stagnation).
DirectionSample flow_direction(const VectorField& field, const Vec3& x, const TrajectoryOptions& options);

// The integrator itself, over any direction sampler (tests feed it
// directions with deliberately random signs). With signed directions a
// curve that comes back to its seed (a closed streamline of a steady
// flow) stops there, closed, instead of running round again.
Trajectory trace_directions(const DirectionSampler& sampler, const Vec3& seed,
                            const TrajectoryOptions& options);

// Integrates both directions from `seed` with RK4. Every stage's sampled
// eigenvector is flipped to agree with the current direction of travel, so
// the arbitrary sign of eigenvectors never reverses the curve. A step that
// would leave the domain is shortened so the curve ends on the boundary.
// A seed outside the domain or at a stopping point gives a single point.
Trajectory trace_trajectory(const TensorField& field, const Vec3& seed,
                            const TrajectoryOptions& options);
// The same for a vector field: a streamline (signed directions).
Trajectory trace_streamline(const VectorField& field, const Vec3& seed, const TrajectoryOptions& options);

}  // namespace hsb

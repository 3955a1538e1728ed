#pragma once
// Evenly spaced trajectories: Jobard and Lefer's evenly spaced streamlines
// (1997) in three dimensions, as 3D-TSV does for stress lines (Wang et
// al. 2022), with a density that follows the field's magnitude.
//
// The rule, with d the separation:
//  - A seed is taken only where no trajectory passes within d of it; a
//    trajectory stops where it comes within ½ d of another (or of its own
//    earlier part: a hoop closes into one ring instead of winding on),
//    with d the smaller of its seed's and the local one.
//  - New seeds are taken beside each finished trajectory, d away across it
//    (six directions round it; two, in the plane, for a 2-D result), and
//    from a pool of points inside the body (body_lattice.h), so the body
//    fills and a region no neighbour reaches is still found.
//  - Importance: d is local, d(x) = d_sep·clamp(√(m_ref/m(x)), ½, 2), with
//    m the field's magnitude (largest |λ|) and m_ref its median over the
//    body: lines per unit cross-section ∝ 1/d² ∝ m, from ¼ to 4 times
//    the mean. Seeds are taken in order of magnitude (in half-octave bands;
//    within a band, the neighbours of finished lines first), so a hole's
//    edge, a notch, a corner or a load gets its lines before the far field
//    takes the room. Without importance d is d_sep everywhere.
//  - A seed where no line can start (a degenerate or weak spot: the
//    direction is undefined) waits until every other seed is taken, then
//    stands as a lone glyph where there is still room: lines first.
// The result is deterministic (one thread traces, in a fixed order).

#include <optional>
#include <vector>

#include "field/tracing/body_lattice.h"
#include "field/tracing/trajectory.h"

namespace hsb {

struct EvenSeedingOptions {
  double separation = 0.0;   // d_sep, in the data's units
  double stop_ratio = 0.5;   // a line stops this fraction of d from another
  bool importance = true;    // d follows the magnitude (the rule above)
  std::optional<Vec3> plane_normal;  // a 2-D result: neighbours beside the line, in its plane
  std::size_t max_lines = 4000;      // a guard against a separation far too small
  // m_ref given rather than the pool's median: the families of one picture
  // share the body's reference, so each is dense where its own stress is
  // large against the stress typical of the body.
  std::optional<double> reference_magnitude;
  // Seeds where no line starts stand as lone glyphs (the last rule above);
  // false: they are dropped (the picture's lines elsewhere, or another
  // family, show the field; the pipeline falls back to lone glyphs only
  // where no line is found anywhere).
  bool lone_glyphs = true;
};

struct EvenTrajectories {
  std::vector<Vec3> seeds;  // one per trajectory, in the order taken
  std::vector<Trajectory> trajectories;
  double reference_magnitude = 0.0;  // m_ref
  bool reached_max_lines = false;
};

// Traces evenly spaced trajectories along `sampler`'s directions: first
// from `given` seeds (in order; each still only where no line passes
// within d), then as the rule above finds them, from `pool` (points inside
// the body with their magnitudes).
EvenTrajectories evenly_spaced_trajectories(const DirectionSampler& sampler, const MagnitudeSampler& magnitude,
                                            const std::vector<Vec3>& given, const BodyLattice& pool,
                                            const TrajectoryOptions& trajectory, const EvenSeedingOptions& options);

}  // namespace hsb

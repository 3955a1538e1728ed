#pragma once
// Kindlmann's superquadric gauge, many glyphs at a time:
//   N(q) = ‖(‖(q_a, q_b)‖_{2/α}, q_z)‖_{2/β}
// and ∇N, for the glyph-shape tracer's probes (glyph_shape.h), which ask
// it of every source a ray is inside at once. Each p-norm raises a ratio
// to a power and its sum to another: log₂ and exp₂ a dozen times a glyph,
// which libm computes one at a time behind a call. Here they are polynomials in
// plain arithmetic, so each instruction set's loop runs them in SIMD lanes
// (8 glyphs at a time with AVX-512), and one glyph alone (the Newton entry,
// the shading) goes through the same code and gets the same bits.
//
// The same bits on every instruction set: the loop is compiled once per set
// (as the span kernels are, ray_span.cpp) from the same source, without
// fused multiply-adds, and nothing in it depends on the vector width.

#include "renderer/surface/instruction_set.h"

namespace hsb {

// Up to kGaugeLanes glyphs, one per lane. In: the point in each glyph's own
// frame by role (a, b the equatorial axes, z the symmetry axis) and
// Kindlmann's α and β (the norms' exponents are 2/α and 2/β). Out: N and
// ∂N/∂q_a, ∂q_b, ∂q_z.
constexpr int kGaugeLanes = 8;
struct alignas(64) GaugeLanes {
  double qa[kGaugeLanes], qb[kGaugeLanes], qz[kGaugeLanes];
  double alpha[kGaugeLanes], beta[kGaugeLanes];
  double n[kGaugeLanes], da[kGaugeLanes], db[kGaugeLanes], dz[kGaugeLanes];
};

// Fills lanes [0, count) of n, da, db, dz under `isa`, in the narrowest
// batch of 2, 4 or kGaugeLanes lanes that holds them; the other lanes'
// outputs are not to be read.
void superquadric_gauges(GaugeLanes& lanes, int count, InstructionSet isa);
// Under active_isa().
void superquadric_gauges(GaugeLanes& lanes, int count);

// log₂ x for a positive normal x and 2^y for y in [−64, 0], within a few ulp:
// the gauge's own, exposed for its tests.
double gauge_log2(double x);
double gauge_exp2(double y);

}  // namespace hsb

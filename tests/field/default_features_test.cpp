// The default picture finds what an engineer looks for, on data nobody
// tuned a scene for: each data set here is generated (analytic stress on a
// grid, NaN outside the body), read from a file as a user's would be, and
// given to the pipeline with nothing but its path. Evenly spaced seeding
// (field/tracing/even_seeding.h) must put a glyph at the hole's edge of a
// plate, at the re-entrant corner of an L, at the load point of a
// half-space, and in both halves of a bent beam; and the trajectories must
// not depend on the stress's unit.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "field/glyph_pipeline.h"
#include "field/tracing/body_lattice.h"
#include "field/tracing/even_seeding.h"
#include "tests/temp_dir.h"
#include "tests/vtk_written.h"

namespace hsb {
namespace {

// An isolated glyph's extent for a largest radius of 1, as the renderer's
// defaults give it (influence radius 1, wyvill at C = ½).
constexpr double kExtent = 0.64;

// σ at a point, or nothing outside the body.
using Stress = std::function<std::optional<Sym3>(const Vec3&)>;

// A grid of `n` points over `box` holding `stress` (NaN outside the body),
// written as a .vti the way VTK writes it.
std::string grid_file(const std::string& name, const Box3& box, const std::array<int, 3>& n, const Stress& stress,
                      double unit = 1.0) {
  return grid_written(test_temp_dir("default_features") / name, box, n, [&](const Vec3& p) -> std::optional<Sym3> {
    std::optional<Sym3> s = stress(p);
    if (s) *s = unit * *s;
    return s;
  });
}

GlyphScene default_scene(const std::string& path, std::vector<EigenFamily> families = {}) {
  GlyphPipelineSpec spec;
  spec.data.kind = DataKind::vtk_file;
  spec.data.file.path = path;
  spec.trajectory.families = std::move(families);
  return build_glyph_scene(spec, kExtent);
}

double glyph_size(const GlyphSource& s) { return kExtent * s.radii.maxCoeff(); }

// The nearest any glyph's surface comes to `p` (its centre's distance less
// its size), over the sources that `keep` accepts.
double nearest_glyph(const GlyphScene& scene, const Vec3& p) {
  double best = INFINITY;
  for (const GlyphSource& s : scene.sources) best = std::min(best, (s.centre - p).norm() - glyph_size(s));
  return best;
}

// Kirsch's plate with a hole of radius a under tension σ along x, in
// metres and pascals: 3σ at the top and bottom of the hole.
constexpr double kHole = 0.2, kSigma = 1e7;
std::optional<Sym3> kirsch(const Vec3& p) {
  const double r = std::hypot(p.x(), p.y());
  if (r < kHole) return std::nullopt;
  const double t = std::atan2(p.y(), p.x()), c = std::cos(t), s = std::sin(t);
  const double a2 = kHole * kHole / (r * r), a4 = a2 * a2, h = 0.5 * kSigma;
  const double rr = h * (1 - a2) + h * (1 - 4 * a2 + 3 * a4) * std::cos(2 * t);
  const double tt = h * (1 + a2) - h * (1 + 3 * a4) * std::cos(2 * t);
  const double rt = -h * (1 + 2 * a2 - 3 * a4) * std::sin(2 * t);
  Sym3 out;
  out.xx = rr * c * c + tt * s * s - 2 * rt * s * c;
  out.yy = rr * s * s + tt * c * c + 2 * rt * s * c;
  out.xy = (rr - tt) * s * c + rt * (c * c - s * s);
  return out;
}
const Box3 kPlate{Vec3(-2, -1, 0), Vec3(2, 1, 0.04)};
const std::array<int, 3> kPlateGrid{161, 81, 3};

TEST(DefaultFeatures, APlateWithAHoleGetsGlyphsAtTheHolesEdge) {
  const GlyphScene scene = default_scene(grid_file("kirsch.vti", kPlate, kPlateGrid, kirsch));
  ASSERT_FALSE(scene.sources.empty());
  const double h = 0.025;  // the grid's spacing: the hole's edge is known to a cell
  // Where the 3σ concentration is: the top and bottom of the hole.
  for (double side : {1.0, -1.0}) {
    const Vec3 edge(0.0, side * kHole, 0.02);
    EXPECT_LT(nearest_glyph(scene, edge), 2.0 * h) << "no glyph at the hole's edge, y = " << edge.y();
  }
  // And the concentration keeps its glyphs large: the largest glyph is
  // near the hole, not in the far field.
  const auto largest = std::max_element(scene.sources.begin(), scene.sources.end(),
                                        [](const GlyphSource& a, const GlyphSource& b) { return glyph_size(a) < glyph_size(b); });
  EXPECT_LT(std::hypot(largest->centre.x(), largest->centre.y()), 3.0 * kHole);
}

TEST(DefaultFeatures, AnLBracketGetsGlyphsAtItsReentrantCornerAndNoneOutside) {
  // [0, 2]² less the quadrant x, y > 1, 0.2 thick; a stress that grows
  // towards the re-entrant corner (1, 1) as 1/√r, circling it.
  const Vec3 corner(1, 1, 0.1);
  const Stress bracket = [&](const Vec3& p) -> std::optional<Sym3> {
    if (p.x() > 1.0 && p.y() > 1.0) return std::nullopt;
    const Vec3 d = p - corner;
    const double r = std::hypot(d.x(), d.y());
    const double k = 1.0 / std::sqrt(r + 0.02);
    const Vec3 e_t = r > 0 ? Vec3(-d.y() / r, d.x() / r, 0) : Vec3::UnitX();
    Sym3 s;
    s.xx = 1.0 + k * e_t.x() * e_t.x();
    s.yy = 0.3 + k * e_t.y() * e_t.y();
    s.xy = k * e_t.x() * e_t.y();
    return s;
  };
  const GlyphScene scene =
      default_scene(grid_file("bracket.vti", Box3{Vec3(0, 0, 0), Vec3(2, 2, 0.2)}, {81, 81, 9}, bracket));
  ASSERT_FALSE(scene.sources.empty());
  EXPECT_LT(nearest_glyph(scene, corner), 2.0 * 0.025);
  for (const Vec3& seed : scene.values.seeds.points)
    EXPECT_FALSE(seed.x() > 1.0 && seed.y() > 1.0) << "a seed outside the L at " << seed.transpose();
  // Every arm has lines: the L fills.
  int lower = 0, upper = 0;
  for (const GlyphSource& s : scene.sources) (s.centre.y() < 1.0 && s.centre.x() > 1.2 ? lower : upper) += 1;
  EXPECT_GT(lower, 10);
  EXPECT_GT(upper, 10);
}

TEST(DefaultFeatures, AHalfSpaceGetsGlyphsAtItsLoadPoint) {
  GlyphPipelineSpec spec;  // the analytic point load, nothing else said
  const GlyphScene scene = build_glyph_scene(spec, kExtent);
  ASSERT_FALSE(scene.sources.empty());
  const Box3& b = spec.data.point_load.bounds;
  const Vec3 load(0.5 * (b.lo.x() + b.hi.x()), 0.5 * (b.lo.y() + b.hi.y()), b.hi.z());
  EXPECT_LT(nearest_glyph(scene, load), 0.02 * b.diagonal());
}

TEST(DefaultFeatures, ABentBeamGetsLinesInBothHalves) {
  // A simply supported beam, 10 × 1 × 0.5, under a uniform load: σxx =
  // M(x) y / I (tension below, compression above), with the shear
  // τxy = V(x) (3/2A) (1 − 4y²/h²).
  const double L = 10, h = 1, w = 0.5, A = h * w, I = w * h * h * h / 12.0, q = 1.0;
  const Stress beam = [&](const Vec3& p) -> std::optional<Sym3> {
    const double x = p.x(), y = p.y();
    Sym3 s;
    s.xx = -q * x * (L - x) / 2.0 * y / I;
    s.xy = q * (L / 2.0 - x) * 1.5 / A * (1 - 4 * y * y / (h * h));
    return s;
  };
  const GlyphScene scene =
      default_scene(grid_file("beam.vti", Box3{Vec3(0, -0.5, 0), Vec3(10, 0.5, 0.5)}, {201, 21, 11}, beam));
  // The major trajectories run along the stretched half and arch up
  // through the compressed one towards the supports (the classic picture
  // of a beam's principal stresses); at mid-span above the neutral axis
  // the major stress is ~0 and its direction undefined, so that half gets
  // arcs and lone glyphs rather than lines along the beam.
  std::size_t along_below = 0, through_above = 0;
  for (const Trajectory& t : scene.trajectories) {
    double in_upper = 0.0;
    for (std::size_t i = 1; i < t.points.size(); ++i)
      if (t.points[i].y() > 0.1 && t.points[i - 1].y() > 0.1) in_upper += (t.points[i] - t.points[i - 1]).norm();
    if (t.length() > L / 4 && t.points[t.seed_index].y() < 0) ++along_below;
    if (in_upper > 0.25 * h) ++through_above;  // a line, not a lone glyph
  }
  EXPECT_GE(along_below, 2u) << "no long trajectory in the stretched half";
  EXPECT_GE(through_above, 2u) << "no trajectory through the compressed half";
  std::size_t top = 0, bottom = 0;
  for (const GlyphSource& s : scene.sources) (s.centre.y() > 0 ? top : bottom) += 1;
  EXPECT_GT(top, scene.sources.size() / 5);
  EXPECT_GT(bottom, scene.sources.size() / 5);
  // Tension against compression: the default traces both families, so
  // the compressed half has long minor (compression) lines of its own,
  // coloured by their negative λ3, as the stretched half has major ones
  // coloured by a positive λ1.
  std::size_t tension = 0, compression = 0;
  for (const Trajectory& t : scene.trajectories) {
    if (t.length() < L / 4) continue;
    const double y = t.points[t.seed_index].y();
    if (t.family == EigenFamily::major && y < -0.1) ++tension;
    if (t.family == EigenFamily::minor && y > 0.1) ++compression;
  }
  EXPECT_GE(tension, 2u);
  EXPECT_GE(compression, 2u) << "no compression line along the compressed half";
  // Each family's glyphs are a group of their own (GlyphSource::group:
  // tension lines do not blend into compression lines), the family's axis:
  // a source shows its own family's eigenvalue.
  std::size_t in_group[3] = {0, 0, 0};
  for (const GlyphSource& s : scene.sources) {
    ASSERT_TRUE(s.group == 0 || s.group == 2) << int(s.group);
    ++in_group[s.group];
    EXPECT_EQ(s.scalar, s.eigenvalues[s.group]);
  }
  EXPECT_GT(in_group[0], 0u);
  EXPECT_GT(in_group[2], 0u);
  double most_compressive = 0.0, most_tensile = 0.0;
  for (const GlyphSource& s : scene.sources) {
    if (s.centre.y() > 0.3) most_compressive = std::min(most_compressive, s.scalar);
    if (s.centre.y() < -0.3) most_tensile = std::max(most_tensile, s.scalar);
  }
  const double peak = q * L * L / 8.0 * (h / 2) / I;  // |σxx| at mid-span's faces
  EXPECT_LT(most_compressive, -0.5 * peak) << "the compressed half is not coloured as compression";
  EXPECT_GT(most_tensile, 0.5 * peak);
}

// Stress in pascals and the same as "strain" a million times smaller: the
// same trajectories, seeds and glyph places. Direction fields do not
// depend on the unit; nothing in the integrator or the seeding may.
// Lamé's thick tube under internal pressure: hoop tension, radial
// compression. The hoop lines are whole rings, closed where they began
// (they stopped a line's separation short of their seed, a gap in every
// ring).
TEST(DefaultFeatures, ATubesHoopLinesAreClosedRings) {
  constexpr double a = 0.5, b = 1.0, p = 1e6;
  const auto lame = [&](const Vec3& x) -> std::optional<Sym3> {
    const double r = std::hypot(x.x(), x.y());
    if (r < a || r > b) return std::nullopt;
    const double k = p * a * a / (b * b - a * a), radial = k * (1 - b * b / (r * r)), hoop = k * (1 + b * b / (r * r));
    const double c = x.x() / r, s = x.y() / r;
    Sym3 out;
    out.xx = radial * c * c + hoop * s * s;
    out.yy = radial * s * s + hoop * c * c;
    out.xy = (radial - hoop) * s * c;
    out.zz = 0.3 * (radial + hoop);
    return out;
  };
  const GlyphScene scene = default_scene(grid_file("lame.vti", {Vec3(-1, -1, 0), Vec3(1, 1, 0.2)}, {81, 81, 9}, lame));
  std::size_t rings = 0;
  for (const Trajectory& t : scene.trajectories) {
    if (t.family != EigenFamily::major || t.length() < 2.0) continue;  // a hoop line: at least r = ½ round
    ASSERT_TRUE(t.closed()) << "a hoop line of length " << t.length() << " is not a ring";
    EXPECT_EQ(t.points.front(), t.points.back());
    const double r = std::hypot(t.points.front().x(), t.points.front().y());
    EXPECT_NEAR(t.length(), 2 * M_PI * r, 0.02 * 2 * M_PI * r);
    ++rings;
  }
  EXPECT_GE(rings, 2u);
}

TEST(DefaultFeatures, TrajectoriesDoNotDependOnTheStressUnit) {
  const GlyphScene pascals = default_scene(grid_file("kirsch_pa.vti", kPlate, kPlateGrid, kirsch));
  const GlyphScene scaled = default_scene(grid_file("kirsch_micro.vti", kPlate, kPlateGrid, kirsch, 1e-6));
  ASSERT_EQ(pascals.trajectories.size(), scaled.trajectories.size());
  for (std::size_t i = 0; i < pascals.trajectories.size(); ++i) {
    const Trajectory &a = pascals.trajectories[i], &b = scaled.trajectories[i];
    ASSERT_EQ(a.points.size(), b.points.size()) << "trajectory " << i;
    for (std::size_t k = 0; k < a.points.size(); ++k)
      ASSERT_LT((a.points[k] - b.points[k]).norm(), 1e-9) << "trajectory " << i << " point " << k;
  }
  ASSERT_EQ(pascals.sources.size(), scaled.sources.size());
  for (std::size_t i = 0; i < pascals.sources.size(); ++i) {
    EXPECT_LT((pascals.sources[i].centre - scaled.sources[i].centre).norm(), 1e-9);
    EXPECT_NEAR(glyph_size(pascals.sources[i]), glyph_size(scaled.sources[i]), 1e-9);
  }
}

// A seed at a degenerate point (isotropic stress) of a field given in two
// units traces the same (no) trajectory: the degeneracy test is relative.
TEST(DefaultFeatures, ADegenerateSeedIsTheSameInEveryUnit) {
  double reference = -1.0;  // the length beside the axis, in the first unit
  for (double unit : {1.0, 1e-6, 1e6}) {
    // Isotropic along x = 0, sheared away from it.
    const Stress field = [&](const Vec3& p) -> std::optional<Sym3> {
      Sym3 s;
      s.xx = s.yy = s.zz = unit;
      s.xy = unit * 0.5 * p.x();
      return s;
    };
    struct Analytic : TensorField {
      Stress f;
      Box3 bounds() const override { return {Vec3(-1, -1, -1), Vec3(1, 1, 1)}; }
      std::optional<Sym3> sample(const Vec3& x) const override {
        if ((x.array() < -1).any() || (x.array() > 1).any()) return std::nullopt;
        return f(x);
      }
    } analytic;
    analytic.f = field;
    TrajectoryOptions options;
    options.step = 0.01;
    options.max_length = 1.0;
    const Trajectory at_axis = trace_trajectory(analytic, Vec3(0, 0.3, 0), options);
    const Trajectory beside = trace_trajectory(analytic, Vec3(0.2, 0.3, 0), options);
    EXPECT_EQ(at_axis.points.size(), 1u) << "unit " << unit;
    EXPECT_EQ(at_axis.forward_stop, StopReason::degenerate) << "unit " << unit;
    EXPECT_GT(beside.length(), 0.1) << "unit " << unit;
    if (reference < 0) reference = beside.length();
    EXPECT_NEAR(beside.length(), reference, 1e-9) << "unit " << unit;
  }
}

// A field whose followed eigenvector is undefined gets a warning that
// says what helps, from which eigenvalues are equal.
TEST(DefaultFeatures, ADegenerateFieldIsToldWhatHelps) {
  const Box3 cube{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const auto warnings_of = [&](const std::string& name, const Sym3& constant) {
    const GlyphScene scene = default_scene(grid_file(name, cube, {5, 5, 5}, [&](const Vec3&) { return constant; }),
                                           {EigenFamily::major});
    std::string all;
    for (const std::string& w : scene.warnings) all += w + "\n";
    return all;
  };
  Sym3 isotropic;
  isotropic.xx = isotropic.yy = isotropic.zz = -2.0;
  EXPECT_NE(warnings_of("isotropic.vti", isotropic).find("isotropic"), std::string::npos);
  Sym3 compression;  // uniaxial: λ1 = λ2 = 0, λ3 = −1
  compression.zz = -1.0;
  EXPECT_NE(warnings_of("compression.vti", compression).find("trajectories.family = \"minor\""), std::string::npos);
  // The default traces the minor family too: lines, and nothing to warn of.
  const GlyphScene both = default_scene(grid_file("compression.vti", cube, {5, 5, 5}, [&](const Vec3&) {
    return compression;
  }));
  EXPECT_TRUE(both.warnings.empty()) << both.warnings.front();
  ASSERT_FALSE(both.trajectories.empty());
  for (const Trajectory& t : both.trajectories) EXPECT_EQ(t.family, EigenFamily::minor);
}

// An isotropic background (a body under pressure, a diffusion volume's
// fluid) with one anisotropic spot: lines in the spot, and no lone
// spheres in the background to hide it; a warning says how much of the
// body has no direction and what would show it.
TEST(DefaultFeatures, AnIsotropicBackgroundLeavesTheAnisotropicSpotAlone) {
  const Box3 cube{Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const Vec3 spot(0.65, 0.4, 0.55);
  constexpr double kRadius = 0.15;
  const GlyphScene scene = default_scene(grid_file("pressure_spot.vti", cube, {31, 31, 31}, [&](const Vec3& p) {
    Sym3 s;
    s.xx = s.yy = s.zz = -1e5;
    s.xy = 2e4 * std::exp(-(p - spot).squaredNorm() / (kRadius * kRadius));
    return std::optional<Sym3>(s);
  }));
  ASSERT_FALSE(scene.sources.empty());
  // Beyond 2.6 R the shear is under 1e-3 of the pressure: no direction.
  for (const GlyphSource& s : scene.sources)
    EXPECT_LT((s.centre - spot).norm(), 2.7 * kRadius) << "a glyph in the isotropic background";
  EXPECT_LT(nearest_glyph(scene, spot), 0.5 * kRadius) << "no glyph at the spot";
  std::string all;
  for (const std::string& w : scene.warnings) all += w + "\n";
  EXPECT_NE(all.find("isotropic"), std::string::npos) << all;
  EXPECT_NE(all.find("glyphs.placement = \"points\""), std::string::npos) << all;
}

}  // namespace
}  // namespace hsb

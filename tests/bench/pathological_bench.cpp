// The renderer on the scenes that hurt: rays that cross many supports.
//
//   pathological_bench [SOURCE_DIR]      (default: the source tree it was built from)
//
// Rows:
//  - pile N, N = 10, 100, 1000: N glyphs far too large for their spacing,
//    all overlapping (every ray through the pile crosses all N supports);
//  - pile 100, camera inside: the same pile seen from its centre, where
//    every camera ray starts inside the surface;
//  - fig06: the paper's square-root point-load figure, whose dense cap at
//    the load has hundreds of overlapping sources;
//  - fig09: the reference, an ordinary dense figure.
// Each at 320×320, one sample per pixel, the key light's soft shadows and
// ambient occlusion. Prints primary and shadow Mrays/s; supports crossed,
// segments walked and kernel evaluations per ray, for camera rays and for
// shadow rays; and each ray kind's rate as a fraction of fig09's primary
// rate. Then fig09, fig06 and the 100-glyph pile again under every
// instruction set the processor has (forced as HSB_ISA would), with the
// ratios of AVX2 to AVX-512 and of SSE4.2 to AVX2. Measures; never fails
// on a number.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "renderer/library/prepared_scene.h"
#include "renderer/render/ray_scene.h"
#include "renderer/render/render_image.h"
#include "renderer/surface/instruction_set.h"

namespace {

using namespace hsb;

#ifndef HSB_SOURCE_DIR
#define HSB_SOURCE_DIR "."
#endif

constexpr int kSize = 320;

struct Row {
  std::string name;
  std::size_t sources = 0;
  RenderOutput out;
};

BlobField pile(int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BlobField field;
  for (int i = 0; i < n; ++i) {
    Vec3 centre(normal(rng), normal(rng), normal(rng));
    centre *= 0.25 * std::cbrt(unit(rng)) / centre.norm();
    const Mat3 axes = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
    // Influence semi-axes 1.2 to 2: every support holds the pile's centre.
    const Vec3 radii(2.0, 1.2 + 0.8 * unit(rng), 1.2 + 0.8 * unit(rng));
    field.sources.push_back(make_blob_source(centre, axes, radii, 1.0, {0.6f, 0.5f, 0.3f}));
  }
  // So many overlapping sources sum far above any isovalue; a high C keeps
  // the surface inside the supports, where the work is.
  field.isovalue = 0.9 * double(n) * kernel_value(field.kernel, 0.15);
  field.isovalue = std::min(field.isovalue, 0.5 * double(n));
  return field;
}

RenderOutput render_field(const EmbreeDevice& device, const BlobField& field, const CameraSpec& camera,
                          Intersector intersector) {
  const Box3 domain{Vec3(-2, -2, -2), Vec3(2, 2, 2)};
  const ShadingSpec shading;
  TraceSettings trace;
  trace.intersector = intersector;
  trace.min_step = 1e-6 * domain.diagonal();
  RenderSettings render;
  render.width = render.height = kSize;
  render.samples = 1;
  render.shadow_offset = 1e-5 * domain.diagonal();
  const RayScene scene(device, field, trace);
  return render_image(scene, camera, shading, render);
}

Row render_scene_file(const EmbreeDevice& device, const std::string& name, const std::string& path,
                      Intersector intersector) {
  SceneSpec spec = load_scene(path, {"render.width=" + std::to_string(kSize), "render.height=" + std::to_string(kSize),
                                     "render.samples=1"});
  const ColorManagement color("", "");
  const std::unique_ptr<PreparedScene> p = prepare_scene(std::move(spec), color);
  p->trace.intersector = intersector;
  const RayScene scene(device, p->field, p->trace, p->context);
  return {name, p->field.sources.size(), render_image(scene, p->camera, p->shading, p->render)};
}

double per_ray(std::uint64_t count, const TraceStats& stats) {
  return double(count) / double(std::max<std::uint64_t>(1, stats.field_rays));
}

void print(const Row& row, double reference) {
  const RenderOutput& o = row.out;
  const double primary = o.primary_mrays_per_second(), shadow = o.shadow_mrays_per_second();
  std::printf("%-24s %7zu %8.2f %8.2f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f %7.2f %7.2f\n", row.name.c_str(),
              row.sources, primary, shadow, per_ray(o.stats.spans, o.stats), per_ray(o.shadow_stats.spans, o.shadow_stats),
              per_ray(o.stats.segments, o.stats), per_ray(o.shadow_stats.segments, o.shadow_stats),
              per_ray(o.stats.kernel_evaluations, o.stats), per_ray(o.shadow_stats.kernel_evaluations, o.shadow_stats),
              primary / reference, o.shadow_rays ? shadow / reference : 0.0);
  std::fflush(stdout);
}

// The processor's name, as the kernel reports it.
std::string processor_name() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown processor";
}

// fig09, fig06 and the 100-glyph pile under each instruction set, the
// best of two runs each (taken in turn, so that drift in the machine's
// speed falls on every set alike).
void instruction_set_table(const std::string& source_dir, const CameraSpec& outside) {
  const std::vector<InstructionSet> isas = supported_isas();
  const InstructionSet original = active_isa();
  struct Rates {
    double primary = 0.0, shadow = 0.0;
  };
  std::map<std::pair<int, std::string>, Rates> best;
  const std::vector<std::string> scenes = {"fig09", "fig06", "pile 100"};
  for (int run = 0; run < 2; ++run) {
    for (const InstructionSet isa : isas) {
      force_isa(isa);
      const EmbreeDevice device;
      for (const std::string& scene : scenes) {
        const RenderOutput out =
            scene == "pile 100"
                ? render_field(device, pile(100), outside, Intersector::exact)
                : render_scene_file(device, scene,
                                    source_dir + (scene == "fig09" ? "/scenes/fig09_point_load_hyperstreamsurface.toml"
                                                                   : "/scenes/fig06_point_load_sqrt.toml"),
                                    Intersector::exact)
                      .out;
        Rates& r = best[{int(isa), scene}];
        r.primary = std::max(r.primary, out.primary_mrays_per_second());
        r.shadow = std::max(r.shadow, out.shadow_mrays_per_second());
      }
    }
  }
  force_isa(original);

  std::printf("\ninstruction sets (exact, %dx%d, 1 sample per pixel; best of 2 runs; Mrays/s primary / shadow)\n",
              kSize, kSize);
  std::printf("processor: %s\n", processor_name().c_str());
  std::printf("%-10s", "set");
  for (const std::string& scene : scenes) std::printf(" %17s", scene.c_str());
  std::printf("\n");
  for (const InstructionSet isa : isas) {
    std::printf("%-10s", isa_name(isa));
    for (const std::string& scene : scenes) {
      const Rates& r = best[{int(isa), scene}];
      std::printf("      %5.2f / %4.2f", r.primary, r.shadow);
    }
    std::printf("\n");
  }
  // The targets: AVX2 within 25% of AVX-512, SSE4.2 within 2× of AVX2.
  const auto ratio_row = [&](InstructionSet slow, InstructionSet fast, const char* target) {
    if (!processor_supports(slow) || !processor_supports(fast)) return;
    std::printf("%-10s", (std::string(isa_name(slow)) + "/" + isa_name(fast)).c_str());
    for (const std::string& scene : scenes) {
      const Rates &s = best[{int(slow), scene}], &f = best[{int(fast), scene}];
      std::printf("      %5.2f / %4.2f", s.primary / f.primary, s.shadow / f.shadow);
    }
    std::printf("   (target %s)\n", target);
  };
  ratio_row(InstructionSet::avx2, InstructionSet::avx512, "at least 0.75");
  ratio_row(InstructionSet::sse42, InstructionSet::avx2, "at least 0.50");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string source_dir = argc > 1 ? argv[1] : HSB_SOURCE_DIR;
  const EmbreeDevice device;
  std::printf("processor: %s; instruction set: %s\n", processor_name().c_str(), isa_name(active_isa()));
  CameraSpec outside;
  outside.position = Vec3(4.0, -6.0, 3.0);
  outside.look_at = Vec3::Zero();
  outside.fov_degrees = 40;
  CameraSpec inside = outside;
  inside.position = Vec3(0.01, -0.02, 0.015);
  inside.look_at = Vec3(1, -1, 0.5);
  inside.fov_degrees = 90;

  for (const Intersector intersector : {Intersector::exact, Intersector::sphere}) {
    std::printf("\nintersector: %s  (%dx%d, 1 sample per pixel, shadows)\n",
                intersector == Intersector::exact ? "exact" : "sphere", kSize, kSize);
    std::printf("%-24s %7s %8s %8s %17s %17s %17s %15s\n", "", "", "primary", "shadow", "supports/ray",
                "segments/ray", "kernel evals/ray", "rate/fig09");
    std::printf("%-24s %7s %8s %8s %8s %8s %8s %8s %8s %8s %7s %7s\n", "scene", "sources", "Mrays/s", "Mrays/s",
                "primary", "shadow", "primary", "shadow", "primary", "shadow", "primary", "shadow");
    const Row reference = render_scene_file(
        device, "fig09", source_dir + "/scenes/fig09_point_load_hyperstreamsurface.toml", intersector);
    const double base = reference.out.primary_mrays_per_second();
    for (const int n : {10, 100, 1000}) {
      const BlobField field = pile(n);
      print({"pile " + std::to_string(n), field.sources.size(), render_field(device, field, outside, intersector)},
            base);
    }
    const BlobField field = pile(100);
    print({"pile 100, camera inside", field.sources.size(), render_field(device, field, inside, intersector)}, base);
    print(render_scene_file(device, "fig06 (dense cap)", source_dir + "/scenes/fig06_point_load_sqrt.toml",
                            intersector),
          base);
    print(reference, base);
  }
  std::printf("\n(supports: source supports a field ray crosses; segments: stretches between support\n"
              " endpoints it walks; kernel evals: single-source kernel evaluations, per ray that reaches\n"
              " the field, for camera rays and for shadow and occlusion rays; rate/fig09: the rate as a\n"
              " fraction of fig09's primary rate, the target being at least 0.25)\n");
  instruction_set_table(source_dir, outside);
  return 0;
}

// What finding a point's cell costs in a mixed-cell mesh (hexahedra,
// wedges, pyramids), with the part's size given in three units: metres
// (a 1 mm part), millimetres and micrometres. Trajectories and evenly
// spaced seeding sample the mesh this way ~10⁵ times per picture, so a
// cost that depends on the unit turns seconds into minutes.
//
//   locate_bench [file.vtk]   (default scenes/data/generated/mixed_cells_legacy.vtk)
//
// Prints, per unit: µs per query (20,000 random points in the bounds, on
// one thread) and the share found inside a cell, which must be the same
// in every unit. Measures; never fails on a number.

#include <vtkNew.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <string>

#include "field/sampling/mesh_locator.h"

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const std::string path =
      argc > 1 ? argv[1] : std::string(HSB_SOURCE_DIR) + "/scenes/data/generated/mixed_cells_legacy.vtk";
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetOutput()->GetNumberOfCells() == 0) {
    std::fprintf(stderr, "locate_bench: no cells in %s\n", path.c_str());
    return 1;
  }
  std::printf("%s: %lld cells\n", path.c_str(), static_cast<long long>(reader->GetOutput()->GetNumberOfCells()));
  std::printf("%-10s %12s %10s\n", "scale", "us/query", "found");
  constexpr int kQueries = 20000;
  for (const double scale : {1.0, 1e3, 1e6}) {
    vtkNew<vtkTransform> transform;
    transform->Scale(scale, scale, scale);
    vtkNew<vtkTransformFilter> scaled;
    scaled->SetTransform(transform);
    scaled->SetInputConnection(reader->GetOutputPort());
    scaled->Update();
    const hsb::MeshLocator locator(scaled->GetOutput());
    const hsb::Box3 b = locator.bounds();
    std::mt19937 rng(7);  // the same points, scaled, in every unit
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int found = 0;
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < kQueries; ++i) {
      const hsb::Vec3 t(u(rng), u(rng), u(rng));
      found += locator.locate(b.lo + t.cwiseProduct(b.size())) != nullptr;
    }
    const double us = std::chrono::duration<double, std::micro>(Clock::now() - start).count() / kQueries;
    std::printf("%-10g %12.2f %9.1f%%\n", scale, us, 100.0 * found / kQueries);
  }
  return 0;
}

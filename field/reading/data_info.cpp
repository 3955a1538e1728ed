#include "field/reading/data_info.h"

#include <sstream>

#include "field/tensor/eigenvalue_range.h"

namespace hsb {

std::string describe_data(const DataSpec& spec) {
  if (spec.kind == DataKind::vtk_file) return describe_vtk_file(spec.file);
  if (spec.kind == DataKind::none) return "no data set: the scene gives its sources (a curve or a list)\n";
  const PointLoadField field(spec.point_load);
  const Box3 b = field.bounds();
  std::ostringstream out;
  out << "point load (Boussinesq), analytic\n"
      << "  bounds    x [" << b.lo.x() << ", " << b.hi.x() << "]  y [" << b.lo.y() << ", " << b.hi.y()
      << "]  z [" << b.lo.z() << ", " << b.hi.z() << "]\n"
      << "  load      " << spec.point_load.load << " at (" << field.load_point().transpose()
      << "), Poisson ratio " << spec.point_load.poisson_ratio << "\n"
      << "  singular  clamped within " << field.singular_radius() << " of the load\n";
  constexpr int n = 21;
  EigenvalueRange range;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        range.add(*field.sample(b.lo + b.size().cwiseProduct(Vec3(i, j, k) / double(n - 1))));
  out << range;
  return out.str();
}

}  // namespace hsb

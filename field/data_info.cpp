#include "field/data_info.h"

#include <sstream>

#include "field/eigensystem.h"

namespace hsb {

std::string describe_data(const DataSpec& spec) {
  if (spec.kind == DataKind::vtk_file) return describe_vtk_file(spec.file);
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
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 x = b.lo + b.size().cwiseProduct(Vec3(i, j, k) / double(n - 1));
        const Vec3 values = decompose(*field.sample(x)).values;
        lo = lo.cwiseMin(values);
        hi = hi.cwiseMax(values);
      }
  const char* names[3] = {"λ1 (major) ", "λ2 (medium)", "λ3 (minor) "};
  for (int k = 0; k < 3; ++k) out << "  " << names[k] << " [" << lo[k] << ", " << hi[k] << "]\n";
  return out.str();
}

}  // namespace hsb

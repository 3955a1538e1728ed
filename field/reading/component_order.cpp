#include "field/reading/component_order.h"

namespace hsb {
namespace {

// (row, column) of each of the six, for the five layouts in use.
constexpr ComponentOrder::Entries vtk{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}}};
constexpr ComponentOrder::Entries voigt{{{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}}};
constexpr ComponentOrder::Entries engineering{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
constexpr ComponentOrder::Entries upper{{{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}}};
constexpr ComponentOrder::Entries lower{{{0, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}, {2, 2}}};

}  // namespace

const std::vector<ComponentOrder>& component_orders() {
  static const std::vector<ComponentOrder> orders{
      {"vtk", "XX YY ZZ XY YZ XZ", "VTK and ParaView", vtk},
      {"voigt", "XX YY ZZ YZ XZ XY", "Voigt notation", voigt},
      {"sfepy", "XX YY ZZ XY XZ YZ", "SfePy", engineering},
      {"abaqus", "XX YY ZZ XY XZ YZ", "Abaqus (S11 S22 S33 S12 S13 S23)", engineering},
      {"code_aster", "XX YY ZZ XY XZ YZ", "Code_Aster (SIXX SIYY SIZZ SIXY SIXZ SIYZ)", engineering},
      {"mrtrix", "XX YY ZZ XY XZ YZ", "MRtrix (D11 D22 D33 D12 D13 D23)", engineering},
      {"fsl", "XX XY XZ YY YZ ZZ", "FSL dtifit's tensor volume", upper},
      {"teem", "XX XY XZ YY YZ ZZ", "Teem (after the confidence)", upper},
      {"nifti", "XX XY YY XZ YZ ZZ", "NIfTI's symmetric-matrix intent (lower triangle)", lower},
      {"dipy", "XX XY YY XZ YZ ZZ", "DIPY", lower},
  };
  return orders;
}

const ComponentOrder* component_order(const std::string& name) {
  for (const ComponentOrder& o : component_orders())
    if (o.name == name) return &o;
  return nullptr;
}

Sym3 tensor_in_order(const double* six, const ComponentOrder& order) {
  // Each component straight to its place (a symmetric matrix's (i, j) and
  // (j, i) are one): what the symmetric part of the full matrix gives, to
  // the bit, without making it, for every voxel of a volume.
  Sym3 s;
  double* const place[3][3] = {{&s.xx, &s.xy, &s.xz}, {&s.xy, &s.yy, &s.yz}, {&s.xz, &s.yz, &s.zz}};
  for (std::size_t k = 0; k < 6; ++k) *place[order.entries[k][0]][order.entries[k][1]] = six[k];
  return s;
}

std::array<double, 6> components_in_order(const Sym3& t, const ComponentOrder& order) {
  const Mat3 m = t.matrix();
  std::array<double, 6> six{};
  for (std::size_t k = 0; k < 6; ++k) six[k] = m(order.entries[k][0], order.entries[k][1]);
  return six;
}

}  // namespace hsb

#pragma once
// The order in which a file's six components of a symmetric tensor come:
// VTK's own (XX, YY, ZZ, XY, YZ, XZ) is one of five that real tools write,
// and reading one as another swaps shears silently (SfePy's output read as
// VTK's turned 40 % of an L-bracket's tensors by more than 5 %).

#include <array>
#include <string>
#include <vector>

#include "field/tensor/sym3.h"

namespace hsb {

struct ComponentOrder {
  std::string name;    // the data.components word: "vtk", "sfepy", ...
  std::string layout;  // "XX YY ZZ XY YZ XZ"
  std::string tools;   // who writes it
  using Entries = std::array<std::array<int, 2>, 6>;
  Entries entries;     // (row, column) of each component
};

// Every preset, VTK's first; tools that share an order have a name each.
const std::vector<ComponentOrder>& component_orders();

// The preset named `name`, else nullptr.
const ComponentOrder* component_order(const std::string& name);

// The tensor whose six components, in `order`, are `six`.
Sym3 tensor_in_order(const double* six, const ComponentOrder& order);

// The six components of `t` in `order`: tensor_in_order() undone.
std::array<double, 6> components_in_order(const Sym3& t, const ComponentOrder& order);

}  // namespace hsb

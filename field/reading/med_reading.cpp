// MED files (Code_Aster's results, SALOME's meshes and fields), read through
// MED-fichier's own C library (libmedC 4.1, Debian's libmedc-dev; the file
// is HDF5 inside): the first mesh's cells of its highest dimension (its 3-D
// cells; a plane result's 2-D ones when it has none) in VTK's node order,
// and every floating-point field on that mesh at one computing step, each
// an array named by the field's type as Code_Aster writes it after the
// result's name ("SIGM_NOEU" of "RESU____SIGM_NOEU"):
//  - per node (MED_NODE, Code_Aster's *_NOEU): point data;
//  - per element node (MED_NODE_ELEMENT, *_ELNO): averaged onto the
//    points, which is said with the array (cells that meet there mix);
//  - per cell (MED_CELL, *_ELEM) or per Gauss point (*_ELGA): cell data, a
//    cell's Gauss points averaged into one value, which is said too.
// A field whose components name a symmetric tensor's entries (SIXX SIYY
// SIZZ SIXY SIXZ SIYZ for a stress, EPXX ... for a strain: Code_Aster puts
// XZ before YZ) is put in VTK's order XX YY ZZ XY YZ XZ by those names, and
// its order recorded. The nodal stress is made the active tensors.
//
// MED numbers a cell's nodes so that its first face turns outward (its
// reference elements; MEDCoupling's CellModel lists their faces so): the
// mirror of VTK's tetrahedron, pyramid and hexahedron, whose first face
// turns toward the rest of the cell, so each read in MED's order would be
// inside out. A wedge (PENTA) turns its first face outward in both
// (vtkWedge.h; VTK's volume of such a wedge is positive). The edge and face
// nodes of the quadratic cells follow the same edges and faces in both:
// each table below follows from its corners'.
//
// Internal to field/; the file is parsed only in a child process
// (field/reading/dataset_reading.h): the library trusts the counts a file
// declares, so each is checked against the file's size before a buffer is
// sized by it (MED stores its arrays uncompressed).

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"

// Last: med.h defines macros of short names (STR). It includes the HDF5
// header of the MPI build the library is made with (hdf5/openmpi), not
// VTK's serial one: field/CMakeLists.txt puts that first for this file.
#include <med.h>

namespace hsb {
namespace {

// A MED cell type hsb reads: VTK's node i is MED's node order[i].
struct CellType {
  med_geometry_type med;
  const char* name;
  int vtk;
  std::vector<int> order;
  int dimension() const { return int(med / 100); }
  int nodes() const { return int(order.size()); }
};

std::vector<int> same_order(int n) {
  std::vector<int> order;
  for (int i = 0; i < n; ++i) order.push_back(i);
  return order;
}

const std::vector<CellType>& cell_types() {
  static const std::vector<CellType> types = {
      {MED_TETRA4, "TETRA4", VTK_TETRA, {0, 2, 1, 3}},
      {MED_PYRA5, "PYRA5", VTK_PYRAMID, {0, 3, 2, 1, 4}},
      {MED_PENTA6, "PENTA6", VTK_WEDGE, same_order(6)},
      {MED_HEXA8, "HEXA8", VTK_HEXAHEDRON, {0, 3, 2, 1, 4, 7, 6, 5}},
      {MED_TETRA10, "TETRA10", VTK_QUADRATIC_TETRA, {0, 2, 1, 3, 6, 5, 4, 7, 9, 8}},
      {MED_PYRA13, "PYRA13", VTK_QUADRATIC_PYRAMID, {0, 3, 2, 1, 4, 8, 7, 6, 5, 9, 12, 11, 10}},
      {MED_PENTA15, "PENTA15", VTK_QUADRATIC_WEDGE, same_order(15)},
      {MED_HEXA20, "HEXA20", VTK_QUADRATIC_HEXAHEDRON,
       {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17}},
      // MED's face nodes: bottom, (0 1 5 4), (1 2 6 5), (2 3 7 6), (3 0 4 7), top; VTK's
      // (0 3 7 4), (1 2 6 5), (0 1 5 4), (3 2 6 7), bottom, top.
      {MED_HEXA27, "HEXA27", VTK_TRIQUADRATIC_HEXAHEDRON,
       {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 15, 14, 13, 12, 16, 19, 18, 17, 21, 23, 24, 22, 20, 25, 26}},
      // A surface has no inside: MED's order is VTK's.
      {MED_TRIA3, "TRIA3", VTK_TRIANGLE, same_order(3)},
      {MED_QUAD4, "QUAD4", VTK_QUAD, same_order(4)},
      {MED_TRIA6, "TRIA6", VTK_QUADRATIC_TRIANGLE, same_order(6)},
      {MED_TRIA7, "TRIA7", VTK_BIQUADRATIC_TRIANGLE, same_order(7)},
      {MED_QUAD8, "QUAD8", VTK_QUADRATIC_QUAD, same_order(8)},
      {MED_QUAD9, "QUAD9", VTK_BIQUADRATIC_QUAD, same_order(9)},
  };
  return types;
}

// Cell types MED has and hsb does not read, with their dimension.
struct UnreadType {
  med_geometry_type med;
  const char* name;
  int dimension;
};
const UnreadType unread_types[] = {{MED_OCTA12, "OCTA12", 3},
                                   {MED_PENTA18, "PENTA18", 3},
                                   {MED_POLYHEDRON, "POLYHEDRON", 3},
                                   {MED_POLYGON, "POLYGON", 2},
                                   {MED_POLYGON2, "POLYGON2", 2}};

// A mesh's or a field's name: a C string of at most `width`.
std::string c_string(const char* text, std::size_t width) { return std::string(text, strnlen(text, width)); }

// A component's name: fixed-width, padded with blanks.
std::string trimmed(const char* text, std::size_t width) {
  std::string s = c_string(text, width);
  s.erase(s.find_last_not_of(' ') + 1);
  return s;
}

// The file as the MED library opens it, closed at the end of scope.
class MedFile {
 public:
  explicit MedFile(const std::string& path) : path_(path) {
    std::error_code error;
    size_ = double(std::filesystem::file_size(path, error));
    if (error) throw DataError(path + ": cannot read it: " + error.message());
    med_bool hdf5 = MED_FALSE, med = MED_FALSE;
    MEDfileCompatibility(path.c_str(), &hdf5, &med);
    if (!hdf5)
      throw DataError(path + ": not a MED file: the HDF5 library cannot open it (MED is HDF5 inside; truncated, "
                      "or another format)");
    id_ = MEDfileOpen(path.c_str(), MED_ACC_RDONLY);
    if (id_ < 0) throw DataError(path + ": the MED library cannot open it: the HDF5 inside is truncated or damaged");
    if (!med) {
      MEDfileClose(id_);
      throw DataError(path + ": an HDF5 file, but no MED file the MED library 4.1 reads (it has no MED version, "
                      "INFOS_GENERALES, of 2.2 or later)");
    }
  }
  ~MedFile() { MEDfileClose(id_); }
  MedFile(const MedFile&) = delete;
  MedFile& operator=(const MedFile&) = delete;
  med_idt id() const { return id_; }
  const std::string& path() const { return path_; }

  // Refuses `count` values of `bytes` each that the file cannot hold.
  void check_fits(double count, std::size_t bytes, const std::string& what) const {
    if (count >= 0 && count * double(bytes) <= size_) return;
    throw DataError(path_ + ": " + what + " declares " + std::to_string(static_cast<long long>(count)) +
                    " values, more than its " + std::to_string(static_cast<long long>(size_)) +
                    " bytes hold: the file is corrupt");
  }

 private:
  std::string path_;
  med_idt id_ = -1;
  double size_ = 0;
};

// One type's cells, from `first` on in the grid, with their nodes as MED
// lists them (0-based): per-element-node values come in that order.
struct CellBlock {
  const CellType* type = nullptr;
  vtkIdType first = 0, count = 0;
  std::vector<vtkIdType> med_nodes;
};

struct Mesh {
  std::string name;
  med_int numdt = MED_NO_DT, numit = MED_NO_IT;  // its first computing step
  med_int space = 0;                             // its axes
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  std::vector<CellBlock> blocks;
};

med_int entity_count(const MedFile& file, const Mesh& mesh, med_entity_type entity, med_geometry_type type,
                     med_data_type data) {
  med_bool changed = MED_FALSE, transformed = MED_FALSE;
  const med_int n = MEDmeshnEntity(file.id(), mesh.name.c_str(), mesh.numdt, mesh.numit, entity, type, data,
                                   entity == MED_NODE ? MED_NO_CMODE : MED_NODAL, &changed, &transformed);
  return std::max<med_int>(n, 0);
}

// The file's first mesh as its description says (a mesh that moves has
// several computing steps: the first is drawn).
Mesh first_mesh(const MedFile& file) {
  const std::string& path = file.path();
  if (MEDnMesh(file.id()) < 1) throw DataError(path + ": the MED file has no mesh");
  const med_int axes = MEDmeshnAxis(file.id(), 1);
  if (axes < 0) throw DataError(path + ": the MED library cannot read its first mesh's axes");
  if (axes < 1 || axes > 3) throw DataError(path + ": its first mesh has " + std::to_string(axes) + " axes");
  Mesh mesh;
  char name[MED_NAME_SIZE + 1] = {}, description[MED_COMMENT_SIZE + 1] = {}, dt_unit[MED_SNAME_SIZE + 1] = {};
  std::vector<char> axis_names(std::size_t(axes) * MED_SNAME_SIZE + 1, '\0'), axis_units(axis_names.size(), '\0');
  med_int dimension = 0, steps = 0;
  med_mesh_type kind = MED_UNDEF_MESH_TYPE;
  med_sorting_type sorting = MED_SORT_DTIT;
  med_axis_type axis_type = MED_CARTESIAN;
  if (MEDmeshInfo(file.id(), 1, name, &mesh.space, &dimension, &kind, description, dt_unit, &sorting, &steps,
                  &axis_type, axis_names.data(), axis_units.data()) < 0)
    throw DataError(path + ": the MED library cannot read its first mesh's description");
  mesh.name = c_string(name, MED_NAME_SIZE);
  if (kind != MED_UNSTRUCTURED_MESH)
    throw DataError(path + ": its mesh \"" + mesh.name + "\" is a structured grid, which hsb does not read; " +
                    "convert it to .vtu (ParaView's MED reader, Save Data)");
  if (mesh.space != axes)
    throw DataError(path + ": its mesh \"" + mesh.name + "\" says it has " + std::to_string(mesh.space) +
                    " axes but names " + std::to_string(axes));
  med_float time = 0;
  if (steps > 0) MEDmeshComputationStepInfo(file.id(), name, 1, &mesh.numdt, &mesh.numit, &time);
  return mesh;
}

// The nodes of `mesh` as VTK's points (z = 0 for a mesh in a plane).
vtkSmartPointer<vtkPoints> read_points(const MedFile& file, const Mesh& mesh) {
  const med_int nodes = entity_count(file, mesh, MED_NODE, MED_NONE, MED_COORDINATE);
  if (nodes < 1) throw DataError(file.path() + ": its mesh \"" + mesh.name + "\" has no nodes");
  const std::size_t space = std::size_t(mesh.space);
  file.check_fits(double(nodes) * double(space), sizeof(med_float), "the mesh's coordinates");
  std::vector<med_float> xyz(std::size_t(nodes) * space);
  if (MEDmeshNodeCoordinateRd(file.id(), mesh.name.c_str(), mesh.numdt, mesh.numit, MED_FULL_INTERLACE, xyz.data()) < 0)
    throw DataError(file.path() + ": the MED library cannot read the coordinates of mesh \"" + mesh.name + "\"");
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nodes);
  for (vtkIdType i = 0; i < nodes; ++i) {
    double p[3] = {0, 0, 0};
    for (std::size_t a = 0; a < space; ++a) p[a] = xyz[std::size_t(i) * space + a];
    points->SetPoint(i, p);
  }
  return points;
}

// The file's first mesh: its points, and its cells of the highest
// dimension it has in VTK's order (lower ones are a 3-D mesh's faces and
// edges: groups, boundary conditions).
Mesh read_mesh(const MedFile& file) {
  const std::string& path = file.path();
  Mesh mesh = first_mesh(file);
  mesh.grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh.grid->SetPoints(read_points(file, mesh));
  const vtkIdType nodes = mesh.grid->GetNumberOfPoints();
  int highest = 0;
  for (const CellType& t : cell_types())
    if (entity_count(file, mesh, MED_CELL, t.med, MED_CONNECTIVITY) > 0) highest = std::max(highest, t.dimension());
  for (const UnreadType& t : unread_types)
    if (t.dimension >= highest && entity_count(file, mesh, MED_CELL, t.med, MED_CONNECTIVITY) > 0)
      throw DataError(path + ": its mesh \"" + mesh.name + "\" has " + t.name + " cells, which hsb does not read " +
                      "(it reads TETRA4, PYRA5, PENTA6, HEXA8, their quadratic forms, HEXA27, triangles and " +
                      "quadrangles); convert it to .vtu (ParaView's MED reader, Save Data)");
  if (highest < 2) throw DataError(path + ": its mesh \"" + mesh.name + "\" has no cells of 2 or 3 dimensions");

  for (const CellType& t : cell_types()) {
    const med_int cells = t.dimension() == highest ? entity_count(file, mesh, MED_CELL, t.med, MED_CONNECTIVITY) : 0;
    if (cells < 1) continue;
    const std::size_t n = std::size_t(t.nodes());
    file.check_fits(double(cells) * double(n), sizeof(med_int), std::string("its ") + t.name + " cells");
    std::vector<med_int> connectivity(std::size_t(cells) * n);
    if (MEDmeshElementConnectivityRd(file.id(), mesh.name.c_str(), mesh.numdt, mesh.numit, MED_CELL, t.med, MED_NODAL,
                                     MED_FULL_INTERLACE, connectivity.data()) < 0)
      throw DataError(path + ": the MED library cannot read the " + t.name + " cells of mesh \"" + mesh.name + "\"");
    CellBlock block{&t, mesh.grid->GetNumberOfCells(), cells, {}};
    block.med_nodes.reserve(connectivity.size());
    std::vector<vtkIdType> ids(n);
    for (std::size_t c = 0; c < std::size_t(cells); ++c) {
      for (std::size_t k = 0; k < n; ++k) {
        const med_int node = connectivity[c * n + k];
        if (node < 1 || node > nodes)
          throw DataError(path + ": " + t.name + " cell " + std::to_string(c + 1) + " names node " +
                          std::to_string(node) + "; the mesh's nodes are 1 to " + std::to_string(nodes));
        block.med_nodes.push_back(node - 1);
      }
      for (std::size_t k = 0; k < n; ++k) ids[k] = block.med_nodes[c * n + std::size_t(t.order[k])];
      mesh.grid->InsertNextCell(t.vtk, vtkIdType(n), ids.data());
    }
    mesh.blocks.push_back(std::move(block));
  }
  return mesh;
}

// A computing step (MED's time step number and iteration) and its time.
struct Step {
  med_int numdt = MED_NO_DT, numit = MED_NO_IT;
  double time = 0;
  bool operator<(const Step& o) const { return numdt != o.numdt ? numdt < o.numdt : numit < o.numit; }
  bool operator==(const Step& o) const { return numdt == o.numdt && numit == o.numit; }
};

struct Field {
  std::string name;
  std::vector<std::string> components;
  med_field_type type = MED_FLOAT64;
  std::vector<Step> steps;
};

// The fields of floating-point values on mesh `mesh_name`.
std::vector<Field> read_fields(const MedFile& file, const std::string& mesh_name) {
  std::vector<Field> fields;
  const med_int count = MEDnField(file.id());
  for (int i = 1; i <= count; ++i) {
    const med_int components = MEDfieldnComponent(file.id(), i);
    if (components < 0)
      throw DataError(file.path() + ": the MED library cannot read the components of field " + std::to_string(i));
    file.check_fits(double(components) * MED_SNAME_SIZE, 1, "field " + std::to_string(i) + "'s component names");
    if (components < 1) continue;
    char name[MED_NAME_SIZE + 1] = {}, mesh[MED_NAME_SIZE + 1] = {}, dt_unit[MED_SNAME_SIZE + 1] = {};
    std::vector<char> names(std::size_t(components) * MED_SNAME_SIZE + 1, '\0'), units(names.size(), '\0');
    med_bool local = MED_TRUE;
    med_int steps = 0;
    Field field;
    if (MEDfieldInfo(file.id(), i, name, mesh, &local, &field.type, names.data(), units.data(), dt_unit, &steps) < 0)
      throw DataError(file.path() + ": the MED library cannot read the description of field " + std::to_string(i));
    if (c_string(mesh, MED_NAME_SIZE) != mesh_name || (field.type != MED_FLOAT64 && field.type != MED_FLOAT32))
      continue;
    field.name = c_string(name, MED_NAME_SIZE);
    for (std::size_t c = 0; c < std::size_t(components); ++c)
      field.components.push_back(trimmed(names.data() + c * MED_SNAME_SIZE, MED_SNAME_SIZE));
    file.check_fits(double(steps), 1, "field \"" + field.name + "\"'s list of steps");
    for (int s = 1; s <= steps; ++s) {
      Step step;
      med_float time = 0;
      if (MEDfieldComputingStepInfo(file.id(), name, s, &step.numdt, &step.numit, &time) < 0)
        throw DataError(file.path() + ": the MED library cannot read step " + std::to_string(s) + " of field \"" +
                        field.name + "\"");
      step.time = time;
      field.steps.push_back(step);
    }
    fields.push_back(std::move(field));
  }
  return fields;
}

// Every step any field has, in order.
std::vector<Step> all_steps(const std::vector<Field>& fields) {
  std::set<Step> steps;
  for (const Field& f : fields) steps.insert(f.steps.begin(), f.steps.end());
  return {steps.begin(), steps.end()};
}

// A field's values at one step on one support (the nodes, or one cell
// type's cells or element nodes), under one profile: `points` values of
// every component (Gauss points, a cell's nodes) for each of `entities`
// (0-based: all in order without a profile, else those it lists).
struct Support {
  std::vector<double> values;
  std::vector<vtkIdType> entities;
  med_int points = 1;
};

std::vector<Support> supports(const MedFile& file, const Field& field, const Step& step, med_entity_type entity,
                              med_geometry_type type, vtkIdType entities) {
  std::vector<Support> found;
  const char* name = field.name.c_str();
  const std::string what = "field \"" + field.name + "\" at step (" + std::to_string(step.numdt) + ", " +
                           std::to_string(step.numit) + ")";
  char profile[MED_NAME_SIZE + 1] = {}, localization[MED_NAME_SIZE + 1] = {};
  const med_int profiles =
      MEDfieldnProfile(file.id(), name, step.numdt, step.numit, entity, type, profile, localization);
  const double components = double(field.components.size());
  for (int p = 1; p <= profiles; ++p) {
    Support s;
    med_int profile_size = 0;
    const med_int n = MEDfieldnValueWithProfile(file.id(), name, step.numdt, step.numit, entity, type, p,
                                                MED_COMPACT_PFLMODE, profile, &profile_size, localization, &s.points);
    if (n < 0) throw DataError(file.path() + ": the MED library cannot read how many values " + what + " has");
    if (n == 0) continue;
    if (s.points < 1 || n > entities)
      throw DataError(file.path() + ": " + what + " has " + std::to_string(n) + " × " + std::to_string(s.points) +
                      " values for " + std::to_string(entities) + " entities");
    const double values = double(n) * double(s.points) * components;
    file.check_fits(values, field.type == MED_FLOAT64 ? 8 : 4, what);
    s.values.resize(std::size_t(values));
    std::vector<float> singles(field.type == MED_FLOAT32 ? s.values.size() : 0);
    unsigned char* into = field.type == MED_FLOAT64 ? reinterpret_cast<unsigned char*>(s.values.data())
                                                    : reinterpret_cast<unsigned char*>(singles.data());
    if (MEDfieldValueWithProfileRd(file.id(), name, step.numdt, step.numit, entity, type, MED_COMPACT_PFLMODE, profile,
                                   MED_FULL_INTERLACE, MED_ALL_CONSTITUENT, into) < 0)
      throw DataError(file.path() + ": the MED library cannot read the values of " + what);
    std::copy(singles.begin(), singles.end(), s.values.begin());
    const std::string profile_name = c_string(profile, MED_NAME_SIZE);
    if (profile_name.empty() || profile_name == MED_NO_PROFILE_INTERNAL) {
      for (vtkIdType e = 0; e < n; ++e) s.entities.push_back(e);
    } else {
      std::vector<med_int> ids(static_cast<std::size_t>(n));
      if (MEDprofileSizeByName(file.id(), profile) != n || MEDprofileRd(file.id(), profile, ids.data()) < 0)
        throw DataError(file.path() + ": the MED library cannot read the profile \"" + profile_name + "\" of " + what);
      for (const med_int id : ids) {
        if (id < 1 || id > entities)
          throw DataError(file.path() + ": the profile \"" + profile_name + "\" of " + what + " lists entity " +
                          std::to_string(id) + " of " + std::to_string(entities));
        s.entities.push_back(id - 1);
      }
    }
    found.push_back(std::move(s));
  }
  return found;
}

// A field's values at one step, one per point or per cell (NaN: none
// there), and what was done to make them so.
struct Values {
  std::vector<double> data;
  bool on_points = true;
  std::string note;
};

std::optional<Values> field_values(const MedFile& file, const Mesh& mesh, const Field& field, const Step& step) {
  const std::size_t nc = field.components.size();
  const std::size_t points = std::size_t(mesh.grid->GetNumberOfPoints());
  Values v;
  // Per node.
  if (const std::vector<Support> found = supports(file, field, step, MED_NODE, MED_NONE, vtkIdType(points));
      !found.empty()) {
    v.data.assign(points * nc, NAN);
    for (const Support& s : found)
      for (std::size_t i = 0; i < s.entities.size(); ++i)
        for (std::size_t c = 0; c < nc; ++c)
          v.data[std::size_t(s.entities[i]) * nc + c] = s.values[i * std::size_t(s.points) * nc + c];
    return v;
  }
  // Per element node: the mean of the cells' values at each point.
  std::vector<double> sums(points * nc, 0.0);
  std::vector<int> counts(points, 0);
  for (const CellBlock& b : mesh.blocks)
    for (const Support& s : supports(file, field, step, MED_NODE_ELEMENT, b.type->med, b.count)) {
      const std::size_t n = std::size_t(b.type->nodes());
      if (s.points != b.type->nodes())
        throw DataError(file.path() + ": field \"" + field.name + "\" has " + std::to_string(s.points) +
                        " values per element node of a " + b.type->name + " cell, of " + std::to_string(n) + " nodes");
      for (std::size_t i = 0; i < s.entities.size(); ++i)
        for (std::size_t k = 0; k < n; ++k) {
          const std::size_t point = std::size_t(b.med_nodes[std::size_t(s.entities[i]) * n + k]);
          ++counts[point];
          for (std::size_t c = 0; c < nc; ++c) sums[point * nc + c] += s.values[(i * n + k) * nc + c];
        }
    }
  if (std::any_of(counts.begin(), counts.end(), [](int c) { return c > 0; })) {
    for (std::size_t p = 0; p < points; ++p)
      for (std::size_t c = 0; c < nc; ++c) sums[p * nc + c] = counts[p] ? sums[p * nc + c] / counts[p] : NAN;
    v.data = std::move(sums);
    v.note = "is given per element node in the file (MED_NODE_ELEMENT): the values of the cells that meet at a "
             "point are averaged there";
    return v;
  }
  // Per cell, or per Gauss point: the mean of a cell's points.
  v.on_points = false;
  v.data.assign(std::size_t(mesh.grid->GetNumberOfCells()) * nc, NAN);
  med_int most = 0;
  for (const CellBlock& b : mesh.blocks)
    for (const Support& s : supports(file, field, step, MED_CELL, b.type->med, b.count)) {
      most = std::max(most, s.points);
      const std::size_t g = std::size_t(s.points);
      for (std::size_t i = 0; i < s.entities.size(); ++i)
        for (std::size_t c = 0; c < nc; ++c) {
          double sum = 0;
          for (std::size_t k = 0; k < g; ++k) sum += s.values[(i * g + k) * nc + c];
          v.data[std::size_t(b.first + s.entities[i]) * nc + c] = sum / double(g);
        }
    }
  if (most == 0) return std::nullopt;
  if (most > 1)
    v.note = "is given at " + std::to_string(most) + " Gauss points per cell in the file: each cell's are averaged "
             "into one value";
  return v;
}

// Where each of VTK's six entries XX YY ZZ XY YZ XZ is among a field's
// components (-1: absent, zero), when their names are a symmetric tensor's:
// one prefix, then XX YY ZZ XY YZ XZ in any order, XX YY XY at least.
std::optional<std::array<int, 6>> tensor_entries(const std::vector<std::string>& names) {
  static const char* const suffixes[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  std::map<std::string, std::array<int, 6>> by_prefix;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& n = names[i];
    if (n.size() < 3) continue;
    std::string suffix = n.substr(n.size() - 2);
    if (suffix == "YX" || suffix == "ZY" || suffix == "ZX") std::swap(suffix[0], suffix[1]);
    for (std::size_t k = 0; k < 6; ++k)
      if (suffix == suffixes[k]) {
        std::array<int, 6>& entries =
            by_prefix.try_emplace(n.substr(0, n.size() - 2), std::array<int, 6>{-1, -1, -1, -1, -1, -1}).first->second;
        if (entries[k] >= 0) return std::nullopt;  // YX beside XY: no symmetric tensor
        entries[k] = int(i);
      }
  }
  std::optional<std::array<int, 6>> found;
  for (const auto& [prefix, entries] : by_prefix)
    if (entries[0] >= 0 && entries[1] >= 0 && entries[3] >= 0) {
      if (found) return std::nullopt;  // two (a shell's forces and moments): which one is unsaid
      found = entries;
    }
  return found;
}

// "SIGM_NOEU" of "RESU____SIGM_NOEU": Code_Aster pads the result's name to
// 8 characters with '_' and appends the field's type (4 letters, then where
// its values stand). Other names stay as they are.
std::string field_type(const std::string& name) {
  // At 12 characters, only after a padded name: 8 letters before 4 are more
  // often one word.
  if (name.size() != 17 && (name.size() != 12 || name[7] != '_')) return name;
  const auto word = [&](std::size_t at) {
    return std::all_of(name.begin() + std::ptrdiff_t(at), name.begin() + std::ptrdiff_t(at + 4), [](char c) {
             return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c));
           }) && std::isupper(static_cast<unsigned char>(name[at]));
  };
  const bool result = std::all_of(name.begin(), name.begin() + 8, [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  if (!result || !word(8) || (name.size() == 17 && (name[12] != '_' || !word(13)))) return name;
  return name.substr(8);
}

// How much a field of Code_Aster's `type` is the stress to draw: the nodal
// stress, the nodal generalized stress, a stress per element node
// (averaged onto the points), one per Gauss point or cell. 4: none.
int stress_rank(const std::string& type, bool on_points) {
  if (type == "SIGM_NOEU") return 0;
  if (type == "SIEF_NOEU") return 1;
  if (type.rfind("SIGM_", 0) != 0 && type.rfind("SIEF_", 0) != 0) return 4;
  return on_points ? 2 : 3;
}

// The array `name` of `field`'s `values`; a tensor's in VTK's order, which
// is recorded.
vtkSmartPointer<vtkDoubleArray> field_array(const Field& field, const std::string& name, const Values& values,
                                            vtkFieldData* records) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  const std::size_t nc = field.components.size(), tuples = values.data.size() / nc;
  const std::optional<std::array<int, 6>> entries = tensor_entries(field.components);
  if (!entries) {
    array->SetNumberOfComponents(int(nc));
    array->SetNumberOfTuples(vtkIdType(tuples));
    for (std::size_t c = 0; c < nc; ++c) array->SetComponentName(vtkIdType(c), field.components[c].c_str());
    std::copy(values.data.begin(), values.data.end(), array->GetPointer(0));
    return array;
  }
  static const char* const vtk_entries[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  array->SetNumberOfComponents(6);
  array->SetNumberOfTuples(vtkIdType(tuples));
  std::string names, absent;
  for (const std::string& c : field.components) names += (names.empty() ? "" : " ") + c;
  for (std::size_t k = 0; k < 6; ++k) {
    const int from = (*entries)[k];
    array->SetComponentName(vtkIdType(k), from >= 0 ? field.components[std::size_t(from)].c_str() : vtk_entries[k]);
    if (from < 0) absent += std::string(absent.empty() ? "" : " and ") + vtk_entries[k];
    for (std::size_t t = 0; t < tuples; ++t)
      array->SetComponent(vtkIdType(t), int(k), from >= 0 ? values.data[t * nc + std::size_t(from)] : 0.0);
  }
  const std::size_t used = 6 - std::size_t(std::count(entries->begin(), entries->end(), -1));
  const bool aster = names == "SIXX SIYY SIZZ SIXY SIXZ SIYZ" || names == "EPXX EPYY EPZZ EPXY EPXZ EPYZ";
  record_component_order(records, name,
                         (aster ? "Code_Aster's " : "its components ") + names + ", by the field's component names" +
                             (absent.empty() ? "" : "; " + absent + " absent, taken as zero") +
                             (nc > used ? "; the others left out" : ""));
  return array;
}

// The step asked for (-1: the first) among the file's.
Step step_asked(const std::string& path, const std::vector<Step>& steps, int step) {
  if (step > 0 && step >= int(steps.size()))
    throw DataError(path + ": data.step " + std::to_string(step) + " is beyond its " + std::to_string(steps.size()) +
                    " computing steps" +
                    (steps.empty() ? std::string(" (it has no fields)")
                                   : " (0 to " + std::to_string(steps.size() - 1) + ")"));
  return steps.empty() ? Step{} : steps[std::size_t(std::max(step, 0))];
}

vtkSmartPointer<vtkDataSet> read_med(const std::string& path, const ReadRequest& request, const VtkSession&) {
  const MedFile file(path);
  const Mesh mesh = read_mesh(file);
  const std::vector<Field> fields = read_fields(file, mesh.name);
  const Step step = step_asked(path, all_steps(fields), request.step);
  vtkFieldData* records = mesh.grid->GetFieldData();
  // Two results' fields of one type keep their whole names, apart.
  std::map<std::string, int> of_type;
  for (const Field& f : fields) ++of_type[field_type(f.name)];
  int best_rank = 4;
  vtkDataArray* best = nullptr;
  vtkDataSetAttributes* best_attributes = nullptr;
  for (const Field& f : fields) {
    if (std::find(f.steps.begin(), f.steps.end(), step) == f.steps.end()) continue;
    const std::optional<Values> values = field_values(file, mesh, f, step);
    if (!values) continue;  // on cells not read (a 3-D mesh's faces)
    const std::string type = field_type(f.name), name = of_type[type] > 1 ? f.name : type;
    const vtkSmartPointer<vtkDoubleArray> array = field_array(f, name, *values, records);
    vtkDataSetAttributes* attributes = values->on_points ? static_cast<vtkDataSetAttributes*>(mesh.grid->GetPointData())
                                                         : mesh.grid->GetCellData();
    attributes->AddArray(array);
    if (!values->note.empty()) record_reading_note(records, name, values->note);
    const int rank = stress_rank(type, values->on_points);
    if (array->GetNumberOfComponents() == 6 && rank < best_rank) {
      best_rank = rank;
      best = array;
      best_attributes = attributes;
    }
  }
  if (best) best_attributes->SetTensors(best);
  return mesh.grid;
}

// The times of the computing steps of the fields on the file's first mesh,
// in order; none for a file of one step or none.
std::vector<double> med_times(const std::string& path) {
  const MedFile file(path);
  const std::vector<Step> steps = all_steps(read_fields(file, first_mesh(file).name));
  if (steps.size() < 2) return {};
  std::vector<double> times;
  for (const Step& s : steps) times.push_back(s.time);
  return times;
}

}  // namespace

const FormatReader med_reader{read_med, nullptr, nullptr, med_times};

}  // namespace hsb

// Gmsh meshes (.msh: MSH 2.2 and 4.1, ASCII or binary) with their
// post-processing views, read through Gmsh's own library (libgmsh, its C
// API gmshc.h; Debian's libgmsh4.8), not a parser of hsb's: the nodes, the
// elements of the highest dimension there is (a volume mesh's faces and
// edges are its boundaries and physical groups, and carry no volume), and
// each view as an array named as the view:
//  - $NodeData: point data;
//  - $ElementData: cell data;
//  - $ElementNodeData (values per element and node, discontinuous across
//    elements): averaged onto the points, each node the mean of the values
//    its kept elements give it, so that it samples like point data;
//  - components as Gmsh writes them: 9 are its tensor layout, the 3×3 row
//    by row (XX XY XZ YX YY YZ ZX ZY ZZ), which is VTK's; 3 a vector; 1 a
//    scalar. Gmsh has no layout of 6 (its views' tensors have 9): a view
//    of 6 is read in VTK's order, recorded as a default data.components
//    may overrule.
// Gmsh's node orders are turned into VTK's (most linear cells share them,
// the wedge's base turns the other way; the quadratic tetrahedron swaps two
// midside nodes, the quadratic hexahedron, wedge and pyramid number their
// edges otherwise); elements VTK has no cell for (third order and beyond)
// are read by their corner nodes. Points and cells come in the order of
// their tags, which may have gaps: the views' tags are mapped to them.
// A view of several time steps is read at ReadRequest::step, steps counted
// among those that hold data; a view with one step is the same at every
// step, and one without the step asked for is left out.
//
// The library is not linked but opened at the first read, in the child
// process that parses the file (field/reading/gmsh_library.h says why).
//
// Gmsh keeps global state: one session at a time, initialised and
// finalised around each read. It trusts some counts a file declares and
// allocates them before reading (a view's entity count, its time step
// index), so those are checked first against the bytes there are.
// Internal to field/.

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "base/input_file.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"
#include "field/reading/gmsh_library.h"

namespace hsb {
namespace {

// Gmsh allocates every time step up to a view's step index (about 300
// bytes each): an index beyond this is a corrupt header, not a simulation.
constexpr long long most_time_steps = 100000;

// ---- The file, checked before Gmsh sees it ----

// The leading integer of the next line, as Gmsh reads a header's counts.
bool leading_integer(std::istream& in, long long& value) {
  std::string line;
  if (!std::getline(in, line)) return false;
  std::istringstream words(line);
  return bool(words >> value);
}

// Checks the header of the data section at `offset` (after its "$NodeData"
// line) against the `size` bytes of the file: the counts Gmsh allocates
// before it reads the values (header lines are text in binary files too).
void check_data_header(const std::string& path, std::ifstream& file, std::uint64_t offset, std::uint64_t size,
                       const std::string& section, bool binary) {
  const auto refuse = [&](const std::string& what) {
    throw DataError(path + ": its " + section + " section at byte " + std::to_string(offset) + " is corrupt: " + what);
  };
  file.clear();
  file.seekg(std::streamoff(offset));
  // String tags (name, interpolation), real tags (time), integer tags
  // (step index, components, entities, partition), each a count then lines.
  std::vector<long long> integers;
  for (const std::string kind : {"string", "real", "integer"}) {
    long long count = 0, value = 0;
    if (!leading_integer(file, count) || count < 0 || count > 100)
      refuse("no count of " + kind + " tags (0 to 100) where one belongs");
    for (std::string line; count > 0; --count)
      if (kind == "integer" ? !leading_integer(file, value) : !std::getline(file, line))
        refuse("it ends in its " + kind + " tags");
      else if (kind == "integer")
        integers.push_back(value);
  }
  integers.resize(std::max<std::size_t>(integers.size(), 3), 0);
  const long long step = integers[0], components = integers[1], entities = integers[2];
  if (step < 0 || step > most_time_steps)
    refuse("time step index " + std::to_string(step) + " (0 to " + std::to_string(most_time_steps) + ")");
  if (entities <= 0) return;  // Gmsh reads no values
  if (components < 1) refuse(std::to_string(components) + " components per value");
  // The fewest bytes an entity takes: its tag and values, 4 and 8 bytes
  // each in binary, a digit and a space each in text.
  const double least = double(entities) * (binary ? 4.0 + 8.0 * double(components) : 2.0 + 2.0 * double(components));
  const std::uint64_t here = std::uint64_t(std::max<std::streamoff>(file.tellg(), 0));
  const std::uint64_t left = size - std::min(size, here);
  if (least > double(left))
    refuse(std::to_string(entities) + " entities of " + std::to_string(components) + " components, more than its " +
           std::to_string(left) + " bytes left hold");
}

// Refuses what Gmsh would not read as MSH, or would read as something else:
// it picks its parser by the file's extension first (a .py or .exe it
// would run), then by its first line, and parses any other text as a .geo
// script, which can run commands. Then checks the data sections' headers.
void check_gmsh_file(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".msh") throw DataError(path + ": Gmsh reads a mesh by its extension: name it .msh");
  const std::string head = file_head(path, 256);
  if (head.rfind("$MeshFormat", 0) != 0)
    throw DataError(path + ": not a Gmsh mesh: it does not begin with $MeshFormat");
  std::istringstream format(head.substr(head.find('\n') + 1));
  double version = 0;
  int binary = 0;
  if (!(format >> version >> binary) || version < 2 || version >= 5)
    throw DataError(path + ": its $MeshFormat gives no MSH version Gmsh 4.8 reads (2.x, 4.x)");

  // Every line that starts a data section, found byte by byte as Gmsh finds
  // them (a line beginning with '$'), whatever binary data lies between.
  std::ifstream file(path, std::ios::binary);
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  std::vector<std::pair<std::string, std::uint64_t>> sections;
  std::vector<char> block(1 << 20);
  std::string line;
  bool at_line_start = false, in_marker = false;
  std::uint64_t position = 0;
  while (file.read(block.data(), std::streamsize(block.size())) || file.gcount() > 0) {
    for (std::streamsize i = 0; i < file.gcount(); ++i, ++position) {
      const char c = block[std::size_t(i)];
      if (in_marker && (c == '\n' || c == '\r' || line.size() > 20)) {
        if (line == "$NodeData" || line == "$ElementData" || line == "$ElementNodeData")
          sections.emplace_back(line, position + 1 + (c == '\r'));
        in_marker = false;
      } else if (in_marker) {
        line += c;
      } else if (at_line_start && c == '$') {
        in_marker = true;
        line = "$";
      }
      at_line_start = c == '\n';
    }
  }
  for (const auto& [section, offset] : sections) check_data_header(path, file, offset, size, section, binary != 0);
}

// ---- Gmsh's session ----

// The file opened by Gmsh, quiet, its session finalised at the end of
// scope. Gmsh is global: one at a time. A session of its own for each
// file, because an error half-way leaves Gmsh's state half-way (its file
// lock held), which only a new session resets.
class GmshFile {
 public:
  explicit GmshFile(const std::string& path) {
    check_gmsh_file(path);
    load_gmsh(path);
    if (open_) throw DataError(path + ": Gmsh is reading another file in this process");
    open_ = true;
    try {
      gmsh_call(path, gmsh.initialize, 0, nullptr, 0);  // no configuration files of the user's
      gmsh_call(path, gmsh.set_number, "General.Terminal", 0.0);
      // 3: every error throws (which the C API catches), whether or not a
      // GUI runs (2), never exits (4).
      gmsh_call(path, gmsh.set_number, "General.AbortOnError", 3.0);
      gmsh_call(path, gmsh.open, path.c_str());
    } catch (...) {
      close();
      throw;
    }
  }
  ~GmshFile() { close(); }
  GmshFile(const GmshFile&) = delete;
  GmshFile& operator=(const GmshFile&) = delete;

 private:
  static void close() {
    int ignored = 0;
    gmsh.finalize(&ignored);
    open_ = false;
  }
  static inline bool open_ = false;
};

// ---- The mesh ----

// A Gmsh element type VTK has a cell for: VTK's node i is Gmsh's node
// order[i] (empty: the same order). From Gmsh's node ordering
// (gmsh.info/doc/texinfo/gmsh.html#Node-ordering, checked against
// gmsh::model::mesh::getElementProperties) and VTK's cell headers; each
// order read so passes vtkCellValidator (faces outward, convex), and
// agrees with Gmsh's own VTK export (MElement::getVertexVTK).
struct CellType {
  int gmsh, vtk;
  std::vector<int> order;
};

const std::vector<CellType>& cell_types() {
  static const std::vector<CellType> types{
      {15, VTK_VERTEX, {}}, {1, VTK_LINE, {}}, {8, VTK_QUADRATIC_EDGE, {}},
      {2, VTK_TRIANGLE, {}}, {3, VTK_QUAD, {}}, {9, VTK_QUADRATIC_TRIANGLE, {}},
      {16, VTK_QUADRATIC_QUAD, {}}, {10, VTK_BIQUADRATIC_QUAD, {}},
      {4, VTK_TETRA, {}}, {5, VTK_HEXAHEDRON, {}}, {7, VTK_PYRAMID, {}},
      // VTK's linear wedge turns its base (0, 1, 2) outward, away from
      // (3, 4, 5); Gmsh's prism turns it inward. VTK's quadratic wedges
      // take Gmsh's turn (their validator says so; so does Gmsh's export).
      {6, VTK_WEDGE, {0, 2, 1, 3, 5, 4}},
      // Gmsh's edges 30, 32, 31 after 01 12 20; VTK's 30, 31, 32.
      {11, VTK_QUADRATIC_TETRA, {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}},
      // Gmsh numbers a hexahedron's edges 01 03 04 12 15 23 26 37 45 47 56 67;
      // VTK bottom, top, then the vertical ones: 01 12 23 30 45 56 67 74 04 15 26 37.
      {17, VTK_QUADRATIC_HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 16, 18, 19, 17, 10, 12, 14, 15}},
      // Faces: Gmsh z−, y−, x−, x+, y+, z+, VTK x−, x+, y−, y+, z−, z+; then the centre.
      {12, VTK_TRIQUADRATIC_HEXAHEDRON, {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                                         19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26}},
      // Gmsh's wedge edges 01 02 03 12 14 25 34 35 45; VTK's 01 12 20 34 45 53 03 14 25.
      {18, VTK_QUADRATIC_WEDGE, {0, 1, 2, 3, 4, 5, 6, 9, 7, 12, 14, 13, 8, 10, 11}},
      // Quad faces: Gmsh 0143, 0253, 1254; VTK 0143, 1254, 2035.
      {13, VTK_BIQUADRATIC_QUADRATIC_WEDGE, {0, 1, 2, 3, 4, 5, 6, 9, 7, 12, 14, 13, 8, 10, 11, 15, 17, 16}},
      // Gmsh's pyramid edges 01 03 04 12 14 23 24 34; VTK's 01 12 23 30 04 14 24 34.
      {19, VTK_QUADRATIC_PYRAMID, {0, 1, 2, 3, 4, 5, 8, 10, 6, 7, 9, 11, 12}},
  };
  return types;
}

const CellType* cell_type(int gmsh_type) {
  for (const CellType& c : cell_types())
    if (c.gmsh == gmsh_type) return &c;
  return nullptr;
}

// The linear Gmsh type of an element read by its corners (Gmsh's primary
// nodes, which come first): by its dimension and number of corners.
const CellType* corner_type(int dimension, int corners) {
  switch (dimension * 100 + corners) {
    case 1: return cell_type(15);
    case 102: return cell_type(1);
    case 203: return cell_type(2);
    case 204: return cell_type(3);
    case 304: return cell_type(4);
    case 305: return cell_type(7);
    case 306: return cell_type(6);
    case 308: return cell_type(5);
    default: return nullptr;
  }
}

struct GmshMesh {
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  std::unordered_map<std::size_t, vtkIdType> point_of;  // node tag → point
  std::unordered_map<std::size_t, vtkIdType> cell_of;   // element tag (kept) → cell
  std::unordered_set<std::size_t> left_out;              // element tags of lower dimension
  // Each cell's points in Gmsh's node order (all its nodes), from
  // first_node[cell]: where its ElementNodeData values go.
  std::vector<vtkIdType> gmsh_nodes;
  std::vector<std::size_t> first_node;
};

GmshMesh read_mesh(const std::string& path) {
  GmshMesh mesh;
  mesh.grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  GmshArray<std::size_t> node_tags;
  GmshArray<double> coordinates, parametric;
  gmsh_call(path, gmsh.nodes, &node_tags.data, &node_tags.length, &coordinates.data, &coordinates.length,
            &parametric.data, &parametric.length, -1, -1, 0, 0);
  if (node_tags.empty()) throw DataError(path + ": Gmsh reads no nodes in it: it holds no mesh");
  if (coordinates.size() != 3 * node_tags.size())
    throw DataError(path + ": Gmsh gives " + std::to_string(coordinates.size()) + " coordinates for " +
                    std::to_string(node_tags.size()) + " nodes");
  // Points and cells in the order of their tags, as the file numbers them
  // (Gmsh hands them out by entity, which MSH 2.2 and 4.1 files differ in).
  std::vector<std::size_t> by_tag(node_tags.size());
  for (std::size_t i = 0; i < by_tag.size(); ++i) by_tag[i] = i;
  std::sort(by_tag.begin(), by_tag.end(), [&](std::size_t a, std::size_t b) { return node_tags[a] < node_tags[b]; });
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const std::size_t i : by_tag)
    if (mesh.point_of.emplace(node_tags[i], points->GetNumberOfPoints()).second)
      points->InsertNextPoint(&coordinates[3 * i]);
  mesh.grid->SetPoints(points);

  GmshArray<int> types;
  GmshArrays<std::size_t> element_tags, element_nodes;
  gmsh_call(path, gmsh.elements, &types.data, &types.length, &element_tags.data, &element_tags.lengths,
            &element_tags.count, &element_nodes.data, &element_nodes.lengths, &element_nodes.count, -1, -1);
  if (element_tags.size() != types.size() || element_nodes.size() != types.size())
    throw DataError(path + ": Gmsh gives " + std::to_string(element_tags.size()) + " lists of elements for " +
                    std::to_string(types.size()) + " element types");
  struct TypeInfo {
    std::string name;
    int dimension = 0, order = 0, nodes = 0, corners = 0;
  };
  std::vector<TypeInfo> info(types.size());
  int highest = -1;
  for (std::size_t t = 0; t < types.size(); ++t) {
    GmshArray<double> local;
    char* name = nullptr;
    gmsh_call(path, gmsh.element_properties, types[t], &name, &info[t].dimension, &info[t].order, &info[t].nodes,
              &local.data, &local.length, &info[t].corners);
    info[t].name = taken(name);
    if (!element_tags[t].empty()) highest = std::max(highest, info[t].dimension);
  }
  struct Kept {
    std::size_t tag, type, index;  // element tag; its type's and its own place in Gmsh's lists
  };
  std::vector<Kept> kept;
  std::vector<const CellType*> read_as(types.size(), nullptr);
  for (std::size_t t = 0; t < types.size(); ++t) {
    const GmshValues<std::size_t> tags = element_tags[t];
    if (info[t].dimension != highest) {
      mesh.left_out.insert(tags.begin(), tags.end());
      continue;
    }
    const CellType* known = cell_type(types[t]);
    read_as[t] = known ? known : corner_type(info[t].dimension, info[t].corners);
    if (!read_as[t])
      throw DataError(path + ": its elements of Gmsh type " + std::to_string(types[t]) + " (" + info[t].name +
                      ") have no VTK cell, nor corners VTK has one for");
    const std::size_t n = std::size_t(info[t].nodes);
    if (n == 0 || std::size_t(info[t].corners) > n || element_nodes[t].size() != n * tags.size())
      throw DataError(path + ": Gmsh gives " + std::to_string(element_nodes[t].size()) + " node tags for " +
                      std::to_string(tags.size()) + " elements of " + std::to_string(n) + " nodes (" + info[t].name + ")");
    for (std::size_t e = 0; e < tags.size(); ++e) kept.push_back({tags[e], t, e});
  }
  std::sort(kept.begin(), kept.end(), [](const Kept& a, const Kept& b) { return a.tag < b.tag; });
  mesh.grid->AllocateEstimate(vtkIdType(kept.size()), 4);
  std::vector<vtkIdType> ids;
  for (const Kept& k : kept) {
    const std::size_t n = std::size_t(info[k.type].nodes);
    mesh.first_node.push_back(mesh.gmsh_nodes.size());
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t node = element_nodes[k.type][k.index * n + j];
      const auto point = mesh.point_of.find(node);
      if (point == mesh.point_of.end())
        throw DataError(path + ": element " + std::to_string(k.tag) + " names node " + std::to_string(node) +
                        ", which is not among its nodes");
      mesh.gmsh_nodes.push_back(point->second);
    }
    // All its nodes, or its corners where VTK has no cell for them all.
    const CellType& cell = *read_as[k.type];
    ids.resize(cell.gmsh == types[k.type] ? n : std::size_t(info[k.type].corners));
    const vtkIdType* gmsh_order = mesh.gmsh_nodes.data() + mesh.first_node.back();
    for (std::size_t j = 0; j < ids.size(); ++j) ids[j] = gmsh_order[cell.order.empty() ? j : std::size_t(cell.order[j])];
    if (!mesh.cell_of.emplace(k.tag, mesh.grid->InsertNextCell(cell.vtk, vtkIdType(ids.size()), ids.data())).second)
      throw DataError(path + ": two elements have the tag " + std::to_string(k.tag));
  }
  mesh.first_node.push_back(mesh.gmsh_nodes.size());
  return mesh;
}

// ---- The views ----

struct ViewStep {
  int index = 0;  // Gmsh's step index
  double time = 0;
};

struct View {
  int tag = 0;
  std::string name;
  std::vector<ViewStep> steps;  // those that hold data, in order
};

// A view's data at one of its steps, as Gmsh gives it: the values of
// each entity (node or element) tagged.
struct StepData {
  std::string type;  // NodeData, ElementData, ElementNodeData, GaussPointData
  GmshArray<std::size_t> tags;
  GmshArrays<double> values;
  double time = 0;
  int components = 0;
};

void read_step(const std::string& path, int view, int step, StepData& data) {
  char* type = nullptr;
  gmsh_call(path, gmsh.model_data, view, step, &type, &data.tags.data, &data.tags.length, &data.values.data,
            &data.values.lengths, &data.values.count, &data.time, &data.components);
  data.type = taken(type);
}

std::vector<View> read_views(const std::string& path) {
  std::vector<View> views;
  GmshArray<int> tags;
  gmsh_call(path, gmsh.view_tags, &tags.data, &tags.length);
  for (const int tag : tags) {
    View view;
    view.tag = tag;
    int error = 0;
    const int index = gmsh.view_index(tag, &error);
    refuse_gmsh_error(path, error);
    const std::string option = "View[" + std::to_string(index) + "].";
    char* name = nullptr;
    gmsh_call(path, gmsh.get_string, (option + "Name").c_str(), &name);
    view.name = taken(name);
    double steps = 0;
    gmsh_call(path, gmsh.get_number, (option + "NbTimeStep").c_str(), &steps);
    for (int s = 0; s < int(steps); ++s) {
      StepData data;
      read_step(path, tag, s, data);
      if (!data.tags.empty()) view.steps.push_back({s, data.time});
    }
    if (!view.steps.empty()) views.push_back(view);
  }
  return views;
}

// How many steps the file has: its views' most.
std::size_t step_count(const std::vector<View>& views) {
  std::size_t most = 0;
  for (const View& v : views) most = std::max(most, v.steps.size());
  return most;
}

// `view`'s name, or another where an array has it already.
std::string array_name(const View& view, vtkUnstructuredGrid* grid) {
  const std::string name = view.name.empty() ? "view " + std::to_string(view.tag) : view.name;
  if (!grid->GetPointData()->GetAbstractArray(name.c_str()) && !grid->GetCellData()->GetAbstractArray(name.c_str()))
    return name;
  return name + " (view " + std::to_string(view.tag) + ")";
}

// The data of `view` at its step `step` as an array named `name` of
// `mesh`'s grid, on its points (`on_points`) or cells, NaN where the view
// gives nothing; null when none of it lies on the kept cells. Values per
// element node are averaged at each point over the cells that give it one.
vtkSmartPointer<vtkDoubleArray> view_array(const std::string& path, const GmshMesh& mesh, const View& view,
                                           const ViewStep& step, const std::string& name, bool& on_points) {
  StepData step_data;
  read_step(path, view.tag, step.index, step_data);
  const std::string& type = step_data.type;
  const GmshArray<std::size_t>& tags = step_data.tags;
  const GmshArrays<double>& data = step_data.values;
  const int components = step_data.components;
  const std::string said = path + ": view \"" + view.name + "\" (" + type + ")";
  if (type != "NodeData" && type != "ElementData" && type != "ElementNodeData") return nullptr;  // Gauss points
  if (components < 1 || data.size() != tags.size())
    throw DataError(said + ": Gmsh gives " + std::to_string(components) + " components");
  const std::size_t width = std::size_t(components);
  on_points = type != "ElementData";
  const vtkIdType tuples = on_points ? mesh.grid->GetNumberOfPoints() : mesh.grid->GetNumberOfCells();
  std::vector<double> sums(std::size_t(tuples) * width, 0.0);
  std::vector<int> counts(std::size_t(tuples), 0);
  const auto add = [&](vtkIdType tuple, const double* values) {
    for (std::size_t j = 0; j < width; ++j) sums[std::size_t(tuple) * width + j] += values[j];
    ++counts[std::size_t(tuple)];
  };
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const char* entity = type == "NodeData" ? "node " : "element ";
    const auto& of = type == "NodeData" ? mesh.point_of : mesh.cell_of;
    const auto found = of.find(tags[i]);
    if (found == of.end() && type != "NodeData" && mesh.left_out.count(tags[i])) continue;
    if (found == of.end())
      throw DataError(said + " has values for " + entity + std::to_string(tags[i]) + ", which the mesh does not have");
    const std::size_t c = std::size_t(found->second);
    const std::size_t nodes = type == "ElementNodeData" ? mesh.first_node[c + 1] - mesh.first_node[c] : 1;
    if (data[i].size() != nodes * width)
      throw DataError(said + ": " + entity + std::to_string(tags[i]) + " has " + std::to_string(data[i].size()) +
                      " values, not " + std::to_string(nodes) + " × " + std::to_string(components));
    if (type != "ElementNodeData") add(found->second, data[i].data);
    for (std::size_t k = 0; type == "ElementNodeData" && k < nodes; ++k)
      add(mesh.gmsh_nodes[mesh.first_node[c] + k], data[i].data + k * width);
  }
  if (std::all_of(counts.begin(), counts.end(), [](int n) { return n == 0; })) return nullptr;
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType t = 0; t < tuples; ++t)
    for (std::size_t j = 0; j < width; ++j)
      array->SetComponent(t, int(j), counts[std::size_t(t)] ? sums[std::size_t(t) * width + j] / counts[std::size_t(t)]
                                                            : std::numeric_limits<double>::quiet_NaN());
  return array;
}

vtkSmartPointer<vtkDataSet> read_gmsh_data(const std::string& path, const ReadRequest& request, const VtkSession&) {
  const GmshFile file(path);
  const GmshMesh mesh = read_mesh(path);
  const std::vector<View> views = read_views(path);
  const std::size_t steps = step_count(views);
  if (request.step > 0 && std::size_t(request.step) >= steps)
    throw DataError(path + ": data.step " + std::to_string(request.step) + " is beyond its " + std::to_string(steps) +
                    " time steps" + (steps > 0 ? " (0 to " + std::to_string(steps - 1) + ")" : std::string()));
  const std::size_t step = std::size_t(std::max(request.step, 0));
  for (const View& view : views) {
    if (view.steps.size() > 1 && step >= view.steps.size()) continue;
    const std::string name = array_name(view, mesh.grid);
    bool on_points = true;
    const vtkSmartPointer<vtkDoubleArray> array =
        view_array(path, mesh, view, view.steps[view.steps.size() > 1 ? step : 0], name, on_points);
    if (!array) continue;
    (on_points ? static_cast<vtkDataSetAttributes*>(mesh.grid->GetPointData()) : mesh.grid->GetCellData())
        ->AddArray(array);
    if (array->GetNumberOfComponents() == 6)
      record_default_order(mesh.grid->GetFieldData(), name, "vtk",
                           "a Gmsh view of 6 components, whose order Gmsh does not define (its tensors have 9)");
  }
  return mesh.grid;
}

// The times of the file's steps (its view of the most steps), none for
// one step.
std::vector<double> gmsh_times(const std::string& path) {
  const GmshFile file(path);
  const std::vector<View> views = read_views(path);
  const std::size_t steps = step_count(views);
  if (steps < 2) return {};
  std::vector<double> times;
  for (const View& view : views)
    if (view.steps.size() == steps) {
      for (const ViewStep& s : view.steps) times.push_back(s.time);
      break;
    }
  return times;
}

}  // namespace

const FormatReader gmsh_reader{read_gmsh_data, nullptr, nullptr, gmsh_times};

}  // namespace hsb

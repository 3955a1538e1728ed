// CalculiX results (.frd, as ccx writes them: ASCII or binary), read by
// hsb itself: no library in Debian reads the format (CalculiX's viewer cgx
// parses it in code of its own). What is read, on the undeformed mesh:
//  - the nodes (block 2C) and the 3-D elements (block 3C) of frd types 1 to
//    6 (he8, pe6, te4, he20, pe15, te10: C3D8, C3D6, C3D4, C3D20, C3D15,
//    C3D10), put in VTK's node order (element_types below); 2-D and beam
//    elements are refused, naming their type;
//  - the result blocks (100C) of one step, each an array of point data
//    named as the block: a symmetric tensor (STRESS, TOSTRAIN) put in VTK's
//    order XX YY ZZ XY YZ XZ by the row and column its component lines give
//    (ccx's SXX SYY SZZ SXY SYZ SZX: SZX is XZ), and recorded so; a vector
//    (DISP: its fourth name, ALL, has no values in the file) or scalars.
//    STRESS is the active tensors. Left out: ccx's error estimators (ERROR,
//    HERROR), and 6 or 9 values that are no tensor (a complex result's
//    amplitudes and phases), which hsb would take for one. A node the step
//    has no value for is NaN (no data);
//  - the steps: a step's blocks share their 100C line's step number and
//    value (a static step's time), which `times` lists.
// The records have fixed columns, numbers packed without spaces between
// them ("-1.23450E+02-4.56780E-01"): short text (format 0: five-digit node
// numbers), long text (1: ten digits), or after each block's header lines
// binary little-endian records without keys or end lines (int32 numbers;
// coordinates and values as floats, 2, or doubles, 3). Every count the file declares is checked against the bytes
// there are before it is trusted, so the file is parsed in this process
// (FormatReader::in_process). Internal to field/.

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "base/mapped_file.h"
#include "field/reading/byte_numbers.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"

namespace hsb {
namespace {

// An frd element type hsb reads, and where each of VTK's nodes stands in
// the frd's list of its nodes.
struct ElementType {
  int frd = 0;
  const char* name = "";
  int nodes = 0;
  int vtk = 0;
  std::array<int, 20> vtk_from_frd{};
};

// ccx lists an element's nodes as its input (Abaqus' order, VTK's for the
// hexahedra and tetrahedra), except that a he20's input nodes 13-16 (the
// top face's edges) come after 17-20 (the edges between the faces), and a
// pe15's 10-12 after 13-15. A wedge is mirrored besides: ccx's first
// triangle turns (right hand) toward the second, VTK's away from it
// (vtkWedge's faces: in ccx's order VTK's geometry filter draws every
// face of a wedge inward).
constexpr ElementType element_types[] = {
    {1, "he8 (C3D8)", 8, VTK_HEXAHEDRON, {0, 1, 2, 3, 4, 5, 6, 7}},
    {2, "pe6 (C3D6)", 6, VTK_WEDGE, {0, 2, 1, 3, 5, 4}},
    {3, "te4 (C3D4)", 4, VTK_TETRA, {0, 1, 2, 3}},
    {4, "he20 (C3D20)", 20, VTK_QUADRATIC_HEXAHEDRON,
     {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 12, 13, 14, 15}},
    {5, "pe15 (C3D15)", 15, VTK_QUADRATIC_WEDGE, {0, 2, 1, 3, 5, 4, 8, 7, 6, 14, 13, 12, 9, 11, 10}},
    {6, "te10 (C3D10)", 10, VTK_QUADRATIC_TETRA, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}},
};

const ElementType* element_type(long long type) {
  for (const ElementType& t : element_types)
    if (t.frd == type) return &t;
  return nullptr;
}

// The frd's other element types, named in the message that refuses them.
std::string refused_type(long long type) {
  static const char* const names[] = {"tr3 (a 3-node triangle)", "tr6 (a 6-node triangle)",
                                      "qu4 (a 4-node quadrilateral)", "qu8 (an 8-node quadrilateral)",
                                      "be2 (a 2-node beam)", "be3 (a 3-node beam)"};
  const std::string name = type >= 7 && type <= 12 ? std::string(" ") + names[type - 7] : std::string();
  return "frd element type " + std::to_string(type) + name +
         ", which hsb does not read: it reads the 3-D types 1 to 6 (he8, pe6, te4, he20, pe15, te10; ccx writes "
         "shells and plane elements so unless asked for OUTPUT=2D)";
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// The field of `width` columns from column `at` (0-based) of `line`,
// shorter at the line's end.
std::string_view column(std::string_view line, std::size_t at, std::size_t width) {
  return at >= line.size() ? std::string_view() : line.substr(at, width);
}

std::optional<long long> integer_in(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// A number such as "-1.23450E+02" (Fortran's "D" exponent too).
std::optional<double> real_in(std::string_view text) {
  text = trimmed(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  char spelled[40];
  if (text.empty() || text.size() > sizeof spelled) return std::nullopt;
  std::transform(text.begin(), text.end(), spelled, [](char c) { return c == 'D' || c == 'd' ? 'E' : c; });
  double value = 0;
  const auto [end, error] = std::from_chars(spelled, spelled + text.size(), value);
  if (error != std::errc() || end != spelled + text.size()) return std::nullopt;
  return value;
}

// A line as a message quotes it: printable, and not too long.
std::string quoted(std::string_view line) {
  std::string text(line.substr(0, 72));
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return "\"" + text + (line.size() > 72 ? "...\"" : "\"");
}

// The numbers of a binary record: little-endian, whatever this machine's order.
bool big_endian_machine() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 0;
}
long long int32_at(const unsigned char* at) {
  static const bool swap = big_endian_machine();
  return static_cast<long long>(load_number<std::int32_t>(at, swap));
}
double real_at(const unsigned char* at, std::size_t bytes) {
  static const bool swap = big_endian_machine();
  return bytes == 4 ? load_number<float>(at, swap) : load_number<double>(at, swap);
}

// The file's bytes: mapped, else read.
class FileBytes {
 public:
  explicit FileBytes(const std::string& path) : mapped_(path) {
    if (mapped_.size() > 0) return;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DataError(path + ": cannot open it");
    read_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const unsigned char* data() const {
    return mapped_.size() > 0 ? mapped_.data() : reinterpret_cast<const unsigned char*>(read_.data());
  }
  std::size_t size() const { return mapped_.size() > 0 ? mapped_.size() : read_.size(); }

 private:
  MappedFile mapped_;
  std::vector<char> read_;
};

// Where the parse stands: lines of text, or a binary block's records. Its
// errors name the line, or, once binary records have been met (after which
// the file's lines are not counted), the byte.
class FrdCursor {
 public:
  FrdCursor(const std::string& path, const unsigned char* bytes, std::size_t size)
      : path_(path), bytes_(bytes), size_(size) {}

  // The next line without its end (\n or \r\n); none at the end of the file.
  std::optional<std::string_view> line() {
    if (at_ >= size_) return std::nullopt;
    const void* newline = std::memchr(bytes_ + at_, '\n', size_ - at_);
    const std::size_t end = newline ? std::size_t(static_cast<const unsigned char*>(newline) - bytes_) : size_;
    std::string_view text(reinterpret_cast<const char*>(bytes_ + at_), end - at_);
    mark_ = at_;
    at_ = newline ? end + 1 : size_;
    ++line_;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
  }
  // The key (" -2", " -3", ...) of the next line, trimmed, without reading it.
  std::string_view next_key() const {
    return trimmed(std::string_view(reinterpret_cast<const char*>(bytes_ + at_), std::min<std::size_t>(3, size_ - at_)));
  }
  // `count` records of `size` bytes, checked to be in the file.
  const unsigned char* records(long long count, std::size_t size, const std::string& what) {
    mark_ = at_;
    binary_ = true;
    if (count < 0 || std::uint64_t(count) > (size_ - at_) / size)
      fail("the file ends within " + what + ": " +
           (count == 1 ? std::string() : std::to_string(count) + " records of ") + std::to_string(size) +
           " bytes declared, " + std::to_string(size_ - at_) + " left");
    const unsigned char* first = bytes_ + at_;
    at_ += std::size_t(count) * size;
    return first;
  }
  std::size_t left() const { return size_ - at_; }
  std::size_t line_number() const { return line_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw DataError(path_ + (binary_ ? ": at byte " + std::to_string(mark_) : ":" + std::to_string(line_)) + ": " +
                    what);
  }

 private:
  const std::string& path_;
  const unsigned char* bytes_;
  std::size_t size_;
  std::size_t at_ = 0, mark_ = 0, line_ = 0;
  bool binary_ = false;
};

// The count and format flag of a 2C or 3C line: (1X,'   2','C',18X,I12,37X,I1).
struct BlockHeader {
  long long count = 0;
  int format = 0;  // 0, 1: short, long text; 2, 3: binary
  std::size_t line = 0;
};

BlockHeader block_header(const FrdCursor& in, std::string_view line, const std::string& what) {
  BlockHeader h;
  h.line = in.line_number();
  const std::optional<long long> count = integer_in(column(line, 6, 30));
  if (!count || *count < 0) in.fail("expected the number of " + what + " in columns 25-36, found " + quoted(line));
  h.count = *count;
  const std::string_view flag = trimmed(column(line, 36, line.size()));
  const std::optional<long long> format = flag.empty() ? 0LL : integer_in(flag);
  if (!format || *format < 0 || *format > 3)
    in.fail("expected a format flag from 0 to 3 after the number of " + what + ", found " + quoted(line));
  h.format = int(*format);
  return h;
}

struct Mesh {
  std::vector<double> xyz;  // three a node, in the file's order
  std::unordered_map<long long, vtkIdType> index;  // of a node's number
  std::vector<vtkIdType> offsets{0}, connectivity;
  std::vector<unsigned char> types;
  bool has_nodes = false, has_elements = false;
};

// The node block: its nodes kept when `keep` (else only walked over).
void read_nodes(FrdCursor& in, std::string_view line, Mesh& mesh, bool keep) {
  const BlockHeader h = block_header(in, line, "nodes");
  if (mesh.has_nodes) in.fail("a second node block (2C): hsb reads files of one mesh");
  mesh.has_nodes = true;
  const auto add = [&](long long number, const double* xyz) {
    if (!keep) return;
    if (number <= 0) in.fail("node number " + std::to_string(number) + ": node numbers are positive");
    if (!mesh.index.emplace(number, vtkIdType(mesh.xyz.size() / 3)).second)
      in.fail("node " + std::to_string(number) + " is listed twice in the node block");
    mesh.xyz.insert(mesh.xyz.end(), xyz, xyz + 3);
  };
  if (keep) mesh.xyz.reserve(3 * std::size_t(std::min<long long>(h.count, static_cast<long long>(in.left() / 28))));
  if (h.format >= 2) {
    const std::size_t real = h.format == 2 ? 4 : 8;
    const unsigned char* r = in.records(h.count, 4 + 3 * real, "the node block's records");
    for (long long i = 0; i < h.count; ++i, r += 4 + 3 * real) {
      const double xyz[3] = {real_at(r + 4, real), real_at(r + 4 + real, real), real_at(r + 4 + 2 * real, real)};
      add(int32_at(r), xyz);
    }
    return;
  }
  const std::size_t values_at = h.format == 0 ? 8 : 13;  // after (1X,I2,I5) or (1X,I2,I10)
  long long found = 0;
  for (;;) {
    const std::optional<std::string_view> l = in.line();
    if (!l) in.fail("the file ends inside the node block of line " + std::to_string(h.line) + ", before its end line \" -3\"");
    const std::string_view key = trimmed(column(*l, 0, 3));
    if (key == "-3") break;
    if (key != "-1") in.fail("expected a node (\" -1\") or the node block's end (\" -3\"), found " + quoted(*l));
    const std::optional<long long> number = integer_in(column(*l, 3, values_at - 3));
    std::optional<double> x[3];
    for (std::size_t k = 0; k < 3; ++k) x[k] = real_in(column(*l, values_at + 12 * k, 12));
    if (!number || !x[0] || !x[1] || !x[2])
      in.fail("expected a node's number and its three coordinates in 12-column fields from column " +
              std::to_string(values_at + 1) + ", found " + quoted(*l));
    const double xyz[3] = {*x[0], *x[1], *x[2]};
    add(*number, xyz);
    ++found;
  }
  if (found != h.count)
    in.fail("the node block of line " + std::to_string(h.line) + " declares " + std::to_string(h.count) +
            " nodes and lists " + std::to_string(found));
}

// One element, its nodes in the frd's order, put in VTK's.
void add_element(const FrdCursor& in, Mesh& mesh, long long number, const ElementType& type, const long long* nodes) {
  for (int v = 0; v < type.nodes; ++v) {
    const long long node = nodes[type.vtk_from_frd[std::size_t(v)]];
    const auto it = mesh.index.find(node);
    if (it == mesh.index.end())
      in.fail("element " + std::to_string(number) + " names node " + std::to_string(node) +
              ", which the node block does not list");
    mesh.connectivity.push_back(it->second);
  }
  mesh.offsets.push_back(vtkIdType(mesh.connectivity.size()));
  mesh.types.push_back(static_cast<unsigned char>(type.vtk));
}

void read_elements(FrdCursor& in, std::string_view line, Mesh& mesh, bool keep) {
  const BlockHeader h = block_header(in, line, "elements");
  if (mesh.has_elements) in.fail("a second element block (3C): hsb reads files of one mesh");
  if (keep && !mesh.has_nodes) in.fail("an element block (3C) before the node block (2C)");
  mesh.has_elements = true;
  const auto type_of = [&](long long number, long long type) -> const ElementType& {
    const ElementType* t = element_type(type);
    if (!t) in.fail("element " + std::to_string(number) + " is of " + refused_type(type));
    return *t;
  };
  long long nodes[20];
  if (h.format >= 2) {
    for (long long i = 0; i < h.count; ++i) {
      const unsigned char* r = in.records(1, 16, "an element");  // number, type, group, material
      const long long number = int32_at(r);
      const ElementType& type = type_of(number, int32_at(r + 4));
      r = in.records(1, 4 * std::size_t(type.nodes), "element nodes");
      for (int k = 0; k < type.nodes; ++k) nodes[k] = int32_at(r + 4 * k);
      if (keep) add_element(in, mesh, number, type, nodes);
    }
    return;
  }
  const std::size_t width = h.format == 0 ? 5 : 10;  // of a number: (1X,I2,I5,3I5), (1X,I2,15I5); I10, 10I10
  long long found = 0;
  for (std::optional<std::string_view> l = in.line();; l = in.line()) {
    if (!l) in.fail("the file ends inside the element block of line " + std::to_string(h.line) + ", before its end line \" -3\"");
    const std::string_view key = trimmed(column(*l, 0, 3));
    if (key == "-3") break;
    if (key != "-1") in.fail("expected an element (\" -1\") or the element block's end (\" -3\"), found " + quoted(*l));
    const std::optional<long long> number = integer_in(column(*l, 3, width));
    const std::optional<long long> type_number = integer_in(column(*l, 3 + width, 5));
    if (!number || !type_number) in.fail("expected an element's number and type, found " + quoted(*l));
    const ElementType& type = type_of(*number, *type_number);
    int listed = 0;
    while (listed < type.nodes) {
      if (in.next_key() != "-2")
        in.fail("element " + std::to_string(*number) + ", a " + type.name + ", lists " + std::to_string(listed) +
                " of its " + std::to_string(type.nodes) + " nodes");
      const std::string_view nodes_line = *in.line();
      for (std::size_t at = 3; at < nodes_line.size(); at += width) {
        if (trimmed(column(nodes_line, at, width)).empty()) continue;
        const std::optional<long long> node = integer_in(column(nodes_line, at, width));
        if (!node || listed == type.nodes)
          in.fail("expected the " + std::to_string(type.nodes) + " node numbers of element " +
                  std::to_string(*number) + " (" + type.name + ") in " + std::to_string(width) +
                  "-column fields, found " + quoted(nodes_line));
        nodes[listed++] = *node;
      }
    }
    if (keep) add_element(in, mesh, *number, type, nodes);
    ++found;
  }
  if (found != h.count)
    in.fail("the element block of line " + std::to_string(h.line) + " declares " + std::to_string(h.count) +
            " elements and lists " + std::to_string(found));
}

// A component line (" -5") of a result block.
struct Component {
  std::string name;
  long long type = 0, row = 0, column = 0;  // type 4: a matrix's component (row, column)
  bool in_file = true;                      // false: computed by cgx (DISP's ALL)
};

// Where each component in the file goes in the array: VTK's order for a
// symmetric tensor (by its row and column: ccx's SZX is XZ), row by row
// for a full one, the file's order for anything else. None for 6 or 9
// values that are no tensor (a complex result's amplitudes and phases):
// hsb would take those for tensors.
std::optional<std::vector<int>> component_places(const std::vector<Component>& stored) {
  const std::size_t n = stored.size();
  std::vector<int> places;
  if (n != 6 && n != 9) {
    for (std::size_t k = 0; k < n; ++k) places.push_back(int(k));
    return places;
  }
  std::vector<bool> taken(n, false);
  for (const Component& c : stored) {
    if (c.type != 4 || c.row < 1 || c.row > 3 || c.column < 1 || c.column > 3) return std::nullopt;
    const int r = int(std::min(c.row, c.column)) - 1, s = int(std::max(c.row, c.column)) - 1;
    static const int symmetric[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};
    const int place = n == 6 ? symmetric[r][s] : int(c.row - 1) * 3 + int(c.column - 1);
    if (taken[std::size_t(place)]) return std::nullopt;
    taken[std::size_t(place)] = true;
    places.push_back(place);
  }
  return places;
}

struct StepOfFile {
  double time = 0.0;
  std::vector<std::string> blocks;
};

struct FrdContent {
  Mesh mesh;
  std::vector<StepOfFile> steps;
  // A step's blocks share their 100C line's set name, step number and value.
  std::unordered_map<std::string, std::size_t> step_of_key;
  std::vector<vtkSmartPointer<vtkDoubleArray>> arrays;  // of the step asked for
  std::vector<std::string> orders;                      // the file's order of each 6-component array
  // What those arrays may still take, in bytes: a few times the file's
  // size (a block of a few nodes, as *NODE FILE, NSET= writes, is an array
  // of every node), so that a corrupt file of many blocks cannot take all
  // memory.
  std::uint64_t array_budget = 0;
};

// A result block (100C line, " -4" name, " -5" components, values); its
// values kept when its step is `wanted`.
void read_results(FrdCursor& in, std::string_view line, FrdContent& content, int wanted) {
  // (1X,' 100','C',6A1,E12.5,I12,20A1,I2,I5,10A1,I2): set name, value,
  // count, text, type, step number, analysis, format.
  const std::size_t header_line = in.line_number();
  const std::optional<double> time = real_in(column(line, 12, 12));
  const std::optional<long long> count = integer_in(column(line, 24, 12));
  const std::string_view flag = trimmed(column(line, 73, 2));
  const std::optional<long long> format = flag.empty() ? 0LL : integer_in(flag);
  if (!time || !count || *count < 0 || !format || *format < 0 || *format > 3)
    in.fail("expected a result block's step value (columns 13-24), number of nodes (25-36) and format flag "
            "(74-75), found " + quoted(line));
  const std::string key = std::string(column(line, 6, 6)) + "/" + std::string(trimmed(column(line, 58, 5))) + "/" +
                          std::string(trimmed(column(line, 12, 12)));

  const std::optional<std::string_view> name_line = in.line();
  if (!name_line || trimmed(column(*name_line, 0, 3)) != "-4")
    in.fail("expected the result block's name line (\" -4\") after its 100C line");
  const std::string name(trimmed(column(*name_line, 5, 8)));
  const std::optional<long long> components = integer_in(column(*name_line, 13, 5));
  if (name.empty() || !components || *components < 1 || *components > 1000)
    in.fail("expected a result block's name and its number of components (1 to 1000), found " + quoted(*name_line));
  std::vector<Component> stored;
  for (long long c = 0; c < *components; ++c) {
    const std::optional<std::string_view> l = in.line();
    if (!l || trimmed(column(*l, 0, 3)) != "-5")
      in.fail("block " + name + " declares " + std::to_string(*components) + " components; expected component line " +
              std::to_string(c + 1) + " (\" -5\")");
    Component comp;
    comp.name = std::string(trimmed(column(*l, 5, 8)));
    const auto number = [&](std::size_t at) { return integer_in(column(*l, at, 5)).value_or(0); };
    comp.type = number(18);
    comp.row = number(23);
    comp.column = number(28);
    comp.in_file = number(33) != 1;
    if (comp.in_file) stored.push_back(comp);
  }

  const std::size_t step = content.step_of_key.emplace(key, content.steps.size()).first->second;
  if (step == content.steps.size()) content.steps.push_back({*time, {}});
  std::vector<std::string>& names = content.steps[step].blocks;
  if (std::find(names.begin(), names.end(), name) != names.end())
    in.fail("a second block " + name + " in the step of value " + std::string(trimmed(column(line, 12, 12))));
  names.push_back(name);

  // ccx's error estimators (ERROR: STR(%), HERROR) are no quantity to draw.
  const bool estimator = name.size() >= 5 && name.compare(name.size() - 5, 5, "ERROR") == 0;
  const std::optional<std::vector<int>> places = component_places(stored);
  vtkSmartPointer<vtkDoubleArray> array;
  std::vector<bool> seen;
  const Mesh& mesh = content.mesh;
  if (int(step) == wanted && !estimator && places && !stored.empty()) {
    if (!mesh.has_nodes) in.fail("a result block (100C) before the node block (2C)");
    array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(int(stored.size()));
    for (std::size_t k = 0; k < stored.size(); ++k) array->SetComponentName(vtkIdType((*places)[k]), stored[k].name.c_str());
    const std::uint64_t bytes = mesh.xyz.size() / 3 * stored.size() * sizeof(double);
    if (bytes > content.array_budget)
      in.fail("block " + name + ": the arrays of this step's blocks would take more than 16 times the file's size: "
              "more blocks in one step than a CalculiX file has");
    content.array_budget -= bytes;
    array->SetNumberOfTuples(vtkIdType(mesh.xyz.size() / 3));
    array->Fill(std::nan(""));
    seen.assign(mesh.xyz.size() / 3, false);
  }
  const std::size_t n = stored.size();
  std::vector<double> values(n);
  const auto put = [&](long long node) {
    if (!array) return;
    const auto it = mesh.index.find(node);
    if (it == mesh.index.end())
      in.fail("block " + name + " has values for node " + std::to_string(node) + ", which the node block does not list");
    if (seen[std::size_t(it->second)])
      in.fail("block " + name + " has a second value record for node " + std::to_string(node));
    seen[std::size_t(it->second)] = true;
    for (std::size_t k = 0; k < n; ++k) array->SetTypedComponent(it->second, (*places)[k], values[k]);
  };

  if (*format >= 2) {
    const std::size_t real = *format == 2 ? 4 : 8;
    const unsigned char* r = in.records(*count, 4 + n * real, "the value records of block " + name);
    for (long long i = 0; array && i < *count; ++i, r += 4 + n * real) {
      for (std::size_t k = 0; k < n; ++k) values[k] = real_at(r + 4 + k * real, real);
      put(int32_at(r));
    }
  } else {
    const std::size_t values_at = *format == 0 ? 8 : 13;  // (1X,I2,I5,6E12.5), (1X,I2,I10,6E12.5)
    long long found = 0;
    for (;;) {
      const std::optional<std::string_view> l = in.line();
      if (!l)
        in.fail("the file ends inside block " + name + " of line " + std::to_string(header_line) +
                ", before its end line \" -3\"");
      const std::string_view record_key = trimmed(column(*l, 0, 3));
      if (record_key == "-3") break;
      if (record_key != "-1")
        in.fail("expected a value record (\" -1\") or the end (\" -3\") of block " + name + ", found " + quoted(*l));
      const std::optional<long long> node = integer_in(column(*l, 3, values_at - 3));
      if (!node) in.fail("expected a node number in columns 4-" + std::to_string(values_at) + ", found " + quoted(*l));
      std::size_t got = 0;
      // At most six values a line, the rest on continuation lines (" -2").
      for (std::string_view values_line = *l;;) {
        for (std::size_t at = values_at; at < values_line.size() && !trimmed(column(values_line, at, 12)).empty(); at += 12) {
          const std::optional<double> v = real_in(column(values_line, at, 12));
          if (!v || got == n)
            in.fail("expected node " + std::to_string(*node) + "'s " + std::to_string(n) + " values of block " + name +
                    " in 12-column fields from column " + std::to_string(values_at + 1) + ", found " + quoted(values_line));
          values[got++] = *v;
        }
        if (got == n) break;
        if (in.next_key() != "-2")
          in.fail("node " + std::to_string(*node) + " has " + std::to_string(got) + " of the " + std::to_string(n) +
                  " values of block " + name);
        values_line = *in.line();
      }
      put(*node);
      ++found;
    }
    if (found != *count)
      in.fail("block " + name + " of line " + std::to_string(header_line) + " declares " + std::to_string(*count) +
              " value records and has " + std::to_string(found));
  }
  if (array) {
    std::string order;
    for (const Component& c : stored) order += (order.empty() ? "" : " ") + c.name;
    content.arrays.push_back(array);
    content.orders.push_back(n == 6 ? "CalculiX's " + name + ": " + order : "");
  }
}

// The whole file: its mesh when `keep_mesh`, its steps, and the arrays of
// step `wanted` (none: −1).
FrdContent read_frd_file(const std::string& path, bool keep_mesh, int wanted) {
  const FileBytes file(path);
  static constexpr std::string_view signature = "    1C";
  if (file.size() < signature.size() || std::memcmp(file.data(), signature.data(), signature.size()) != 0)
    throw DataError(path + ":1: not a CalculiX .frd file: it does not start with \"    1C\"");
  FrdCursor in(path, file.data(), file.size());
  FrdContent content;
  content.array_budget = 16 * std::uint64_t(file.size()) + (std::uint64_t(64) << 20);
  while (const std::optional<std::string_view> l = in.line()) {
    const std::string_view start = column(*l, 0, 6);
    if (start == "    2C") {
      read_nodes(in, *l, content.mesh, keep_mesh);
    } else if (start == "    3C") {
      read_elements(in, *l, content.mesh, keep_mesh);
    } else if (start == "  100C") {
      read_results(in, *l, content, keep_mesh ? wanted : -1);
    } else if (start.substr(0, 5) == "    1" || trimmed(*l).empty()) {
      continue;  // the model's name (1C), user lines (1U), a step's parameters (1P)
    } else if (trimmed(*l) == "9999") {
      break;
    } else {
      in.fail("expected a block (\"    2C\" nodes, \"    3C\" elements, \"  100C\" results), a \"    1U\" or "
              "\"    1P\" line, or the end \" 9999\", found " + quoted(*l));
    }
  }
  if (keep_mesh && !content.mesh.has_nodes) throw DataError(path + ": a CalculiX .frd file without a node block (2C)");
  return content;
}

vtkSmartPointer<vtkUnstructuredGrid> grid_of(const Mesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(mesh.xyz.size() / 3));
  for (std::size_t i = 0; i < mesh.xyz.size() / 3; ++i)
    points->SetPoint(vtkIdType(i), mesh.xyz[3 * i], mesh.xyz[3 * i + 1], mesh.xyz[3 * i + 2]);
  const auto ids = [](const std::vector<vtkIdType>& values) {
    auto array = vtkSmartPointer<vtkIdTypeArray>::New();
    array->SetNumberOfValues(vtkIdType(values.size()));
    std::copy(values.begin(), values.end(), array->GetPointer(0));
    return array;
  };
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  const vtkSmartPointer<vtkIdTypeArray> offsets = ids(mesh.offsets), connectivity = ids(mesh.connectivity);
  cells->SetData(offsets.Get(), connectivity.Get());
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  types->SetNumberOfValues(vtkIdType(mesh.types.size()));
  std::copy(mesh.types.begin(), mesh.types.end(), types->GetPointer(0));
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  return grid;
}

vtkSmartPointer<vtkDataSet> read_frd(const std::string& path, const ReadRequest& request, const VtkSession&) {
  const int step = std::max(request.step, 0);
  FrdContent content = read_frd_file(path, true, step);
  const std::size_t steps = content.steps.size();
  if (std::size_t(step) >= steps && !(step == 0 && steps == 0))
    throw DataError(path + ": data.step " + std::to_string(step) + " is beyond its " + std::to_string(steps) +
                    " result steps" + (steps > 0 ? " (0 to " + std::to_string(steps - 1) + ")" : std::string()));
  vtkSmartPointer<vtkUnstructuredGrid> grid = grid_of(content.mesh);
  for (std::size_t i = 0; i < content.arrays.size(); ++i) {
    vtkDoubleArray* array = content.arrays[i];
    if (std::string(array->GetName()) == "STRESS" && array->GetNumberOfComponents() == 6)
      grid->GetPointData()->SetTensors(array);
    else
      grid->GetPointData()->AddArray(array);
    if (!content.orders[i].empty()) record_component_order(grid->GetFieldData(), array->GetName(), content.orders[i]);
  }
  return grid;
}

// The times of the result steps, in order; none for a file of one step.
std::vector<double> frd_times(const std::string& path) {
  const FrdContent content = read_frd_file(path, false, -1);
  std::vector<double> times;
  if (content.steps.size() >= 2)
    for (const StepOfFile& s : content.steps) times.push_back(s.time);
  return times;
}

}  // namespace

const FormatReader frd_reader{read_frd, nullptr, nullptr, frd_times, false, false, true};

}  // namespace hsb

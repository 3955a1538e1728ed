// NRRD volumes (Teem's `tend`, 3D Slicer, ITK), read by hsb itself: VTK's
// vtkNrrdReader takes neither Teem's tensor kinds nor `space directions`.
// What is read:
//  - a header in the file (.nrrd) or apart from its data (.nhdr with
//    `data file:`); raw, ASCII or gzip-compressed data, either endianness,
//    any of NRRD's number types;
//  - three space axes placed by `space origin` and `space directions`
//    (or by `spacings`), so an oblique volume stays oblique;
//  - a first axis of kind 3D-masked-symmetric-matrix (Teem's seven values:
//    a confidence, then XX XY XZ YY YZ ZZ; a confidence below 0.5 is no
//    data), 3D-symmetric-matrix (six), 3D-matrix (nine, row by row),
//    3D-masked-matrix (ten) or 3-vector; without a kind, its count of
//    values says which;
//  - the `measurement frame`: vectors are turned from it into the space
//    here, tensors where every format's are (field/reading/vtk_data.cpp,
//    which data.frame can overrule), from the rotation recorded.
// The tensors come out in VTK's order, with the layout they were read
// from recorded (field/reading/component_arrays.h). Internal to field/. Every
// count the header declares is checked against the bytes there are before
// any is read, so the file is parsed in this process (FormatReader::in_process).

#include <vtkImageData.h>
#include <vtkFieldData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <type_traits>
#include <limits>
#include <map>
#include <optional>
#include <cctype>
#include <sstream>

#include "base/huge_pages.h"
#include "base/mapped_file.h"
#include "base/memory_budget.h"
#include "base/input_file.h"
#include "field/reading/byte_numbers.h"
#include "field/reading/component_arrays.h"
#include "field/reading/component_order.h"
#include "field/reading/data_error.h"
#include "field/reading/file_records.h"
#include "field/reading/format_reader.h"
#include "field/reading/tensor_storage.h"
#include "field/tensor/sym3.h"

namespace hsb {
namespace {

// The most values a volume may declare: far beyond any scan, and the
// guard that keeps a corrupt `sizes:` from asking for all memory.
constexpr std::uint64_t most_values = std::uint64_t(1) << 31;

// One `field: value` line of the header, with where it stood.
struct HeaderField {
  std::string value;
  int line = 0;
};

struct Header {
  std::map<std::string, HeaderField> fields;
  std::streamoff data_offset = 0;  // where the data starts in the header's own file
  const std::string* path = nullptr;

  const HeaderField* find(const std::string& name) const {
    auto it = fields.find(name);
    return it == fields.end() ? nullptr : &it->second;
  }
  [[noreturn]] void fail(const HeaderField* field, const std::string& what) const {
    throw DataError(*path + (field ? ":" + std::to_string(field->line) : std::string()) + ": " + what);
  }
  std::string value(const std::string& name, const std::string& otherwise) const {
    const HeaderField* f = find(name);
    return f ? f->value : otherwise;
  }
  long long integer(const std::string& name) const {
    const HeaderField* f = find(name);
    if (!f) return 0;
    char* end = nullptr;
    const long long v = std::strtoll(f->value.c_str(), &end, 10);
    if (end == f->value.c_str() || *end != '\0' || v < -1 || v > (1LL << 40))
      fail(f, "expected a whole number of at least -1 for \"" + name + "\", found \"" + f->value + "\"");
    return v;
  }
};

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// The header: from "NRRD000x" to the first empty line (or the end of a
// detached header). Key/value pairs (`key:=value`) and comments are skipped.
Header read_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path + ": cannot open it");
  Header header;
  header.path = &path;
  std::string line;
  std::getline(in, line);
  if (line.rfind("NRRD000", 0) != 0)
    throw DataError(path + ":1: not a NRRD file: it does not start with \"NRRD000\"");
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) break;
    if (line[0] == '#' || line.find(":=") != std::string::npos) continue;
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos)
      throw DataError(path + ":" + std::to_string(number) + ": expected \"field: value\" in the NRRD header, found \"" +
                      line.substr(0, 60) + "\"");
    std::string name = line.substr(0, colon);
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (name == "datafile") name = "data file";
    header.fields[name] = {trimmed(line.substr(colon + 2)), number};
  }
  header.data_offset = in.eof() ? std::streamoff(-1) : std::streamoff(in.tellg());
  return header;
}

// A number type: its size and how its bytes read.
struct NumberType {
  int bytes = 0;
  enum { integer, unsigned_integer, floating } kind = floating;
};

NumberType number_type(const Header& h) {
  const HeaderField* f = h.find("type");
  if (!f) h.fail(nullptr, "the NRRD header has no \"type:\"");
  static const std::map<std::string, NumberType> types = [] {
    std::map<std::string, NumberType> t;
    const auto add = [&](std::initializer_list<const char*> names, NumberType type) {
      for (const char* n : names) t[n] = type;
    };
    using K = decltype(NumberType::kind);
    add({"signed char", "int8", "int8_t"}, {1, K(NumberType::integer)});
    add({"uchar", "unsigned char", "uint8", "uint8_t"}, {1, K(NumberType::unsigned_integer)});
    add({"short", "short int", "signed short", "signed short int", "int16", "int16_t"}, {2, K(NumberType::integer)});
    add({"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"}, {2, K(NumberType::unsigned_integer)});
    add({"int", "signed int", "int32", "int32_t"}, {4, K(NumberType::integer)});
    add({"uint", "unsigned int", "uint32", "uint32_t"}, {4, K(NumberType::unsigned_integer)});
    add({"longlong", "long long", "long long int", "signed long long", "signed long long int", "int64", "int64_t"},
        {8, K(NumberType::integer)});
    add({"ulonglong", "unsigned long long", "unsigned long long int", "uint64", "uint64_t"},
        {8, K(NumberType::unsigned_integer)});
    add({"float"}, {4, K(NumberType::floating)});
    add({"double"}, {8, K(NumberType::floating)});
    return t;
  }();
  auto it = types.find(f->value);
  if (it == types.end()) h.fail(f, "NRRD type \"" + f->value + "\" is not a number type");
  return it->second;
}

// The numbers of a list such as "7 12 10 8".
std::vector<double> numbers(const Header& h, const HeaderField* f) {
  std::istringstream in(f->value);
  std::vector<double> out;
  for (std::string word; in >> word;) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0') h.fail(f, "expected a number, found \"" + word + "\"");
    out.push_back(v);
  }
  return out;
}

// The vectors of `space directions:` or `measurement frame:`: "(x,y,z)" or "none" each.
std::vector<std::optional<Vec3>> vectors(const Header& h, const HeaderField* f) {
  std::istringstream in(f->value);
  std::vector<std::optional<Vec3>> out;
  for (std::string word; in >> word;) {
    if (word == "none") {
      out.emplace_back();
      continue;
    }
    Vec3 v;
    char close = 0;
    if (std::sscanf(word.c_str(), "(%lf,%lf,%lf%c", &v.x(), &v.y(), &v.z(), &close) != 4 || close != ')' ||
        !v.allFinite())
      h.fail(f, "expected a vector such as (1,0,0), found \"" + word + "\"");
    out.emplace_back(v);
  }
  return out;
}

// The file the data is in: the header's own, or its `data file:`.
std::string data_file(const Header& h, const std::string& path) {
  const HeaderField* f = h.find("data file");
  if (!f) return path;
  if (f->value.rfind("LIST", 0) == 0 || f->value.find(' ') != std::string::npos)
    h.fail(f, "a data file list or pattern is not read; give one data file");
  return file_named_in(path, f->value);
}

// The bytes of `in` from where it stands to the end, read at once (a
// stream iterator's byte at a time took a tenth of a second for 19 MB).
std::vector<char> rest_of(std::ifstream& in) {
  const std::streamoff here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  std::vector<char> bytes;
  assign_on_huge_pages(bytes, std::size_t(std::max<std::streamoff>(0, end - here)), '\0');
  in.seekg(here);
  in.read(bytes.data(), std::streamsize(bytes.size()));
  bytes.resize(std::size_t(in.gcount()));
  return bytes;
}

// The data's values as the file holds them: bytes (raw, or inflated from
// gzip) of the header's number type, read where they lie, or the numbers
// an ASCII file spells out. Read where they lie, not copied into doubles
// first: for Teem's helix at 88³ that copy was 38 MB, and most of its
// cost was the kernel's page faults.
struct DecodedValues {
  MappedFile mapped;                   // the data file, where it can be mapped
  std::vector<char> raw;               // else the file's bytes after the header, read
  std::vector<unsigned char> inflated; // gzip's output
  const unsigned char* bytes = nullptr;
  NumberType type;
  bool swap = false;
  std::vector<double> text;  // ASCII data
};

// Calls `use(at)`, `at(i)` being value i as a double, with `at` made for
// the data's number type (one loop compiled a type, not a call a value).
template <class Use>
void with_values(const DecodedValues& d, Use&& use) {
  if (!d.bytes) {
    use([&](std::uint64_t i) { return d.text[i]; });
    return;
  }
  const NumberKind kind = d.type.kind == NumberType::floating ? NumberKind::floating
                          : d.type.kind == NumberType::integer ? NumberKind::integer
                                                               : NumberKind::unsigned_integer;
  if (!with_typed_numbers(d.bytes, d.type.bytes, kind, d.swap, use))
    throw std::logic_error("NRRD: a number type without a reader");
}

// Whether the header's data is spelled out as text (ASCII numbers).
bool text_encoding(const Header& h) {
  const std::string encoding = h.value("encoding", "");
  return encoding == "txt" || encoding == "text" || encoding == "ascii";
}

// The data's bytes: `count` values of `type`, decoded as the header says.
DecodedValues read_values(const Header& h, const std::string& path, std::uint64_t count, NumberType type) {
  const std::string encoding = h.value("encoding", "");
  const std::string data_path = data_file(h, path);
  const std::streamoff offset = data_path == path ? h.data_offset : 0;
  if (offset < 0) {
    h.fail(nullptr, "the NRRD header ends without its data (no empty line, and no \"data file:\")");
  }
  if (const std::string why = unreadable_input(data_path); !why.empty() && why != "no such file")
    throw DataError(path + ": names " + data_path + ": " + why);
  std::ifstream in(data_path, std::ios::binary);
  if (!in) throw DataError(path + ": cannot open its data file " + data_path);
  in.seekg(offset);
  for (long long skip = h.integer("line skip"); skip > 0 && in; --skip) in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  DecodedValues d;
  d.type = type;
  const bool text = text_encoding(h);
  // The bytes after the header: mapped (raw and gzip data), else read.
  const std::streamoff here = in.tellg();
  if (!text && here >= 0) d.mapped = MappedFile(data_path);
  const unsigned char* rest = nullptr;
  std::size_t rest_size = 0;
  if (d.mapped.size() > 0) {
    const std::size_t at = std::min(std::size_t(here), d.mapped.size());
    rest = d.mapped.data() + at;
    rest_size = d.mapped.size() - at;
  } else {
    d.raw = rest_of(in);
    rest = reinterpret_cast<const unsigned char*>(d.raw.data());
    rest_size = d.raw.size();
  }
  const long long byte_skip = h.integer("byte skip");

  // Nothing is reserved for what the header declares before the data
  // shows it holds that much: a corrupt size must not take all memory.
  std::vector<double>& values = d.text;
  if (text) {
    std::vector<char>& raw = d.raw;
    raw.push_back('\0');
    const char* at = raw.data();
    for (char* end = nullptr; values.size() < count; at = end) {
      while (*at == ',' || std::isspace(static_cast<unsigned char>(*at))) ++at;
      const double v = std::strtod(at, &end);
      if (end == at) break;
      values.push_back(v);
    }
    if (values.size() < count)
      throw DataError(path + ": its ASCII data has " + std::to_string(values.size()) + " values; the header declares " +
                      std::to_string(count));
    return d;
  }
  const std::uint64_t bytes = count * std::uint64_t(type.bytes);
  std::vector<unsigned char>& inflated = d.inflated;
  const unsigned char* decoded = nullptr;
  if (encoding == "raw") {
    const std::uint64_t start = byte_skip == -1 ? (rest_size >= bytes ? rest_size - bytes : 0) : std::uint64_t(std::max(0LL, byte_skip));
    if (rest_size < start + bytes)
      throw DataError(path + ": its raw data has " + std::to_string(rest_size - std::min<std::uint64_t>(rest_size, start)) +
                      " bytes; the header declares " + std::to_string(bytes));
    decoded = rest + start;
  } else if (encoding == "gzip" || encoding == "gz") {
    z_stream z{};
    if (inflateInit2(&z, 15 + 32) != Z_OK) throw DataError(path + ": cannot start zlib");
    z.next_in = const_cast<unsigned char*>(rest);  // zlib only reads it
    z.avail_in = uInt(std::min<std::size_t>(rest_size, std::numeric_limits<uInt>::max()));
    std::uint64_t done = 0;
    int status = Z_OK;
    while (done < bytes && status == Z_OK) {
      // Grown as the data inflates, not to the declared size at once.
      if (inflated.size() == done)
        inflated.resize(std::size_t(std::min<std::uint64_t>(bytes, std::max<std::uint64_t>(2 * done, 1 << 20))));
      z.next_out = inflated.data() + done;
      z.avail_out = uInt(std::min<std::uint64_t>(inflated.size() - done, std::numeric_limits<uInt>::max()));
      status = inflate(&z, Z_NO_FLUSH);
      done = z.total_out;
    }
    inflateEnd(&z);
    if (done < bytes)
      throw DataError(path + ": its gzip data inflates to " + std::to_string(done) + " bytes; the header declares " +
                      std::to_string(bytes) + (status == Z_DATA_ERROR ? " (the compressed data is corrupt)" : ""));
    decoded = inflated.data();
  } else {
    h.fail(h.find("encoding"), "NRRD encoding \"" + encoding + "\" is not read (raw, gzip and ascii are)");
  }
  d.swap = type.bytes > 1 && h.value("endian", "little") == "big";
  d.bytes = decoded;
  return d;
}

// What the values of one voxel are: how many, and how they make a tensor.
struct VoxelLayout {
  int values = 0;       // per voxel
  bool masked = false;  // a confidence first
  enum { symmetric, full, vector, scalar } kind = symmetric;
  std::string said;     // for the record
};

VoxelLayout voxel_layout(const Header& h, int values) {
  const HeaderField* kinds = h.find("kinds");
  std::string kind;
  if (kinds) std::istringstream(kinds->value) >> kind;
  using K = decltype(VoxelLayout::kind);
  if (kind == "3D-masked-symmetric-matrix" || (kind.empty() && values == 7))
    return {7, true, K(VoxelLayout::symmetric), "a confidence, then XX XY XZ YY YZ ZZ (Teem's 3D-masked-symmetric-matrix)"};
  if (kind == "3D-symmetric-matrix" || (kind.empty() && values == 6))
    return {6, false, K(VoxelLayout::symmetric), "XX XY XZ YY YZ ZZ (NRRD's 3D-symmetric-matrix)"};
  if (kind == "3D-masked-matrix" || (kind.empty() && values == 10))
    return {10, true, K(VoxelLayout::full), "a confidence, then the 3×3 matrix row by row (NRRD's 3D-masked-matrix)"};
  if (kind == "3D-matrix" || (kind.empty() && values == 9))
    return {9, false, K(VoxelLayout::full), "the 3×3 matrix row by row (NRRD's 3D-matrix)"};
  if (kind == "3-vector" || kind == "covariant-vector" || kind == "normal" || (kind.empty() && values == 3) ||
      (kind == "vector" && values == 3))
    return {3, false, K(VoxelLayout::vector), ""};
  h.fail(kinds ? kinds : h.find("sizes"), "the first axis (" + std::to_string(values) + " values" +
                                              (kind.empty() ? "" : ", kind " + kind) +
                                              ") is no tensor or vector NRRD kind hsb reads (3D-masked-symmetric-matrix, "
                                              "3D-symmetric-matrix, 3D-matrix, 3D-masked-matrix, 3-vector)");
}

// The volume in `path`. Throws DataError naming the file and the header
// line for anything it cannot read as described.
// The anatomical letters of NRRD's `space` ("right-anterior-superior" or
// "RAS", "left-posterior-superior" or "LPS", ...; a time axis after them
// aside), or "" for a space without them ("scanner-xyz", "3D-right-handed").
std::string anatomical_letters(const std::string& space) {
  std::string letters;
  if (space.find('-') == std::string::npos) {
    letters = space;
  } else {
    std::istringstream words(space);
    for (std::string word; std::getline(words, word, '-') && letters.size() < 3;)
      if (!word.empty()) letters += word[0];
  }
  for (char& c : letters) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (letters.size() < 3) return "";
  letters.resize(3);
  const std::string pairs[3] = {"RL", "AP", "SI"};
  for (int k = 0; k < 3; ++k)
    if (pairs[k].find(letters[std::size_t(k)]) == std::string::npos) return "";
  return letters;
}

// A tensor (or vector) volume, or with `scalar` a volume of one value per
// voxel (a mask), whose axes are then all space axes.
vtkSmartPointer<vtkImageData> read_nrrd(const std::string& path, bool scalar) {
  const Header h = read_header(path);
  const NumberType type = number_type(h);
  const HeaderField* dimension = h.find("dimension");
  const HeaderField* sizes_field = h.find("sizes");
  if (!dimension || !sizes_field) h.fail(nullptr, "the NRRD header lacks \"dimension:\" or \"sizes:\"");
  const std::vector<double> sizes = numbers(h, sizes_field);
  // The first space axis: after the values of a voxel, if they have one.
  const int first = scalar ? 0 : 1;
  if (scalar && (dimension->value != "3" || sizes.size() != 3))
    h.fail(sizes.size() != 3 ? sizes_field : dimension,
           "a mask is a volume of one value per voxel: expected dimension 3 with three sizes, found dimension " +
               dimension->value + " with " + std::to_string(sizes.size()) + " sizes");
  if (!scalar && dimension->value == "3")
    h.fail(dimension, "a volume of one value per voxel: no tensors or vectors (a 4-D NRRD with a first axis of 6, 7 or "
                      "9); a mask is given as region.mask, beside the tensors' file");
  if (!scalar && (dimension->value != "4" || sizes.size() != 4))
    h.fail(sizes.size() != 4 ? sizes_field : dimension,
           "expected dimension 4 with four sizes (values per voxel, then three space axes), found dimension " +
               dimension->value + " with " + std::to_string(sizes.size()) + " sizes");
  std::uint64_t count = 1;
  for (double s : sizes) {
    if (!(s >= 1 && s <= double(most_values)) || s != std::floor(s))
      h.fail(sizes_field, "each size must be a whole number from 1 to 2^31, found " + sizes_field->value);
    count *= std::uint64_t(s);
    if (count > most_values) h.fail(sizes_field, "the volume declares more than 2^31 values: " + sizes_field->value);
  }
  const VoxelLayout layout = scalar ? VoxelLayout{1, false, VoxelLayout::scalar, ""} : voxel_layout(h, int(sizes[0]));
  if (!scalar && layout.values != int(sizes[0]))
    h.fail(sizes_field, "its kind has " + std::to_string(layout.values) + " values per voxel, its size is " +
                            std::to_string(int(sizes[0])));
  const std::array<int, 3> dims{int(sizes[std::size_t(first)]), int(sizes[std::size_t(first + 1)]),
                                int(sizes[std::size_t(first + 2)])};

  // Where the voxels are: space directions (with an origin), else spacings.
  Mat3 axes = Mat3::Identity();
  Vec3 origin = Vec3::Zero();
  if (const HeaderField* f = h.find("space directions")) {
    const std::vector<std::optional<Vec3>> d = vectors(h, f);
    const bool values_axis_none = scalar || (!d.empty() && !d[0]);
    if (d.size() != std::size_t(first + 3) || !values_axis_none || !d[std::size_t(first)] ||
        !d[std::size_t(first + 1)] || !d[std::size_t(first + 2)])
      h.fail(f, std::string(scalar ? "expected" : "expected \"none\" for the first axis and") +
                    " a vector for each space axis, found " + f->value);
    axes << *d[std::size_t(first)], *d[std::size_t(first + 1)], *d[std::size_t(first + 2)];
    if (std::fabs(axes.determinant()) < 1e-300 * axes.cwiseAbs().maxCoeff())
      h.fail(f, "the space directions are not independent: the voxels have no volume");
    if (const HeaderField* o = h.find("space origin")) {
      const std::vector<std::optional<Vec3>> p = vectors(h, o);
      if (p.size() != 1 || !p[0]) h.fail(o, "expected one vector such as (0,0,0), found " + o->value);
      origin = *p[0];
    }
  } else if (const HeaderField* spacings = h.find("spacings")) {
    std::istringstream in(spacings->value);
    std::vector<std::string> words{std::istream_iterator<std::string>(in), std::istream_iterator<std::string>()};
    for (int a = 0; a < 3 && words.size() == std::size_t(first + 3); ++a) {
      const double s = std::strtod(words[std::size_t(a + first)].c_str(), nullptr);
      if (!(s > 0) || !std::isfinite(s))
        h.fail(spacings, "expected positive spacings for the space axes, found " + spacings->value);
      axes(a, a) = s;
    }
  }
  Vec3 spacing;
  Mat3 direction;
  for (int a = 0; a < 3; ++a) {
    spacing[a] = axes.col(a).norm();
    direction.col(a) = axes.col(a) / spacing[a];
  }
  Mat3 frame = Mat3::Identity();
  if (const HeaderField* f = h.find("measurement frame")) {
    const std::vector<std::optional<Vec3>> m = vectors(h, f);
    if (m.size() != 3 || !m[0] || !m[1] || !m[2]) h.fail(f, "expected three vectors, found " + f->value);
    frame << *m[0], *m[1], *m[2];
  }

  const vtkIdType voxels = vtkIdType(count / std::uint64_t(layout.values));
  // Six components (symmetric tensors) go straight into the field's own
  // storage (tensor_storage.h), which read_tensors() takes over. Other
  // values are floats where the file's numbers are (or fit in them
  // exactly): the array is read once more, into the field's doubles, and a
  // double copy beside those was the read's peak.
  const int out_components = layout.kind == VoxelLayout::scalar ? 1
                             : layout.kind == VoxelLayout::vector ? 3
                             : layout.kind == VoxelLayout::full   ? 9
                                                                  : 6;
  const bool text = text_encoding(h);
  const bool as_float =
      out_components != 6 && !text && (type.kind == NumberType::floating ? type.bytes == 4 : type.bytes <= 2);
  // What the read takes, refused before any of it is allocated: the
  // 2^31-value guard above still lets a header ask for 17 GB of doubles,
  // and a 2 MB gzip stream inflates to 2 GB. The array made below, and the
  // values decoded first where they are not read in place (gzip's output,
  // ASCII's numbers as doubles); raw data is mapped, not held.
  const double decoded = text ? 8.0 * double(count)
                         : h.value("encoding", "") == "raw" ? 0.0
                                                            : double(type.bytes) * double(count);
  check_memory(decoded + double(voxels) * out_components * (as_float ? 4.0 : 8.0),
               path + ": the volume its header declares (sizes " + sizes_field->value + ", " +
                   h.value("type", "") + " values)",
               "a header that declares more values than its data holds is corrupt; else read the volume where "
               "more memory is free");
  const DecodedValues values = read_values(h, path, count, type);
  const vtkSmartPointer<vtkDataArray> array = volume_array(voxels, out_components, as_float);
  array->SetName(layout.kind == VoxelLayout::scalar   ? "values"
                 : layout.kind == VoxelLayout::vector ? "vectors"
                                                      : "tensors");
  const ComponentOrder& teem_order = *component_order("teem");
  const ComponentOrder& vtk_order = *component_order("vtk");
  const bool in_space_frame = frame == Mat3::Identity();
  // Written in place: VTK's per-tuple setters cost a third of the read.
  // Each voxel is its own: in bands on every core.
  const auto convert = [&](const auto& at, auto* out, vtkIdType i) {
    using Out = std::remove_pointer_t<decltype(out)>;  // float or double: the array's
    double v[10];  // the voxel's values (at most a masked 3×3 matrix's ten)
    for (int k = 0; k < layout.values; ++k) v[k] = at(std::uint64_t(i) * std::uint64_t(layout.values) + std::uint64_t(k));
    Out* o = out + std::size_t(i) * std::size_t(out_components);
    const auto put = [&](const double* from, int n) {
      for (int c = 0; c < n; ++c) o[c] = Out(from[c]);
    };
    if (layout.kind == VoxelLayout::scalar) {
      put(v, 1);
      return;
    }
    if (layout.kind == VoxelLayout::vector) {
      put((frame * Vec3(v[0], v[1], v[2])).eval().data(), 3);
      return;
    }
    const double* t = v + (layout.masked ? 1 : 0);
    const bool outside = layout.masked && !(v[0] >= 0.5);  // Teem: below 0.5 is outside the mask
    if (out_components == 9) {
      Eigen::Matrix<double, 3, 3, Eigen::RowMajor> m = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(t);
      if (outside) m.setConstant(std::nan(""));
      put(m.data(), 9);
      return;
    }
    Sym3 sym = tensor_in_order(t, teem_order);
    std::array<double, 6> six = components_in_order(sym, vtk_order);
    if (outside) six.fill(std::nan(""));
    put(six.data(), 6);
  };
  const auto convert_all = [&](auto* out) {
    with_values(values, [&](const auto& at) {
      tbb::parallel_for(tbb::blocked_range<vtkIdType>(0, voxels, 8192), [&](const tbb::blocked_range<vtkIdType>& band) {
        for (vtkIdType i = band.begin(); i < band.end(); ++i) convert(at, out, i);
      });
    });
  };
  if (as_float) convert_all(static_cast<float*>(array->GetVoidPointer(0)));
  else convert_all(static_cast<double*>(array->GetVoidPointer(0)));

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetSpacing(spacing.x(), spacing.y(), spacing.z());
  image->SetOrigin(origin.x(), origin.y(), origin.z());
  auto matrix = vtkSmartPointer<vtkMatrix3x3>::New();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, direction(r, c));
  image->SetDirectionMatrix(matrix);
  if (const HeaderField* f = h.find("space"))
    if (const std::string letters = anatomical_letters(f->value); !letters.empty())
      add_record(image->GetFieldData(), kAnatomicalFrame, {letters});
  if (layout.kind == VoxelLayout::scalar) {
    image->GetPointData()->SetScalars(array);
  } else if (layout.kind == VoxelLayout::vector) {
    image->GetPointData()->SetVectors(array);
  } else {
    image->GetPointData()->SetTensors(array);
    record_component_order(image->GetFieldData(), array->GetName(), "NRRD, " + layout.said);
    if (!in_space_frame) record_tensor_frame(image->GetFieldData(), array->GetName(), frame);
    record_frame_note(image->GetFieldData(), array->GetName(),
                      {in_space_frame ? "the space's own axes (no measurement frame, or the identity)"
                                      : "its measurement frame, turned into its space"});
  }
  return image;
}

vtkSmartPointer<vtkDataSet> read_nrrd_data(const std::string& path, const ReadRequest& request, const VtkSession&) {
  return read_nrrd(path, request.scalar);
}

// A detached header's data file.
std::vector<std::string> nrrd_parts(const std::string& path) {
  const std::string data = data_file(read_header(path), path);
  return data == path ? std::vector<std::string>{} : std::vector<std::string>{data};
}

}  // namespace

const FormatReader nrrd_reader{read_nrrd_data, nullptr, nrrd_parts, nullptr, false, false, true};

}  // namespace hsb

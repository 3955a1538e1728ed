// MRtrix images (.mif, .mif.gz, and a .mih header beside its data), as
// MRtrix 3's dwi2tensor, mrconvert and its other commands write them, read
// by hsb itself: no library in Debian reads the format (MRtrix3 ships its
// commands, no library), and VTK knows nothing of it.
// What is read:
//  - the text header, from its first line "mrtrix image" to its line
//    "END": dim, vox, layout, datatype, transform, scaling, file (others,
//    such as command_history and dw_scheme, and comments are passed over);
//  - the data in the header's own file at the offset `file: . N` names,
//    or in the one file `file: name.dat N` names beside a .mih; a whole
//    .mif.gz inflated (no split data: a numbered series of files is
//    refused);
//  - any layout (each axis's stride rank, a minus for one stored in
//    reverse, the volume axis fastest or slowest), any of MRtrix's number
//    types but the complex ones, either byte order, with its scaling;
//  - placed in the scanner's space by the transform (unit columns, the
//    voxel sizes in vox), as MRtrix places it: voxel (i, j, k) of the
//    image as MRtrix indexes it is at transform · (i vox0, j vox1, k vox2).
// A fourth axis of six values is dwi2tensor's tensor, D11 D22 D33 D12 D13
// D23 in the scanner's axes, turned into VTK's order; of three, a vector
// (sh2peaks', in the scanner's axes too); a 3-D image is a mask's one value
// per voxel. Internal to field/. Every count the header declares is
// checked against the bytes there are before any is read, so the file is
// parsed in this process (FormatReader::in_process).

#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <type_traits>

#include "base/input_file.h"
#include "base/mapped_file.h"
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

// The most values an image may declare: far beyond any scan, and the
// guard that keeps a corrupt `dim:` from asking for all memory.
constexpr std::uint64_t most_values = std::uint64_t(1) << 31;
// The longest header read while looking for its END: MRtrix's own run to
// some kilobytes (a dw_scheme of a thousand directions is 40 KB).
constexpr std::size_t most_header_bytes = std::size_t(16) << 20;

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

// The file's bytes in order, inflated for a .mif.gz: zlib's gz functions
// read a file without gzip's signature as it is, so the header of every
// kind is read here; the data of an uncompressed one is mapped instead.
class FileBytes {
 public:
  explicit FileBytes(const std::string& path) : path_(path), file_(gzopen(path.c_str(), "rb")) {
    if (!file_) throw DataError(path + ": cannot open it");
    gzbuffer(file_, 1 << 17);
  }
  ~FileBytes() { gzclose(file_); }
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;

  // Reads on into `bytes` until it holds `until` bytes or the file ends
  // (false). Grown as the bytes come, not to `until` at once: a corrupt
  // size must not take all memory.
  bool fill(std::vector<unsigned char>& bytes, std::uint64_t until) {
    std::size_t have = bytes.size();
    while (have < until) {
      const std::size_t want =
          std::size_t(std::min<std::uint64_t>(until, std::max<std::uint64_t>(2 * std::uint64_t(have), have + (1 << 20))));
      bytes.resize(want);
      while (have < want) {
        const int got = gzread(file_, bytes.data() + have, unsigned(std::min<std::size_t>(want - have, 1 << 30)));
        int status = Z_OK;
        const char* said = gzerror(file_, &status);
        if (got < 0 || status == Z_DATA_ERROR || status == Z_ERRNO || status == Z_MEM_ERROR)
          throw DataError(path_ + (status == Z_DATA_ERROR ? ": its gzip compression is corrupt (" : ": cannot read it (") +
                          std::string(said ? said : "zlib") + ")");
        if (got == 0) {
          bytes.resize(have);
          return false;
        }
        have += std::size_t(got);
      }
    }
    return true;
  }

  // Whether the bytes are inflated: a .mif.gz, whatever its name says.
  bool compressed() { return gzdirect(file_) == 0; }

 private:
  const std::string& path_;
  gzFile file_;
};

// One `key: value` line of the header, with where it stood.
struct HeaderField {
  std::string value;
  int line = 0;
};

struct Header {
  std::map<std::string, std::vector<HeaderField>> fields;  // by key, lower case; in their order
  std::size_t size = 0;  // its bytes, up to and with the END line
  const std::string* path = nullptr;

  const std::vector<HeaderField>* all(const std::string& key) const {
    auto it = fields.find(key);
    return it == fields.end() ? nullptr : &it->second;
  }
  const HeaderField* find(const std::string& key) const {
    const std::vector<HeaderField>* f = all(key);
    return f ? &f->front() : nullptr;
  }
  const HeaderField& required(const std::string& key) const {
    if (const HeaderField* f = find(key)) return *f;
    fail(nullptr, "the MRtrix header has no \"" + key + ":\" line");
  }
  [[noreturn]] void fail(const HeaderField* field, const std::string& what) const {
    throw DataError(*path + (field ? ":" + std::to_string(field->line) : std::string()) + ": " + what);
  }
};

// The header: "mrtrix image", then `key: value` lines up to "END", read
// from the start of `in` into `bytes` (which may hold some data after it).
// As MRtrix's own reader: a '#' starts a comment, a line without a colon
// is passed over.
Header read_header(const std::string& path, FileBytes& in, std::vector<unsigned char>& bytes) {
  Header h;
  h.path = &path;
  static const std::string signature = "mrtrix image";
  std::size_t line_start = 0;  // of the first line not yet read whole
  int number = 0;
  for (;;) {
    const bool more = in.fill(bytes, bytes.size() + (1 << 16));
    if (bytes.empty()) throw DataError(path + ": it is empty: not an MRtrix image");
    // Another file says so at once, not after 16 MiB of it.
    if (number == 0 && std::memcmp(bytes.data(), signature.data(), std::min(bytes.size(), signature.size())) != 0)
      throw DataError(path + ":1: not an MRtrix image: its first line is not \"mrtrix image\"");
    while (line_start < bytes.size()) {
      const auto* at = static_cast<const unsigned char*>(
          std::memchr(bytes.data() + line_start, '\n', bytes.size() - line_start));
      if (!at && more) break;  // the line goes on in what is not read yet
      const std::size_t line_end = at ? std::size_t(at - bytes.data()) : bytes.size();
      std::string line(bytes.begin() + std::ptrdiff_t(line_start), bytes.begin() + std::ptrdiff_t(line_end));
      line_start = line_end + (at ? 1 : 0);
      if (++number == 1) {
        if (trimmed(line) != signature)
          throw DataError(path + ":1: not an MRtrix image: its first line is not \"mrtrix image\"");
        continue;
      }
      line = trimmed(line.substr(0, line.find('#')));
      if (line == "END") {
        h.size = line_start;
        return h;
      }
      const std::size_t colon = line.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = lower(trimmed(line.substr(0, colon)));
      if (!key.empty()) h.fields[key].push_back({trimmed(line.substr(colon + 1)), number});
    }
    if (!more)
      throw DataError(path + ": the MRtrix header ends without its \"END\" line (" + std::to_string(number) +
                      " lines, then the end of the " + (in.compressed() ? "inflated " : "") + "file)");
    if (bytes.size() > most_header_bytes)
      throw DataError(path + ": no \"END\" line in the first 16 MiB of the MRtrix header (" + std::to_string(number) +
                      " lines): not a header MRtrix writes");
  }
}

// The comma-separated numbers of a field, such as "2,2,2,nan".
std::vector<double> numbers(const Header& h, const HeaderField& f, const std::string& key, const char* example) {
  std::vector<double> out;
  std::istringstream in(f.value);
  for (std::string word; std::getline(in, word, ',');) {
    word = trimmed(word);
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (word.empty() || *end != '\0')
      h.fail(&f, "\"" + key + ":\" expects numbers such as " + example + ", found \"" + f.value + "\"");
    out.push_back(v);
  }
  return out;
}

// A number type: its size and how its bytes read.
struct NumberType {
  int bytes = 4;  // 0: one bit a value
  enum Kind { bit, integer, unsigned_integer, floating } kind = floating;
  bool swap = false;  // stored in the other byte order than this machine's
};

bool big_endian_machine() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

// MRtrix's datatype names: Bit, Int8, UInt8, then Int16 to Float64 with
// an optional LE or BE (without, this machine's order); case aside.
NumberType number_type(const Header& h) {
  const HeaderField& f = h.required("datatype");
  std::string name = lower(f.value);
  if (name.rfind("cfloat", 0) == 0)
    h.fail(&f, "\"datatype: " + f.value + "\" is complex: its values are no tensor components");
  using K = NumberType::Kind;
  if (name == "bit") return {0, K::bit, false};
  if (name == "int8") return {1, K::integer, false};
  if (name == "uint8") return {1, K::unsigned_integer, false};
  bool swap = false;
  if (name.size() > 2 && (name.compare(name.size() - 2, 2, "le") == 0 || name.compare(name.size() - 2, 2, "be") == 0)) {
    swap = (name.back() == 'e' && name[name.size() - 2] == 'b') != big_endian_machine();
    name.resize(name.size() - 2);
  }
  static const std::map<std::string, NumberType> types{
      {"int16", {2, K::integer}},   {"uint16", {2, K::unsigned_integer}}, {"int32", {4, K::integer}},
      {"uint32", {4, K::unsigned_integer}}, {"int64", {8, K::integer}}, {"uint64", {8, K::unsigned_integer}},
      {"float32", {4, K::floating}}, {"float64", {8, K::floating}}};
  auto it = types.find(name);
  if (it == types.end())
    h.fail(&f, "\"datatype: " + f.value + "\" is no MRtrix number type (Bit, Int8, UInt8, Int16LE to UInt64BE, "
                                          "Float32LE, Float64BE, ...)");
  NumberType type = it->second;
  type.swap = swap;
  return type;
}

// Where the data is: `file: NAME [OFFSET]`, NAME "." for the header's own file.
struct DataPlace {
  std::string path;
  std::uint64_t offset = 0;
  bool own_file = true;
  const HeaderField* field = nullptr;
};

DataPlace data_place(const Header& h, const std::string& path) {
  const std::vector<HeaderField>* files = h.all("file");
  if (!files) h.fail(nullptr, "the MRtrix header has no \"file:\" line: it does not say where its data is");
  const HeaderField& f = files->front();
  if (files->size() > 1)
    h.fail(&(*files)[1], "the data is split over " + std::to_string(files->size()) +
                             " \"file:\" entries, which hsb does not read: join them with mrconvert");
  std::istringstream in(f.value);
  std::string name, offset, rest;
  in >> name >> offset >> rest;
  if (name.empty()) h.fail(&f, "\"file:\" expects a file name (\".\" for this one) and a byte offset, found nothing");
  if (name.find('[') != std::string::npos)
    h.fail(&f, "\"file: " + f.value + "\" names a numbered series of data files, which hsb does not read: join them "
                                      "with mrconvert");
  DataPlace place;
  place.field = &f;
  if (!offset.empty()) {
    char* end = nullptr;
    const unsigned long long at = std::strtoull(offset.c_str(), &end, 10);
    if (!std::isdigit(static_cast<unsigned char>(offset[0])) || *end != '\0' || !rest.empty() || at > (1ULL << 62))
      h.fail(&f, "\"file:\" expects a file name and a byte offset such as \". 1024\", found \"" + f.value + "\"");
    place.offset = at;
  }
  if (name == ".") {
    place.path = path;
    // MRtrix puts it right after the header's END, on a 4-byte boundary;
    // far beyond, a .mif.gz would be inflated for nothing.
    if (place.offset < h.size || place.offset - h.size > most_header_bytes)
      h.fail(&f, "\"file: " + f.value + "\" puts the data at byte " + std::to_string(place.offset) +
                     ", not just after the header, which ends at byte " + std::to_string(h.size));
    return place;
  }
  place.own_file = false;
  place.path = file_named_in(path, name);
  return place;
}

// Everything the header says, checked against itself.
struct Image {
  std::array<int, 3> dims{};  // the three space axes
  int values = 1;             // per voxel: the size of a fourth axis
  std::uint64_t count = 1;    // values in all
  std::uint64_t bytes = 0;    // the data's
  NumberType type;
  // The element of voxel (0, 0, 0)'s first value, and the step from one
  // voxel to the next along each space axis and the volume axis (signed:
  // an axis stored in reverse steps back), from the layout.
  std::int64_t first = 0;
  std::array<std::int64_t, 4> steps{};
  Vec3 spacing, origin;
  Mat3 direction;
  double offset = 0, scale = 1;  // value = offset + scale × stored
};

Image read_image_header(const Header& h, bool scalar) {
  Image im;
  const HeaderField& dim = h.required("dim");
  const std::vector<double> sizes = numbers(h, dim, "dim", "64,64,30,6");
  for (double s : sizes) {
    if (!(s >= 1 && s < double(most_values)) || s != std::floor(s))  // each an int for VTK
      h.fail(&dim, "\"dim:\" expects whole numbers from 1 to 2^31 - 1, found \"" + dim.value + "\"");
    im.count *= std::uint64_t(s);
    if (im.count > most_values) h.fail(&dim, "\"dim: " + dim.value + "\" declares more than 2^31 values");
  }
  const std::size_t axes = sizes.size();
  if (axes < 3) h.fail(&dim, "\"dim:\" expects three space axes or more, found \"" + dim.value + "\"");
  for (std::size_t a = 4; a < axes; ++a)
    if (sizes[a] != 1)
      h.fail(&dim, "\"dim: " + dim.value + "\" has a fifth axis of more than one: one volume of tensors, vectors or "
                   "a mask's values is read; pick it with mrconvert -coord");
  for (int a = 0; a < 3; ++a) im.dims[std::size_t(a)] = int(sizes[std::size_t(a)]);
  im.values = axes > 3 ? int(sizes[3]) : 1;
  if (scalar && im.values != 1)
    h.fail(&dim, "its voxels hold " + std::to_string(im.values) + " values (\"dim: " + dim.value +
                     "\"); a mask is a volume of one value per voxel");
  if (!scalar && im.values == 1)
    h.fail(&dim, "its voxels hold one value (\"dim: " + dim.value + "\"): a mask or a scalar map, no tensors (6 values "
                 "along the fourth axis, as dwi2tensor writes them); a mask is given as region.mask, beside the "
                 "tensors' file");
  if (!scalar && im.values != 6 && im.values != 3)
    h.fail(&dim, "its voxels hold " + std::to_string(im.values) + " values (\"dim: " + dim.value +
                     "\"); a tensor image has 6 along its fourth axis (dwi2tensor's D11 D22 D33 D12 D13 D23), or 3 "
                     "for vectors");

  im.type = number_type(h);
  im.bytes = im.type.kind == NumberType::bit ? (im.count + 7) / 8 : im.count * std::uint64_t(im.type.bytes);

  // The layout: for each axis its rank in memory (0 fastest), a minus for
  // an axis stored from its last voxel to its first. As MRtrix's
  // parse_axes, a rank without a sign is stored forward.
  const HeaderField& layout = h.required("layout");
  std::vector<int> rank;
  std::vector<bool> reversed;
  {
    std::istringstream in(layout.value);
    for (std::string word; std::getline(in, word, ',');) {
      word = trimmed(word);
      const bool minus = !word.empty() && word[0] == '-';
      const std::string digits = !word.empty() && (word[0] == '-' || word[0] == '+') ? word.substr(1) : word;
      if (digits.empty() || digits.size() > 3 || !std::all_of(digits.begin(), digits.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c));
          }))
        h.fail(&layout, "\"layout:\" expects a signed rank for each axis such as +0,+1,+2,+3, found \"" +
                            layout.value + "\"");
      rank.push_back(std::atoi(digits.c_str()));
      reversed.push_back(minus);
    }
  }
  std::vector<int> order(rank.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return rank[std::size_t(a)] < rank[std::size_t(b)]; });
  bool permutation = rank.size() == axes;
  for (std::size_t r = 0; permutation && r < axes; ++r) permutation = rank[std::size_t(order[r])] == int(r);
  if (!permutation)
    h.fail(&layout, "\"layout: " + layout.value + "\" is not a rank from 0 to " + std::to_string(axes - 1) +
                        " for each of the " + std::to_string(axes) + " axes of \"dim: " + dim.value + "\"");
  std::vector<std::int64_t> step(axes);
  std::int64_t stride = 1;
  for (int a : order) {
    const auto size = std::int64_t(sizes[std::size_t(a)]);
    step[std::size_t(a)] = reversed[std::size_t(a)] ? -stride : stride;
    if (reversed[std::size_t(a)]) im.first += (size - 1) * stride;
    stride *= size;
  }
  for (std::size_t a = 0; a < 4; ++a) im.steps[a] = a < axes ? step[a] : 0;

  // Voxel sizes, and the transform with unit columns that turns a voxel's
  // index times them into the scanner's millimetres.
  const HeaderField& vox_field = h.required("vox");
  const std::vector<double> vox = numbers(h, vox_field, "vox", "2,2,2,nan");
  if (vox.size() < 3 || !(vox[0] > 0 && vox[1] > 0 && vox[2] > 0) || !std::isfinite(vox[0]) || !std::isfinite(vox[1]) ||
      !std::isfinite(vox[2]))
    h.fail(&vox_field, "\"vox:\" expects a positive size for each space axis, found \"" + vox_field.value + "\"");
  Mat3 rotation = Mat3::Identity();
  Vec3 shift;
  if (const std::vector<HeaderField>* rows = h.all("transform")) {
    if (rows->size() < 3)
      h.fail(&rows->back(), "expected three \"transform:\" lines (the rows of a 3×4 matrix), found " +
                                std::to_string(rows->size()));
    for (int r = 0; r < 3; ++r) {
      const HeaderField& row = (*rows)[std::size_t(r)];
      const std::vector<double> n = numbers(h, row, "transform", "0.94,-0.34,0.06,4.98");
      if (n.size() != 4 || !std::all_of(n.begin(), n.end(), [](double x) { return std::isfinite(x); }))
        h.fail(&row, "\"transform:\" expects a row of four finite numbers, found \"" + row.value + "\"");
      rotation.row(r) << n[0], n[1], n[2];
      shift[r] = n[3];
    }
  } else {
    // MRtrix's default: its axes, the image centred on the origin.
    for (int a = 0; a < 3; ++a) shift[a] = -0.5 * (im.dims[std::size_t(a)] - 1) * vox[std::size_t(a)];
  }
  // A column that is not of unit length scales its voxel size, as MRtrix
  // reads it (Header::sanitise_transform).
  for (int a = 0; a < 3; ++a) {
    const Vec3 axis = rotation.col(a) * vox[std::size_t(a)];
    im.spacing[a] = axis.norm();
    if (!(im.spacing[a] > 0) || !std::isfinite(im.spacing[a]))
      h.fail(h.find("transform"), "the transform's column " + std::to_string(a) + " is zero: the voxels have no size");
    im.direction.col(a) = axis / im.spacing[a];
  }
  if (!(std::fabs(im.direction.determinant()) > 1e-9))
    h.fail(h.find("transform"), "the transform's axes are not independent: the voxels have no volume");
  im.origin = shift;

  if (const HeaderField* f = h.find("scaling")) {
    const std::vector<double> s = numbers(h, *f, "scaling", "0,1");
    if (s.size() != 2 || !std::isfinite(s[0]) || !std::isfinite(s[1]))
      h.fail(f, "\"scaling:\" expects an offset and a scale such as 0,1, found \"" + f->value + "\"");
    im.offset = s[0];
    im.scale = s[1];
  }
  return im;
}

// Calls `use(at)`, `at(e)` being element e of `data` as a double, with
// `at` made for the number type (one loop compiled a type, not a call a
// value). Bits are packed eight a byte, the first in the highest bit.
template <class Use>
void with_numbers(const unsigned char* data, NumberType type, Use&& use) {
  using K = NumberType::Kind;
  if (type.kind == K::bit) {
    use([data](std::uint64_t e) { return double((data[e >> 3] >> (7 - (e & 7))) & 1); });
    return;
  }
  const NumberKind kind = type.kind == K::floating  ? NumberKind::floating
                          : type.kind == K::integer ? NumberKind::integer
                                                    : NumberKind::unsigned_integer;
  if (!with_typed_numbers(data, type.bytes, kind, type.swap, use))
    throw std::logic_error("MRtrix: a number type without a reader");
}

// The data's bytes, held here: mapped (an uncompressed file), read (where
// it cannot be mapped) or inflated (the whole .mif.gz, header and all).
struct DataBytes {
  MappedFile mapped;
  std::vector<unsigned char> held;
  const unsigned char* bytes = nullptr;
};

// Says that the data is shorter than the header declares: `there` bytes
// follow the data's offset.
[[noreturn]] void fail_short(const Header& h, const DataPlace& place, const Image& im, std::uint64_t there,
                             bool compressed) {
  h.fail(place.field, "the data is cut short: \"file: " + place.field->value + "\" puts it at byte " +
                          std::to_string(place.offset) + (place.own_file ? "" : " of " + place.path) + ", where \"dim: " +
                          h.required("dim").value + "\" of \"datatype: " + h.required("datatype").value +
                          "\" declares " + std::to_string(im.bytes) + " bytes; the " +
                          (compressed ? "inflated file" : "file") + " has " + std::to_string(there) + " from there");
}

DataBytes read_data(const Header& h, const DataPlace& place, const Image& im, FileBytes& in,
                    std::vector<unsigned char>& read_so_far) {
  DataBytes d;
  const std::uint64_t end = place.offset + im.bytes;
  if (in.compressed()) {
    // The whole inflated file up to the data's end, header and all: no
    // more than the header and the data it declares.
    if (!place.own_file)
      h.fail(place.field, "a .mif.gz holds its data in itself (\"file: . OFFSET\"), found \"file: " +
                              place.field->value + "\"");
    in.fill(read_so_far, end);
    const std::uint64_t got = read_so_far.size();
    if (got < end) fail_short(h, place, im, got - std::min(got, place.offset), true);
    d.held = std::move(read_so_far);
    d.bytes = d.held.data() + place.offset;
    return d;
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(place.path, error))
    h.fail(place.field, "cannot open its data file " + place.path + " (\"file: " + place.field->value + "\")");
  const std::uint64_t size = std::filesystem::file_size(place.path, error);
  if (error) h.fail(place.field, "cannot read its data file " + place.path + ": " + error.message());
  if (size < end) fail_short(h, place, im, size - std::min(size, place.offset), false);
  d.mapped = MappedFile(place.path);
  if (d.mapped.size() >= end) {
    d.bytes = d.mapped.data() + place.offset;
    return d;
  }
  // Not mapped (refused): the data's own bytes, read.
  std::ifstream data(place.path, std::ios::binary);
  data.seekg(std::streamoff(place.offset));
  d.held.resize(std::size_t(im.bytes));
  data.read(reinterpret_cast<char*>(d.held.data()), std::streamsize(im.bytes));
  if (std::uint64_t(data.gcount()) < im.bytes) fail_short(h, place, im, std::uint64_t(data.gcount()), false);
  d.bytes = d.held.data();
  return d;
}

// A tensor (or vector) image, or with `scalar` a mask's one value a voxel.
vtkSmartPointer<vtkImageData> read_mif(const std::string& path, bool scalar) {
  FileBytes in(path);
  std::vector<unsigned char> bytes;
  const Header h = read_header(path, in, bytes);
  const Image im = read_image_header(h, scalar);
  const DataPlace place = data_place(h, path);
  const DataBytes data = read_data(h, place, im, in, bytes);

  const int nx = im.dims[0], ny = im.dims[1], nz = im.dims[2];
  const vtkIdType voxels = vtkIdType(nx) * ny * nz;
  // Floats where the file's numbers fit them and no scaling changes them
  // (as the NRRD and NIfTI readers); six components go straight into the
  // field's own storage (tensor_storage.h).
  const bool unscaled = im.offset == 0.0 && im.scale == 1.0;
  const NumberType t = im.type;
  const bool as_float = im.values != 6 && unscaled &&
                        (t.kind == NumberType::floating ? t.bytes == 4 : t.bytes <= 2);
  const vtkSmartPointer<vtkDataArray> array = volume_array(voxels, im.values, as_float);
  array->SetName(scalar ? "values" : im.values == 3 ? "vectors" : "tensors");
  const ComponentOrder& mrtrix_order = *component_order("mrtrix");
  const ComponentOrder& vtk_order = *component_order("vtk");
  // From the layout's order into VTK's, x fastest: a row of x at a time,
  // the rows in bands on every core (each voxel is its own).
  const auto convert_all = [&](auto* out) {
    using Out = std::remove_pointer_t<decltype(out)>;  // float or double: the array's
    with_numbers(data.bytes, t, [&](const auto& at) {
      const std::int64_t rows = std::int64_t(ny) * nz;
      tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, rows, 16), [&](const tbb::blocked_range<std::int64_t>& band) {
        for (std::int64_t row = band.begin(); row < band.end(); ++row) {
          const std::int64_t j = row % ny, k = row / ny;
          std::int64_t e = im.first + j * im.steps[1] + k * im.steps[2];
          Out* o = out + std::size_t(row) * std::size_t(nx) * std::size_t(im.values);
          for (int i = 0; i < nx; ++i, e += im.steps[0], o += im.values) {
            double v[6] = {};
            for (int c = 0; c < im.values; ++c) v[c] = im.offset + im.scale * at(std::uint64_t(e + c * im.steps[3]));
            if (im.values == 6) {
              const std::array<double, 6> six = components_in_order(tensor_in_order(v, mrtrix_order), vtk_order);
              std::copy(six.begin(), six.end(), v);
            }
            for (int c = 0; c < im.values; ++c) o[c] = Out(v[c]);
          }
        }
      });
    });
  };
  if (as_float) convert_all(static_cast<float*>(array->GetVoidPointer(0)));
  else convert_all(static_cast<double*>(array->GetVoidPointer(0)));

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(im.spacing.data());
  image->SetOrigin(im.origin.data());
  auto matrix = vtkSmartPointer<vtkMatrix3x3>::New();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, im.direction(r, c));
  image->SetDirectionMatrix(matrix);
  // MRtrix's scanner space is RAS+, as NIfTI's.
  vtkFieldData* records = image->GetFieldData();
  add_record(records, kAnatomicalFrame, {"RAS"});
  if (scalar) {
    image->GetPointData()->SetScalars(array);
  } else if (im.values == 3) {
    image->GetPointData()->SetVectors(array);
  } else {
    image->GetPointData()->SetTensors(array);
    record_component_order(records, "tensors", "MRtrix's .mif (dwi2tensor): D11 D22 D33 D12 D13 D23");
    record_voxel_axes(records, "tensors", im.direction);
    record_frame_note(records, "tensors", {"the scanner's axes, as MRtrix writes them"});
  }
  return image;
}

vtkSmartPointer<vtkDataSet> read_mif_data(const std::string& path, const ReadRequest& request, const VtkSession&) {
  return read_mif(path, request.scalar);
}

// A .mih's data file (or any header's whose `file:` names another).
std::vector<std::string> mif_parts(const std::string& path) {
  FileBytes in(path);
  std::vector<unsigned char> bytes;
  const Header h = read_header(path, in, bytes);
  const DataPlace place = data_place(h, path);
  return place.own_file ? std::vector<std::string>{} : std::vector<std::string>{place.path};
}

}  // namespace

const FormatReader mif_reader{read_mif_data, nullptr, mif_parts, nullptr, false, false, true};

}  // namespace hsb

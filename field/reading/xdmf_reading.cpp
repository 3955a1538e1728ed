// XDMF 2 and 3 (.xdmf, .xmf): XML that describes a mesh and its results
// (the "light data"), with the arrays (the "heavy data") in HDF5 files
// beside it or inline in the XML, as FEniCS/dolfin, meshio and many
// simulation codes write it. Read by hsb itself: the XML with libxml2
// (XInclude with the XPointers dolfin writes, XPath for XDMF 2's Reference
// DataItems), the arrays with HDF5's C API (the serial HDF5 that VTK's
// readers already load into hsb).
//
// Not through the XDMF library: Debian 12's libxdmf3 (3.0+git20190531)
// links and reads these files, but it takes a DataItem without Precision
// as 4-byte (XDMF's default) and has HDF5 convert dolfin's float64
// coordinates and stresses to float32; it counts values in 32-bit
// integers; it reports a missing .h5 as "number of dimensions does not
// match" after printing HDF5's error stack; and the libXdmfCore.so.3 on
// the library path is its OpenMPI build, which would load a second HDF5
// and MPI beside VTK's serial one. Here every array is read in the type
// its HDF5 dataset has, and every count the XML declares is checked
// against the dataset before anything is allocated.
//
// What is read:
//  - unstructured Grids: Triangle, Quadrilateral, Tetrahedron, Pyramid,
//    Wedge, Hexahedron, their quadratic forms (Triangle_6,
//    Quadrilateral_8, Tetrahedron_10, Pyramid_13, Wedge_15,
//    Hexahedron_20) and Mixed of those, with BaseOffset; XDMF's node
//    orders are VTK's (its own library and VTK's XDMF readers copy the
//    connectivity as it is). Cells the writer wound the other way (dolfin
//    sorts each tetrahedron's vertices, so about half are) are turned
//    round: the values move with their nodes, so the field is unchanged,
//    and the body's faces point out;
//  - Geometry XYZ, XY and X_Y_Z;
//  - Attributes at Nodes (point data) and Cells (cell data) under the
//    names the file gives: Scalar, Vector, Tensor (nine, row by row),
//    Matrix, and Tensor6, whose XX XY XZ YY YZ ZZ is turned into VTK's
//    order and recorded (field/reading/component_arrays.h);
//  - DataItems in XML or HDF format (any integer or float type, chunked
//    and compressed as HDF5 reads them), HyperSlabs of them; XDMF 2's
//    References (XPath) to DataItems, Topologies, Geometries;
//  - a temporal collection's grids as time steps (ReadRequest::step), the
//    times from each grid's <Time Value> or the collection's Time list;
//    a spatial collection's grids (pieces, or the Domain's several grids)
//    merged as blocks (field/reading/block_merging.h).
// Internal to field/; the file is parsed only in a child process
// (field/reading/dataset_reading.h).

#include <hdf5.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/uri.h>
#include <libxml/xinclude.h>
#include <libxml/xmlerror.h>
#include <libxml/xpath.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <new>
#include <set>

#include "base/input_file.h"
#include "base/vec3.h"
#include "field/reading/block_merging.h"
#include "field/reading/component_arrays.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"

namespace hsb {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  return first == std::string::npos ? "" : text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// ---- The XML --------------------------------------------------------------

bool is_element(xmlNodePtr node, const char* name) {
  return node && node->type == XML_ELEMENT_NODE && xmlStrcmp(node->name, BAD_CAST name) == 0;
}

std::vector<xmlNodePtr> children(xmlNodePtr node, const char* name) {
  std::vector<xmlNodePtr> found;
  for (xmlNodePtr child = node->children; child; child = child->next)
    if (is_element(child, name)) found.push_back(child);
  return found;
}

std::string attribute(xmlNodePtr node, const char* name) {
  xmlChar* value = xmlGetProp(node, BAD_CAST name);
  if (!value) return "";
  std::string text(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return text;
}

// XDMF 3's attribute name, else XDMF 2's older one ("Type" for most).
std::string attribute(xmlNodePtr node, const char* name, const char* old_name) {
  const std::string value = attribute(node, name);
  return value.empty() ? attribute(node, old_name) : value;
}

std::string text_of(xmlNodePtr node) {
  xmlChar* content = xmlNodeGetContent(node);
  std::string text = content ? reinterpret_cast<const char*>(content) : "";
  xmlFree(content);
  return text;
}

// Where an element is, for messages: "line 17, <DataItem>".
std::string at(xmlNodePtr node) {
  std::string where =
      "line " + std::to_string(xmlGetLineNo(node)) + ", <" + reinterpret_cast<const char*>(node->name) + ">";
  if (const std::string name = attribute(node, "Name"); !name.empty()) where += " \"" + name + "\"";
  return where;
}

// The first message libxml2 has for a parse, kept instead of printed.
void keep_first_error(void* kept, xmlErrorPtr error) {
  auto* first = static_cast<std::string*>(kept);
  if (first->empty() && error && error->message)
    *first = trimmed(error->message) + (error->line > 0 ? " (line " + std::to_string(error->line) + ")" : "");
}

// The file an xi:include names that is no regular file (a FIFO would
// wait for a writer for ever, a device never end), and why; libxml2
// itself would open it. Set by the entity loader below, while a document
// is read; the reading child reads one at a time.
std::string refused_include;
xmlExternalEntityLoader next_loader = nullptr;

xmlParserInputPtr regular_files_only(const char* url, const char* id, xmlParserCtxtPtr context) {
  if (url) {
    std::string path = url;
    if (path.rfind("file://", 0) == 0) path.erase(0, 7);
    if (char* plain = xmlURIUnescapeString(path.c_str(), 0, nullptr)) {
      path = plain;
      xmlFree(plain);
    }
    if (const std::string why = unreadable_input(path); !why.empty()) {
      if (refused_include.empty()) refused_include = path + ": " + why;
      return nullptr;
    }
  }
  return next_loader(url, id, context);
}

// The .xdmf parsed, its <Xdmf> root checked, and XIncludes processed
// (unless `include` is false); freed at the end of scope. libxml2's
// messages are kept, not printed, meanwhile.
class XdmfDocument {
 public:
  XdmfDocument(const std::string& path, bool include)
      : handler_(xmlStructuredError), handler_context_(xmlStructuredErrorContext) {
    xmlSetStructuredErrorFunc(&error_, keep_first_error);
    refused_include.clear();
    next_loader = xmlGetExternalEntityLoader();
    xmlSetExternalEntityLoader(regular_files_only);
    doc_ = xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_BIG_LINES);
    if (!doc_)
      fail(path, "cannot parse it as XML, which an XDMF file is (" +
                     (error_.empty() ? "libxml2 cannot parse it" : error_) + ")");
    const xmlNodePtr root = xmlDocGetRootElement(doc_);
    if (!is_element(root, "Xdmf"))
      fail(path, "not an XDMF file: its root element is <" +
                     std::string(root ? reinterpret_cast<const char*>(root->name) : "") + ">, not <Xdmf>");
    if (include && xmlXIncludeProcessFlags(doc_, XML_PARSE_NONET) < 0)
      fail(path, "cannot resolve its xi:include: " +
                     (!refused_include.empty() ? refused_include
                      : error_.empty()         ? std::string("libxml2 says no more")
                                               : error_));
    restore();
  }
  ~XdmfDocument() {
    if (doc_) xmlFreeDoc(doc_);
    restore();
  }
  XdmfDocument(const XdmfDocument&) = delete;
  XdmfDocument& operator=(const XdmfDocument&) = delete;
  xmlDocPtr doc() const { return doc_; }
  xmlNodePtr root() const { return xmlDocGetRootElement(doc_); }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) {
    if (doc_) xmlFreeDoc(doc_);
    doc_ = nullptr;
    restore();
    throw DataError(path + ": " + what);
  }
  void restore() {
    xmlSetStructuredErrorFunc(handler_context_, handler_);
    if (next_loader) xmlSetExternalEntityLoader(next_loader);
  }
  xmlStructuredErrorFunc handler_;
  void* handler_context_;
  xmlDocPtr doc_ = nullptr;
  std::string error_;
};

// ---- The heavy data -------------------------------------------------------

// HDF5 prints its error stack unless told not to: the first (innermost)
// message is kept for the DataError instead.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

herr_t keep_innermost(unsigned, const H5E_error2_t* error, void* kept) {
  auto* text = static_cast<std::string*>(kept);
  if (text->empty() && error->desc) *text = error->desc;
  return 0;
}

std::string hdf5_error() {
  std::string text;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_innermost, &text);
  H5Eclear2(H5E_DEFAULT);
  return text.empty() ? "no reason given" : text;
}

// An HDF5 identifier, closed at the end of scope.
class Hdf5Id {
 public:
  Hdf5Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Hdf5Id() {
    if (id_ >= 0) close_(id_);
  }
  Hdf5Id(const Hdf5Id&) = delete;
  Hdf5Id& operator=(const Hdf5Id&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// Values row by row, with the shape they came in.
struct Values {
  std::vector<double> data;
  std::vector<std::uint64_t> dims;
};

// A HyperSlab's selection: start, stride and count per axis.
struct Selection {
  std::vector<std::uint64_t> start, stride, count;
};

constexpr std::uint64_t most_values = std::uint64_t(1) << 40;

std::uint64_t product(const std::vector<std::uint64_t>& dims) {
  std::uint64_t count = 1;
  for (std::uint64_t d : dims) count = (d != 0 && count > most_values / d) ? most_values + 1 : count * d;
  return count;
}

std::vector<double> allocated(std::uint64_t count, const std::string& where) {
  try {
    return std::vector<double>(std::size_t(count));
  } catch (const std::bad_alloc&) {
    throw DataError(where + ": " + std::to_string(count) + " values do not fit in memory");
  }
}

// What one read of the file needs: the .xdmf's path and document, and the
// HDF5 files opened so far (dolfin's steps share one).
struct Reading {
  std::string path;
  xmlDocPtr doc = nullptr;
  std::map<std::string, hid_t> hdf5_files;
  ~Reading() {
    for (const auto& [name, id] : hdf5_files) H5Fclose(id);
  }
  [[noreturn]] void fail(xmlNodePtr node, const std::string& what) const {
    throw DataError(path + ": " + at(node) + ": " + what);
  }
};

hid_t hdf5_file(Reading& reading, xmlNodePtr item, const std::string& file) {
  if (const auto open = reading.hdf5_files.find(file); open != reading.hdf5_files.end()) return open->second;
  if (const std::string why = unreadable_input(file); !why.empty())
    reading.fail(item, "its heavy data file " + file + " is missing (" + why +
                           "): an .xdmf needs the .h5 it names, in the place it names it (here relative to the .xdmf)");
  if (H5Fis_hdf5(file.c_str()) <= 0) reading.fail(item, "its heavy data file " + file + " is not an HDF5 file");
  const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) reading.fail(item, "HDF5 cannot open its heavy data file " + file + ": " + hdf5_error());
  reading.hdf5_files[file] = id;
  return id;
}

// The HDF5 dataset "file.h5:/group/data" names, whole or its `selection`;
// `declared` is the DataItem's Dimensions (none: the dataset's own).
Values hdf5_values(Reading& reading, xmlNodePtr item, const std::vector<std::uint64_t>& declared,
                   const Selection* selection) {
  const std::string text = trimmed(text_of(item));
  std::size_t colon = text.find(':', text.size() > 2 && text[1] == ':' ? 2 : 0);  // past a drive letter
  if (colon == std::string::npos || colon == 0 || colon + 1 >= text.size())
    reading.fail(item, "expected FILE:/DATASET for Format=\"HDF\", found \"" + text.substr(0, 80) + "\"");
  const std::string file = file_named_in(reading.path, text.substr(0, colon));
  const std::string name = text.substr(colon + 1);
  const std::string where = reading.path + ": " + at(item) + ": " + file + ":" + name;
  const hid_t id = hdf5_file(reading, item, file);
  if (H5Lexists(id, name.c_str(), H5P_DEFAULT) <= 0) throw DataError(where + ": no such dataset in the file");
  const Hdf5Id dataset(H5Dopen2(id, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!dataset.ok()) throw DataError(where + ": HDF5 cannot open it as a dataset: " + hdf5_error());
  const Hdf5Id space(H5Dget_space(dataset.get()), H5Sclose);
  const Hdf5Id type(H5Dget_type(dataset.get()), H5Tclose);
  const int rank = space.ok() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0 || rank > 32 || !type.ok()) throw DataError(where + ": HDF5 cannot read its shape: " + hdf5_error());
  std::vector<hsize_t> shape(std::size_t(rank), 0);
  H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  const std::vector<std::uint64_t> dims(shape.begin(), shape.end());
  const std::uint64_t stored = product(dims);
  const H5T_class_t kind = H5Tget_class(type.get());
  if (kind != H5T_INTEGER && kind != H5T_FLOAT) throw DataError(where + ": holds neither integers nor floats");
  // Every value is read as a double: HDF5 converts from the dataset's own
  // type. The XML's NumberType and Precision are not trusted for it
  // (dolfin omits Precision on float64 data, which XDMF says is 4 bytes).
  const std::uint64_t bytes = stored * H5Tget_size(type.get());
  const hsize_t storage = H5Dget_storage_size(dataset.get());
  if (stored > 0 && storage == 0) throw DataError(where + ": its values were never written (no storage)");
  // A compressed dataset may declare far more values than its bytes hold:
  // none packs more than about a thousand to one.
  if (stored > most_values || bytes / 2048 > storage)
    throw DataError(where + ": declares " + std::to_string(stored) + " values in " + std::to_string(storage) +
                    " stored bytes");
  std::vector<std::uint64_t> out_dims = dims;
  if (selection) {
    if (selection->start.size() != dims.size())
      reading.fail(item, "its HyperSlab selects " + std::to_string(selection->start.size()) + " axes of a dataset of " +
                             std::to_string(dims.size()));
    std::vector<hsize_t> start, stride, count;
    for (std::size_t a = 0; a < dims.size(); ++a) {
      const std::uint64_t s = selection->start[a], step = selection->stride[a], n = selection->count[a];
      if (step == 0 || n == 0 || s >= dims[a] || (n - 1) > (dims[a] - 1 - s) / step)
        reading.fail(item, "its HyperSlab reaches beyond axis " + std::to_string(a) + " of " + std::to_string(dims[a]));
      start.push_back(s), stride.push_back(step), count.push_back(n);
    }
    H5Sselect_hyperslab(space.get(), H5S_SELECT_SET, start.data(), stride.data(), count.data(), nullptr);
    out_dims = selection->count;
  } else if (!declared.empty() && product(declared) != stored) {
    std::string shape_text;
    for (std::uint64_t d : dims) shape_text += (shape_text.empty() ? "" : " × ") + std::to_string(d);
    reading.fail(item, "its Dimensions say " + std::to_string(product(declared)) + " values; the dataset " + name +
                           " holds " + std::to_string(stored) + " (" + shape_text + ")");
  }
  Values values{allocated(product(out_dims), where), declared.empty() || selection ? out_dims : declared};
  if (values.data.empty()) return values;
  const hsize_t memory_count = values.data.size();
  const Hdf5Id memory(H5Screate_simple(1, &memory_count, nullptr), H5Sclose);
  if (H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, memory.get(), space.get(), H5P_DEFAULT, values.data.data()) < 0)
    throw DataError(where + ": HDF5 cannot read it (a truncated or damaged file?): " + hdf5_error());
  return values;
}

std::vector<std::uint64_t> dimensions(const Reading& reading, xmlNodePtr node, const std::string& text) {
  std::vector<std::uint64_t> dims;
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) break;
    std::uint64_t d = 0;
    const auto [next, error] = std::from_chars(p, end, d);
    if (error != std::errc() || d > most_values) reading.fail(node, "Dimensions \"" + text + "\" are not counts");
    dims.push_back(d);
    p = next;
  }
  if (product(dims) > most_values) reading.fail(node, "Dimensions \"" + text + "\" declare too many values");
  return dims;
}

// The numbers written in an element, as many as `declared` says (any
// number when it says none).
Values xml_values(const Reading& reading, xmlNodePtr item, const std::vector<std::uint64_t>& declared) {
  const std::string text = text_of(item);
  Values values{{}, declared};
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    while (p < end && (std::isspace(static_cast<unsigned char>(*p)) || *p == '+')) ++p;
    if (p == end) break;
    double v = 0;
    const auto [next, error] = std::from_chars(p, end, v);
    if (error != std::errc())
      reading.fail(item, "value " + std::to_string(values.data.size() + 1) + " is not a number: \"" +
                             std::string(p, std::min<std::size_t>(std::size_t(end - p), 20)) + "\"");
    values.data.push_back(v);
    p = next;
  }
  if (declared.empty())
    values.dims = {values.data.size()};
  else if (values.data.size() != product(declared))
    reading.fail(item, "its Dimensions say " + std::to_string(product(declared)) + " values; it holds " +
                           std::to_string(values.data.size()));
  return values;
}

// `source`'s values that `selection` picks, row by row.
Values selected(const Reading& reading, xmlNodePtr item, const Values& source, const Selection& selection) {
  const std::size_t rank = source.dims.size();
  if (selection.start.size() != rank) reading.fail(item, "its HyperSlab does not match its source's axes");
  for (std::size_t a = 0; a < rank; ++a)
    if (selection.stride[a] == 0 || selection.count[a] == 0 || selection.start[a] >= source.dims[a] ||
        (selection.count[a] - 1) > (source.dims[a] - 1 - selection.start[a]) / selection.stride[a])
      reading.fail(item, "its HyperSlab reaches beyond its source's axis " + std::to_string(a));
  Values out{{}, selection.count};
  const std::uint64_t count = product(selection.count);
  out.data.reserve(std::size_t(count));
  std::vector<std::uint64_t> index(rank, 0);
  for (std::uint64_t n = 0; n < count; ++n) {
    std::uint64_t flat = 0;
    for (std::size_t a = 0; a < rank; ++a)
      flat = flat * source.dims[a] + selection.start[a] + index[a] * selection.stride[a];
    out.data.push_back(source.data[flat]);
    for (std::size_t a = rank; a-- > 0;) {
      if (++index[a] < selection.count[a]) break;
      index[a] = 0;
    }
  }
  return out;
}

// The element `node` stands for: itself, or the element of its name its
// XDMF 2 Reference points to, by the XPath in the attribute or in the
// element's text (Reference="XML"), followed up to 8 times.
xmlNodePtr resolved(const Reading& reading, xmlNodePtr node) {
  for (int depth = 0; depth <= 8; ++depth) {
    const std::string reference = attribute(node, "Reference");
    if (reference.empty()) return node;
    const std::string xpath = lower(reference) == "xml" ? trimmed(text_of(node)) : reference;
    xmlXPathContextPtr context = xmlXPathNewContext(reading.doc);
    xmlXPathObjectPtr found = context ? xmlXPathEvalExpression(BAD_CAST xpath.c_str(), context) : nullptr;
    xmlNodePtr target = nullptr;
    if (found && found->type == XPATH_NODESET && found->nodesetval && found->nodesetval->nodeNr > 0)
      target = found->nodesetval->nodeTab[0];
    xmlXPathFreeObject(found);
    xmlXPathFreeContext(context);
    const std::string name = reinterpret_cast<const char*>(node->name);
    if (!is_element(target, name.c_str()))
      reading.fail(node, "its Reference \"" + xpath + "\" names no <" + name + ">");
    node = target;
  }
  reading.fail(node, "its References go on for more than 8 steps");
}

// The values of a <DataItem>.
Values item_values(Reading& reading, xmlNodePtr item, int depth = 0) {
  if (depth > 8) reading.fail(item, "its HyperSlabs nest deeper than 8");
  item = resolved(reading, item);
  const std::vector<std::uint64_t> declared = dimensions(reading, item, attribute(item, "Dimensions"));
  const std::string item_type = lower(attribute(item, "ItemType"));
  if (item_type == "hyperslab") {
    const std::vector<xmlNodePtr> parts = children(item, "DataItem");
    if (parts.size() != 2) reading.fail(item, "a HyperSlab holds two <DataItem>s: the selection, then its source");
    const Values chosen = item_values(reading, parts[0], depth + 1);
    const std::size_t rank = chosen.data.size() / 3;
    if (rank == 0 || chosen.data.size() != 3 * rank) reading.fail(parts[0], "expected start, stride and count rows");
    Selection selection;
    for (std::size_t i = 0; i < 3 * rank; ++i) {
      const double v = chosen.data[i];
      if (!(v >= 0 && v <= double(most_values)) || v != std::floor(v))
        reading.fail(parts[0], "not a selection of counts");
      (i < rank ? selection.start : i < 2 * rank ? selection.stride : selection.count).push_back(std::uint64_t(v));
    }
    const xmlNodePtr source = resolved(reading, parts[1]);
    Values values = lower(attribute(source, "Format")) == "hdf" && lower(attribute(source, "ItemType")) != "hyperslab"
                        ? hdf5_values(reading, source, {}, &selection)
                        : selected(reading, item, item_values(reading, source, depth + 1), selection);
    if (!declared.empty() && product(declared) != values.data.size())
      reading.fail(item, "its Dimensions say " + std::to_string(product(declared)) + " values; it selects " +
                             std::to_string(values.data.size()));
    return values;
  }
  if (!item_type.empty() && item_type != "uniform")
    reading.fail(item, "ItemType=\"" + attribute(item, "ItemType") + "\" is not read (Uniform and HyperSlab are)");
  const std::string format = lower(attribute(item, "Format"));
  if (format == "hdf") return hdf5_values(reading, item, declared, nullptr);
  if (format.empty() || format == "xml") return xml_values(reading, item, declared);
  reading.fail(item, "Format=\"" + attribute(item, "Format") + "\" is not read (XML and HDF are)");
}

// The values of the one <DataItem> in `parent`.
Values only_item_values(Reading& reading, xmlNodePtr parent) {
  const std::vector<xmlNodePtr> items = children(parent, "DataItem");
  if (items.size() != 1) reading.fail(parent, "expected one <DataItem>, found " + std::to_string(items.size()));
  return item_values(reading, items.front());
}

double number_in(const Reading& reading, xmlNodePtr node, const std::string& text) {
  double value = 0;
  const std::string t = trimmed(text);
  const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (error != std::errc() || end != t.data() + t.size()) reading.fail(node, "\"" + t + "\" is not a number");
  return value;
}

// A value for a message: "1701", "1.5", "-3e+20".
std::string number_text(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::string("?");
}

// ---- Cells ----------------------------------------------------------------

struct CellKind {
  const char* name;  // XDMF's TopologyType, lower case
  int code;          // in a Mixed topology
  int nodes;
  int vtk_type;
  std::vector<int> flip;  // the node order of the mirrored cell; none: no volume to turn
};

const std::vector<CellKind>& cell_kinds() {
  static const std::vector<CellKind> kinds = {
      {"triangle", 4, 3, VTK_TRIANGLE, {}},
      {"quadrilateral", 5, 4, VTK_QUAD, {}},
      {"tetrahedron", 6, 4, VTK_TETRA, {0, 2, 1, 3}},
      {"pyramid", 7, 5, VTK_PYRAMID, {0, 3, 2, 1, 4}},
      {"wedge", 8, 6, VTK_WEDGE, {3, 4, 5, 0, 1, 2}},
      {"hexahedron", 9, 8, VTK_HEXAHEDRON, {4, 5, 6, 7, 0, 1, 2, 3}},
      {"triangle_6", 0x24, 6, VTK_QUADRATIC_TRIANGLE, {}},
      {"quadrilateral_8", 0x25, 8, VTK_QUADRATIC_QUAD, {}},
      {"tetrahedron_10", 0x26, 10, VTK_QUADRATIC_TETRA, {0, 2, 1, 3, 6, 5, 4, 7, 9, 8}},
      {"pyramid_13", 0x27, 13, VTK_QUADRATIC_PYRAMID, {}},
      {"wedge_15", 0x28, 15, VTK_QUADRATIC_WEDGE, {3, 4, 5, 0, 1, 2, 9, 10, 11, 6, 7, 8, 12, 13, 14}},
      {"hexahedron_20", 0x30, 20, VTK_QUADRATIC_HEXAHEDRON, {4,  5,  6, 7, 0,  1,  2,  3,  12, 13,
                                                             14, 15, 8, 9, 10, 11, 16, 17, 18, 19}},
  };
  return kinds;
}

// The determinant of VTK's parametric map at the cell's centre, from its
// corners: negative for a cell wound the other way.
double centre_jacobian(int vtk_type, const vtkIdType* ids, const std::vector<double>& xyz) {
  const auto p = [&](int i) {
    return Vec3(xyz[3 * std::size_t(ids[i])], xyz[3 * std::size_t(ids[i]) + 1], xyz[3 * std::size_t(ids[i]) + 2]);
  };
  Vec3 r, s, t;
  switch (vtk_type) {
    case VTK_TETRA:
    case VTK_QUADRATIC_TETRA:
      r = p(1) - p(0), s = p(2) - p(0), t = p(3) - p(0);
      break;
    case VTK_PYRAMID:
    case VTK_QUADRATIC_PYRAMID:
      r = p(1) - p(0) + p(2) - p(3), s = p(3) - p(0) + p(2) - p(1), t = 4.0 * p(4) - p(0) - p(1) - p(2) - p(3);
      break;
    case VTK_WEDGE:
    case VTK_QUADRATIC_WEDGE:
      r = p(1) - p(0) + p(4) - p(3), s = p(2) - p(0) + p(5) - p(3), t = p(3) + p(4) + p(5) - p(0) - p(1) - p(2);
      break;
    default:  // hexahedra
      r = p(1) - p(0) + p(2) - p(3) + p(5) - p(4) + p(6) - p(7);
      s = p(3) - p(0) + p(2) - p(1) + p(7) - p(4) + p(6) - p(5);
      t = p(4) - p(0) + p(5) - p(1) + p(6) - p(2) + p(7) - p(3);
  }
  return r.cross(s).dot(t);
}

// The cells of a <Topology>, on `xyz`'s points.
vtkSmartPointer<vtkUnstructuredGrid> cells_of(Reading& reading, xmlNodePtr topology, const std::vector<double>& xyz) {
  const std::string type = lower(attribute(topology, "TopologyType", "Type"));
  const CellKind* only = nullptr;
  for (const CellKind& kind : cell_kinds())
    if (type == kind.name) only = &kind;
  if (!only && type != "mixed") {
    const bool structured = type.find("mesh") != std::string::npos;
    reading.fail(topology, "TopologyType \"" + attribute(topology, "TopologyType", "Type") + "\" is not read" +
                               (structured ? " (a structured grid: save it as .vts or .vti from ParaView)"
                                           : " (unstructured grids of triangles, quadrilaterals, tetrahedra, "
                                             "pyramids, wedges, hexahedra, their quadratic forms, or Mixed are)"));
  }
  if (only && !attribute(topology, "NodesPerElement").empty() &&
      attribute(topology, "NodesPerElement") != std::to_string(only->nodes))
    reading.fail(topology, "NodesPerElement=\"" + attribute(topology, "NodesPerElement") + "\" for a " + type + " of " +
                               std::to_string(only->nodes));
  const std::vector<std::uint64_t> declared_elements =
      dimensions(reading, topology, attribute(topology, "NumberOfElements", "Dimensions"));
  // XDMF 2's BaseOffset: the number of the first point (1 for Fortran's).
  const std::string offset = attribute(topology, "BaseOffset");
  const double base = offset.empty() ? 0.0 : number_in(reading, topology, offset);
  const Values values = only_item_values(reading, topology);
  const std::vector<double>& v = values.data;
  const std::size_t points = xyz.size() / 3;

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  std::vector<unsigned char> types;
  std::vector<vtkIdType> ids, turned;
  std::size_t at_value = 0;
  while (at_value < v.size()) {
    const CellKind* kind = only;
    if (!kind) {
      for (const CellKind& k : cell_kinds())
        if (double(k.code) == v[at_value]) kind = &k;
      if (!kind)
        reading.fail(topology, "cell " + std::to_string(types.size()) + " of the Mixed topology has type code " +
                                   number_text(v[at_value]) + ", not one of a cell read here");
      ++at_value;
    }
    if (std::size_t(kind->nodes) > v.size() - at_value)
      reading.fail(topology, "its connectivity ends inside cell " + std::to_string(types.size()));
    ids.assign(std::size_t(kind->nodes), 0);
    for (std::size_t n = 0; n < ids.size(); ++n) {
      const double id = v[at_value++] - base;
      if (!(id >= 0 && id < double(points)) || id != std::floor(id))
        reading.fail(topology, "cell " + std::to_string(types.size()) + " names point " + number_text(id + base) +
                                   (base != 0 ? " (BaseOffset " + offset + ")" : std::string()) +
                                   "; the Geometry has " + std::to_string(points) + " points");
      ids[n] = vtkIdType(id);
    }
    if (!kind->flip.empty() && centre_jacobian(kind->vtk_type, ids.data(), xyz) < 0) {
      turned.resize(ids.size());
      for (std::size_t n = 0; n < ids.size(); ++n) turned[n] = ids[std::size_t(kind->flip[n])];
      ids.swap(turned);
    }
    cells->InsertNextCell(vtkIdType(ids.size()), ids.data());
    types.push_back(static_cast<unsigned char>(kind->vtk_type));
  }
  if (!declared_elements.empty() && declared_elements.front() != types.size())
    reading.fail(topology, "it declares " + std::to_string(declared_elements.front()) + " elements; its " +
                               std::to_string(v.size()) + " values make " + std::to_string(types.size()));
  std::vector<int> as_int(types.begin(), types.end());
  grid->SetCells(as_int.data(), cells);
  return grid;
}

// ---- Grids ----------------------------------------------------------------

// The points of a <Geometry>, x y z after each other.
std::vector<double> points_of(Reading& reading, xmlNodePtr geometry) {
  const std::string type = lower(attribute(geometry, "GeometryType", "Type"));
  std::vector<double> xyz;
  if (type.empty() || type == "xyz" || type == "xy") {
    const std::size_t given = type == "xy" ? 2 : 3;
    const Values values = only_item_values(reading, geometry);
    if (values.data.size() % given != 0)
      reading.fail(geometry,
                   std::to_string(values.data.size()) + " coordinates are not points of " + std::to_string(given));
    for (std::size_t i = 0; i < values.data.size(); i += given)
      xyz.insert(xyz.end(), {values.data[i], values.data[i + 1], given == 3 ? values.data[i + 2] : 0.0});
  } else if (type == "x_y_z" || type == "x_y") {
    const std::vector<xmlNodePtr> items = children(geometry, "DataItem");
    if (items.size() != (type == "x_y_z" ? 3u : 2u)) reading.fail(geometry, "expected a <DataItem> per axis");
    std::vector<Values> axes;
    for (xmlNodePtr item : items) axes.push_back(item_values(reading, item));
    for (const Values& axis : axes)
      if (axis.data.size() != axes.front().data.size()) reading.fail(geometry, "its axes have different counts");
    for (std::size_t i = 0; i < axes.front().data.size(); ++i)
      xyz.insert(xyz.end(), {axes[0].data[i], axes[1].data[i], axes.size() > 2 ? axes[2].data[i] : 0.0});
  } else {
    reading.fail(geometry, "GeometryType \"" + attribute(geometry, "GeometryType", "Type") +
                               "\" is not read (XYZ, XY, X_Y_Z and X_Y are)");
  }
  for (std::size_t i = 0; i < xyz.size(); ++i)
    if (!std::isfinite(xyz[i])) reading.fail(geometry, "point " + std::to_string(i / 3) + " is not finite");
  return xyz;
}

// An <Attribute>'s values as a point or cell array, named as the file
// names it; Tensor6's added to `tensor6`. One neither at nodes nor at
// cells (Grid, Face, Edge, a finite element function's) is left out.
void add_attribute(Reading& reading, xmlNodePtr node, vtkUnstructuredGrid* grid, std::set<std::string>& tensor6) {
  const std::string center = lower(attribute(node, "Center"));
  const bool at_points = center.empty() || center == "node";
  if ((!at_points && center != "cell") || lower(attribute(node, "ItemType")) == "finiteelementfunction") return;
  const std::string name = attribute(node, "Name");
  if (name.empty()) reading.fail(node, "an <Attribute> without a Name");
  vtkDataSetAttributes* into = at_points ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                                         : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
  if (into->HasArray(name.c_str())) reading.fail(node, "a second attribute named \"" + name + "\"");
  const std::string type = lower(attribute(node, "AttributeType", "Type"));
  const vtkIdType tuples = at_points ? grid->GetNumberOfPoints() : grid->GetNumberOfCells();
  const Values values = only_item_values(reading, node);
  const std::size_t count = values.data.size();
  if (tuples == 0 || count == 0 || count % std::size_t(tuples) != 0)
    reading.fail(node, std::to_string(count) + " values for " + std::to_string(tuples) +
                           (at_points ? " points" : " cells") + ": not a whole number each");
  const std::size_t components = count / std::size_t(tuples);
  const std::map<std::string, std::vector<std::size_t>> expected = {
      {"", {1}}, {"scalar", {1}}, {"vector", {2, 3}}, {"tensor", {9}}, {"tensor6", {6}}};
  if (const auto e = expected.find(type);
      e != expected.end() && std::find(e->second.begin(), e->second.end(), components) == e->second.end())
    reading.fail(node, "a " + (type.empty() ? std::string("scalar") : type) + " attribute with " +
                           std::to_string(components) + " values " + (at_points ? "per point" : "per cell"));
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(int(components));
  array->SetNumberOfTuples(tuples);
  double* out = array->GetPointer(0);
  if (type == "tensor6") {
    // XX XY XZ YY YZ ZZ, the upper triangle row by row, into VTK's XX YY ZZ XY YZ XZ.
    constexpr std::size_t from[6] = {0, 3, 5, 1, 4, 2};
    for (std::size_t t = 0; t < std::size_t(tuples); ++t)
      for (std::size_t c = 0; c < 6; ++c) out[6 * t + c] = values.data[6 * t + from[c]];
    tensor6.insert(name);
  } else {
    std::copy(values.data.begin(), values.data.end(), out);
  }
  into->AddArray(array);
  if ((type == "tensor" || type == "tensor6") && !into->GetTensors()) into->SetActiveTensors(name.c_str());
  if (type == "vector" && !into->GetVectors()) into->SetActiveVectors(name.c_str());
}

// A uniform <Grid>: its points, cells and attributes.
vtkSmartPointer<vtkUnstructuredGrid> uniform_grid(Reading& reading, xmlNodePtr node, std::set<std::string>& tensor6) {
  const std::vector<xmlNodePtr> topology = children(node, "Topology"), geometry = children(node, "Geometry");
  if (topology.size() != 1 || geometry.size() != 1)
    reading.fail(node, "a uniform grid needs one <Topology> and one <Geometry>; it has " +
                           std::to_string(topology.size()) + " and " + std::to_string(geometry.size()));
  const std::vector<double> xyz = points_of(reading, resolved(reading, geometry.front()));
  vtkSmartPointer<vtkUnstructuredGrid> grid = cells_of(reading, resolved(reading, topology.front()), xyz);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(xyz.size() / 3));
  std::copy(xyz.begin(), xyz.end(), static_cast<double*>(points->GetVoidPointer(0)));
  grid->SetPoints(points);
  for (xmlNodePtr attribute_node : children(node, "Attribute"))
    add_attribute(reading, resolved(reading, attribute_node), grid, tensor6);
  return grid;
}

// What names a uniform grid's mesh: its Topology's and Geometry's data
// (where they are, or their inline numbers) and shapes. Grids of one key
// are one mesh: dolfinx writes the mesh once as a grid of its own and each
// function as a temporal collection of grids that include it.
std::string mesh_key(const Reading& reading, xmlNodePtr grid) {
  std::string key;
  for (const char* part : {"Topology", "Geometry"})
    for (xmlNodePtr node : children(grid, part)) {
      const xmlNodePtr whole = resolved(reading, node);
      key += std::string(part) + ":" + attribute(whole, "TopologyType") + attribute(whole, "GeometryType") + ";";
      for (xmlNodePtr item : children(whole, "DataItem")) {
        const xmlNodePtr data = resolved(reading, item);
        key += attribute(data, "Dimensions") + "@" + trimmed(text_of(data)) + ";";
      }
    }
  return key;
}

// The uniform grids of one step as data sets: those of one mesh (mesh_key)
// made one, with all their attributes, the mesh read once.
std::vector<std::pair<std::string, vtkSmartPointer<vtkUnstructuredGrid>>> grids_of_step(
    Reading& reading, const std::vector<xmlNodePtr>& leaves, std::set<std::string>& tensor6) {
  std::vector<std::pair<std::string, vtkSmartPointer<vtkUnstructuredGrid>>> grids;
  std::map<std::string, std::size_t> by_mesh;
  std::vector<bool> named_by_data;  // a grid is named after the first that brings data, not a bare mesh
  for (xmlNodePtr leaf : leaves) {
    const bool data = !children(leaf, "Attribute").empty();
    const auto [at, first] = by_mesh.emplace(mesh_key(reading, leaf), grids.size());
    if (first) {
      grids.emplace_back(attribute(leaf, "Name"), uniform_grid(reading, leaf, tensor6));
      named_by_data.push_back(data);
      continue;
    }
    auto& [name, grid] = grids[at->second];
    for (xmlNodePtr attribute_node : children(leaf, "Attribute"))
      add_attribute(reading, resolved(reading, attribute_node), grid, tensor6);
    if (data && !named_by_data[at->second]) name = attribute(leaf, "Name"), named_by_data[at->second] = true;
  }
  return grids;
}

enum class GridKind { uniform, temporal, spatial };

GridKind kind_of(const Reading& reading, xmlNodePtr grid) {
  const std::string type = lower(attribute(grid, "GridType"));
  if (type.empty() || type == "uniform") return GridKind::uniform;
  if (type == "tree") return GridKind::spatial;
  if (type == "collection")
    return lower(attribute(grid, "CollectionType")) == "temporal" ? GridKind::temporal : GridKind::spatial;
  reading.fail(grid, "GridType=\"" + attribute(grid, "GridType") + "\" is not read (Uniform and Collection are)");
}

// The time steps under `grids` (read as one spatial set): 0 for none.
std::size_t step_count(const Reading& reading, const std::vector<xmlNodePtr>& grids) {
  std::size_t steps = 0;
  for (xmlNodePtr grid : grids) {
    const GridKind kind = kind_of(reading, grid);
    const std::size_t these = kind == GridKind::temporal  ? children(grid, "Grid").size()
                              : kind == GridKind::spatial ? step_count(reading, children(grid, "Grid"))
                                                          : 0;
    if (these != 0 && steps != 0 && these != steps)
      reading.fail(grid,
                   "its " + std::to_string(these) + " time steps differ from its neighbours' " + std::to_string(steps));
    if (these != 0) steps = these;
  }
  return steps;
}

// The uniform grids of step `step` under `grids`.
void grids_at(const Reading& reading, const std::vector<xmlNodePtr>& grids, std::size_t step, bool in_time,
              std::vector<xmlNodePtr>& leaves) {
  for (xmlNodePtr grid : grids) {
    const GridKind kind = kind_of(reading, grid);
    if (kind == GridKind::uniform) {
      leaves.push_back(grid);
    } else if (kind == GridKind::spatial) {
      grids_at(reading, children(grid, "Grid"), step, in_time, leaves);
    } else {
      if (in_time) reading.fail(grid, "a temporal collection inside a temporal collection");
      const std::vector<xmlNodePtr> steps = children(grid, "Grid");
      if (step < steps.size()) grids_at(reading, {steps[step]}, step, true, leaves);
    }
  }
}

// The first temporal collection under `grids`, depth first.
xmlNodePtr first_temporal(const Reading& reading, const std::vector<xmlNodePtr>& grids) {
  for (xmlNodePtr grid : grids) {
    const GridKind kind = kind_of(reading, grid);
    if (kind == GridKind::temporal) return grid;
    if (kind == GridKind::spatial)
      if (xmlNodePtr found = first_temporal(reading, children(grid, "Grid"))) return found;
  }
  return nullptr;
}

// A temporal collection's times: each grid's <Time Value>, else the
// collection's <Time TimeType="List"> (or HyperSlab: start, stride),
// else the step's index.
std::vector<double> times_of(Reading& reading, xmlNodePtr collection) {
  std::vector<double> listed;
  for (xmlNodePtr time : children(collection, "Time")) {
    const std::string type = lower(attribute(time, "TimeType", "Type"));
    if (type == "list" || type == "hyperslab") listed = only_item_values(reading, time).data;
    if (type == "hyperslab" && listed.size() >= 2) {
      const double start = listed[0], stride = listed[1];
      listed.clear();
      for (std::size_t i = 0; i < children(collection, "Grid").size(); ++i)
        listed.push_back(start + double(i) * stride);
    }
  }
  std::vector<double> times;
  for (xmlNodePtr grid : children(collection, "Grid")) {
    const std::vector<xmlNodePtr> own = children(grid, "Time");
    const std::size_t i = times.size();
    if (!own.empty() && !attribute(own.front(), "Value").empty())
      times.push_back(number_in(reading, own.front(), attribute(own.front(), "Value")));
    else
      times.push_back(i < listed.size() ? listed[i] : double(i));
  }
  return times;
}

// The grids the file's first <Domain> holds.
std::vector<xmlNodePtr> domain_grids(const Reading& reading, const XdmfDocument& document) {
  for (xmlNodePtr domain : children(document.root(), "Domain"))
    if (std::vector<xmlNodePtr> grids = children(domain, "Grid"); !grids.empty()) return grids;
  throw DataError(reading.path + ": an XDMF file without a <Domain> that holds a <Grid>");
}

vtkSmartPointer<vtkDataSet> read_xdmf(const std::string& path, const ReadRequest& request, const VtkSession& vtk) {
  const QuietHdf5 quiet;
  const XdmfDocument document(path, true);
  Reading reading{path, document.doc(), {}};
  const std::vector<xmlNodePtr> top = domain_grids(reading, document);
  const std::size_t steps = step_count(reading, top);
  if (request.step > 0 && std::size_t(request.step) >= std::max<std::size_t>(steps, 1))
    throw DataError(path + ": data.step " + std::to_string(request.step) + " is beyond its " +
                    (steps > 0 ? std::to_string(steps) + " time steps (0 to " + std::to_string(steps - 1) + ")"
                               : std::string("grids, which have no time steps")));
  std::vector<xmlNodePtr> leaves;
  grids_at(reading, top, std::size_t(std::max(request.step, 0)), false, leaves);
  if (leaves.empty())
    throw DataError(path + ": no uniform <Grid> at step " + std::to_string(std::max(request.step, 0)));

  std::set<std::string> tensor6;
  const auto grids = grids_of_step(reading, leaves, tensor6);
  vtkSmartPointer<vtkDataObject> read;
  if (grids.size() == 1) {
    read = grids.front().second;
  } else {
    auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    for (std::size_t i = 0; i < grids.size(); ++i) {
      blocks->SetBlock(unsigned(i), grids[i].second);
      const std::string& name = grids[i].first;
      blocks->GetMetaData(unsigned(i))
          ->Set(vtkCompositeDataSet::NAME(), (name.empty() ? "grid " + std::to_string(i) : name).c_str());
    }
    read = blocks;
  }
  vtkSmartPointer<vtkDataSet> data = merged(read, path, request.block);
  if (const std::string error = vtk.first_error(); !error.empty())
    throw DataError(path + ": cannot merge its grids: " + error);
  for (const std::string& name : tensor6)
    if (data->GetPointData()->HasArray(name.c_str()) || data->GetCellData()->HasArray(name.c_str()))
      record_component_order(data->GetFieldData(), name, "XDMF's Tensor6: XX XY XZ YY YZ ZZ");
  return data;
}

std::vector<double> xdmf_times(const std::string& path) {
  const QuietHdf5 quiet;
  const XdmfDocument document(path, true);
  Reading reading{path, document.doc(), {}};
  const std::vector<xmlNodePtr> top = domain_grids(reading, document);
  xmlNodePtr collection = first_temporal(reading, top);
  if (!collection || step_count(reading, top) < 2) return {};
  return times_of(reading, collection);
}

// The files an .xdmf reads besides itself: those it includes, and its
// HDF5 files; none when it cannot be parsed (reading it says why).
std::vector<std::string> xdmf_parts(const std::string& path) {
  std::vector<std::string> files;
  const auto add = [&](const std::string& name) {
    const std::string file = file_named_in(path, name);
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  const auto walk = [&](xmlNodePtr node, auto&& self) -> void {
    for (; node; node = node->next) {
      if (node->type != XML_ELEMENT_NODE) continue;
      if (is_element(node, "include") && !attribute(node, "href").empty()) add(attribute(node, "href"));
      if (is_element(node, "DataItem") && lower(attribute(node, "Format")) == "hdf") {
        const std::string text = trimmed(text_of(node));
        if (const std::size_t colon = text.find(':', text.size() > 2 && text[1] == ':' ? 2 : 0);
            colon != std::string::npos && colon > 0)
          add(text.substr(0, colon));
      }
      self(node->children, self);
    }
  };
  try {
    walk(XdmfDocument(path, false).root(), walk);
    walk(XdmfDocument(path, true).root(), walk);
  } catch (const DataError&) {
  }
  return files;
}

}  // namespace

const FormatReader xdmf_reader{read_xdmf, nullptr, xdmf_parts, xdmf_times, true, true};

}  // namespace hsb

#include "field/reading/data_formats.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "base/input_file.h"
#include "field/reading/format_reader.h"

namespace hsb {
namespace {

const char* const convert = "convert it to .vtu (meshio convert FILE out.vtu, or ParaView's Save Data)";

// The type attribute of a VTK XML file's root element, if it has one.
std::string vtk_xml_type(const std::string& head) {
  const std::size_t root = head.find("<VTKFile");
  if (root == std::string::npos) return "";
  const std::size_t type = head.find("type=", root);
  if (type == std::string::npos || type + 6 >= head.size()) return "";
  const char quote = head[type + 5];
  const std::size_t end = head.find(quote, type + 6);
  return end == std::string::npos ? "" : head.substr(type + 6, end - type - 6);
}

bool starts(const std::string& head, const char* magic) { return head.rfind(magic, 0) == 0; }

// The content probes, one a signature.
template <const char* Type>
bool vtk_xml(const std::string& head) { return vtk_xml_type(head) == Type; }
constexpr char image_data[] = "ImageData", unstructured_grid[] = "UnstructuredGrid",
               structured_grid[] = "StructuredGrid", rectilinear_grid[] = "RectilinearGrid",
               p_image_data[] = "PImageData", p_unstructured_grid[] = "PUnstructuredGrid",
               p_structured_grid[] = "PStructuredGrid", p_rectilinear_grid[] = "PRectilinearGrid",
               multiblock[] = "vtkMultiBlockDataSet", collection[] = "Collection", poly_data[] = "PolyData";
bool legacy_vtk(const std::string& head) { return starts(head, "# vtk DataFile Version"); }
bool nrrd(const std::string& head) { return starts(head, "NRRD000"); }
// NIfTI-1 and -2 say so at a fixed place (bytes 344 and 4 of the header).
bool nifti(const std::string& head) {
  return (head.size() >= 348 && (head.compare(344, 4, std::string("n+1\0", 4)) == 0 ||
                                 head.compare(344, 4, std::string("ni1\0", 4)) == 0)) ||
         (head.size() >= 8 && (head.compare(4, 4, std::string("n+2\0", 4)) == 0 ||
                               head.compare(4, 4, std::string("ni2\0", 4)) == 0));
}
bool mrtrix(const std::string& head) { return starts(head, "mrtrix image"); }
// Classic netCDF: the container of Exodus II files.
bool netcdf(const std::string& head) { return starts(head, "CDF\x01") || starts(head, "CDF\x02"); }
bool gmsh(const std::string& head) { return starts(head, "$MeshFormat"); }
// CalculiX's results begin with the model header record, "    1C".
bool calculix(const std::string& head) { return starts(head, "    1C"); }
bool abaqus_input(const std::string& head) { return starts(head, "*Heading"); }
bool xdmf(const std::string& head) { return starts(head, "Xdmf") || head.find("<Xdmf") != std::string::npos; }
bool hdf5(const std::string& head) { return starts(head, "\x89HDF\r\n\x1a\n"); }

std::vector<DataFormat> build_formats() {
  return {
      {"legacy VTK", {".vtk"}, legacy_vtk, &legacy_vtk_reader},
      {"VTK XML image data", {".vti"}, vtk_xml<image_data>, &vtk_xml_reader},
      {"VTK XML unstructured grid", {".vtu"}, vtk_xml<unstructured_grid>, &vtk_xml_reader},
      {"VTK XML structured grid", {".vts"}, vtk_xml<structured_grid>, &vtk_xml_reader},
      {"VTK XML rectilinear grid", {".vtr"}, vtk_xml<rectilinear_grid>, &vtk_xml_reader},
      {"parallel VTK XML unstructured grid", {".pvtu"}, vtk_xml<p_unstructured_grid>, &vtk_pieces_reader},
      {"parallel VTK XML image data", {".pvti"}, vtk_xml<p_image_data>, &vtk_xml_reader},
      {"parallel VTK XML structured grid", {".pvts"}, vtk_xml<p_structured_grid>, &vtk_xml_reader},
      {"parallel VTK XML rectilinear grid", {".pvtr"}, vtk_xml<p_rectilinear_grid>, &vtk_xml_reader},
      {"VTK XML multiblock data set", {".vtm", ".vtmb"}, vtk_xml<multiblock>, &vtk_multiblock_reader},
      {"ParaView time series", {".pvd"}, vtk_xml<collection>, &vtk_series_reader},
      {"VTK XML polygonal data", {".vtp"}, vtk_xml<poly_data>, &vtk_xml_reader},
      {"VTK HDF", {".vtkhdf", ".hdf"}, nullptr, &vtk_hdf_reader, "", "HDF5"},
      {"NRRD", {".nrrd", ".nhdr"}, nrrd, &nrrd_reader},
      {"NIfTI", {".nii", ".nii.gz", ".hdr"}, nifti, &nifti_reader},
      {"MRtrix image", {".mif", ".mif.gz", ".mih"}, mrtrix, &mif_reader},
      {"CalculiX results", {".frd"}, calculix, &frd_reader},
      {"Exodus II", {".e", ".exo", ".ex2", ".exii"}, netcdf, &exodus_reader, "", "HDF5"},
      {"Gmsh mesh", {".msh"}, gmsh, &gmsh_reader},
      {"XDMF", {".xdmf", ".xmf"}, xdmf, &xdmf_reader},
      // MED (Code_Aster, SALOME) is HDF5 inside: its signature is HDF5's.
      {"MED (Code_Aster, Salome)", {".med", ".rmed"}, nullptr, &med_reader, "", "HDF5"},
      // Known, not read yet: said as what they are.
      {"Abaqus input", {".inp"}, abaqus_input, nullptr, convert},
      {"Abaqus output database", {".odb"}, nullptr, nullptr, "export the field output to .vtu (Abaqus/CAE or a VTK exporter)"},
      // An .h5 beside an .xdmf holds its arrays: the .xdmf says what they are.
      {"HDF5", {".h5", ".hdf5"}, hdf5, nullptr,
       "if it holds an XDMF file's arrays (FEniCS, meshio), give the .xdmf or .xmf beside it, which says what they "
       "are; otherwise convert it to .vtu (meshio convert FILE out.vtu, or ParaView's Save Data)"},
      {"Gmsh or OpenFOAM results", {".pos", ".foam"}, nullptr, nullptr, convert},
  };
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

const std::vector<DataFormat>& data_formats() {
  static const std::vector<DataFormat> formats = build_formats();
  return formats;
}

const DataFormat* format_by_extension(const std::string& path) {
  const std::string name = lower(path);
  const DataFormat* best = nullptr;
  std::size_t longest = 0;
  for (const DataFormat& f : data_formats())
    for (const std::string& ext : f.extensions)
      if (ext.size() > longest && ends_with(name, ext)) best = &f, longest = ext.size();
  return best;
}

const DataFormat* format_by_content(const std::string& path) {
  const std::string head = file_head(path, 1024);
  if (head.empty()) return nullptr;
  for (const DataFormat& f : data_formats())
    if (f.probe && f.probe(head)) return &f;
  return nullptr;
}

std::string file_stem(const std::string& path) {
  const std::string name = std::filesystem::path(path).filename().string();
  if (const DataFormat* format = format_by_extension(path)) {
    std::size_t longest = 0;
    for (const std::string& e : format->extensions)
      if (ends_with(lower(name), e)) longest = std::max(longest, e.size());
    if (longest > 0 && longest < name.size()) return name.substr(0, name.size() - longest);
  }
  return std::filesystem::path(path).stem().string();
}

bool is_readable_data_file(const std::string& path) {
  const DataFormat* f = format_by_extension(path);
  return f && f->readable();
}

bool is_known_data_file(const std::string& path) {
  if (format_by_extension(path)) return true;
  const std::string ext = lower(path);
  if (ends_with(ext, ".toml")) return false;
  return format_by_content(path) != nullptr;
}

std::string readable_formats_text() {
  std::string text;
  for (const DataFormat& f : data_formats()) {
    if (!f.readable()) continue;
    text += (text.empty() ? "" : ", ") + f.name + " (";
    for (std::size_t i = 0; i < f.extensions.size(); ++i) text += (i ? " " : "") + f.extensions[i];
    text += ")";
  }
  return text;
}

std::string readable_extensions_text() {
  std::string text;
  for (const DataFormat& f : data_formats())
    if (f.readable())
      for (const std::string& ext : f.extensions) text += (text.empty() ? "" : " ") + ext;
  return text;
}

std::string unknown_file_message(const std::string& path, const std::string& toml_error) {
  const std::string head = file_head(path, 64);
  // Text: printable ASCII, UTF-8's bytes and white space, no NUL.
  const bool text = !head.empty() && std::all_of(head.begin(), head.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u >= 0x20 || c == '\n' || c == '\r' || c == '\t';
  });
  std::string seen;
  if (head.empty()) {
    seen = "it is empty";
  } else if (text) {
    std::string line = head.substr(0, head.find_first_of("\r\n"));
    if (line.size() > 40) line = line.substr(0, 40) + "...";
    seen = "it is text beginning \"" + line + "\"";
  } else {
    static const char* const hex = "0123456789abcdef";
    seen = "it is binary, beginning";
    for (std::size_t i = 0; i < std::min<std::size_t>(head.size(), 8); ++i) {
      const auto u = static_cast<unsigned char>(head[i]);
      seen += std::string(" ") + hex[u >> 4] + hex[u & 15];
    }
  }
  return path + ": neither a scene nor a data file hsb knows: " + seen +
         "; not TOML (" + toml_error + "), and no data format has its extension or first bytes. hsb reads "
         "scenes (.toml) and " + readable_formats_text();
}

std::string unreadable_format_message(const std::string& path) {
  const DataFormat* by_name = format_by_extension(path);
  const DataFormat* by_content = format_by_content(path);
  // Content in the container a format's files come in is not another format.
  if (by_name && by_content && by_name->container == by_content->name) by_content = nullptr;
  // The content decides where it says anything; a readable name whose
  // content says nothing is left to the reader's own checks.
  const DataFormat* format = by_content ? by_content : by_name;
  if (format && format->readable() && by_name && by_name->reader == format->reader) return "";
  std::string text = path + ": ";
  if (format) {
    text += "a file in the " + format->name + " format (by its " +
            std::string(by_name == format && by_content == format ? "name and content"
                        : by_content == format                     ? "content"
                                                                   : "name") +
            ")";
    if (format->readable()) {
      text += ", but named as something else: give it its format's extension (" + format->extensions.front() + ")";
    } else {
      std::string advice = format->advice;
      if (const std::size_t at = advice.find("FILE"); at != std::string::npos) advice.replace(at, 4, path);
      text += ", which hsb does not read: " + advice;
    }
  } else {
    text += "not a data file hsb knows by its name or its first bytes";
  }
  return text + ". hsb reads " + readable_formats_text();
}

}  // namespace hsb

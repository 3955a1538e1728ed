// VTK's own formats, read by VTK's readers: legacy files, serial XML data
// sets, parallel pieces, multiblock files, ParaView's time series and VTK's
// HDF5 format (VTKHDF 1.0, vtkHDFReader). The FormatReaders of the
// registry (field/reading/format_reader.h).

#include <vtkDataSetReader.h>
#include <vtkHDFReader.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <new>

#include "base/input_file.h"
#include "base/partial_file.h"
#include "field/reading/block_merging.h"
#include "field/reading/data_error.h"
#include "field/reading/format_reader.h"

namespace hsb {
namespace {

// A file of random bytes, or of another format, gets a clear message
// before VTK's readers see it.
void check_legacy_header(const std::string& path) {
  if (file_head(path, 256).rfind("# vtk DataFile Version", 0) != 0)
    throw DataError(path + ": not a legacy VTK file: its first line is not \"# vtk DataFile Version x.y\"");
}

void check_xml_header(const std::string& path) {
  const std::string head = file_head(path, 256);
  std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // a UTF-8 byte-order mark
  start = head.find_first_not_of(" \t\r\n", start);
  if (start == std::string::npos || (head.compare(start, 5, "<?xml") != 0 && head.compare(start, 8, "<VTKFile") != 0))
    throw DataError(path + ": not a VTK XML file: it does not start with \"<?xml\" or \"<VTKFile\"");
}

// A legacy file written with the type names of VTK's 5.1 format that
// VTK 9.1's reader does not know (meshio, and so SfePy, write
// "vtktypeint32" for an int array) copied with the older names of the same
// types, to `copy`; false when the file has none. Only whole words that
// end a header line are renamed, and only in files of version 5, the only
// ones that have them: no other file is read twice.
bool with_known_type_names(const std::string& path, const std::string& copy) {
  static const std::pair<const char*, const char*> names[] = {
      {" vtktypeint8\n", " signed_char\n"}, {" vtktypeuint8\n", " unsigned_char\n"},
      {" vtktypeint16\n", " short\n"},      {" vtktypeuint16\n", " unsigned_short\n"},
      {" vtktypeint32\n", " int\n"},        {" vtktypeuint32\n", " unsigned_int\n"},
      {" vtktypefloat32\n", " float\n"},    {" vtktypefloat64\n", " double\n"}};
  std::ifstream in(path, std::ios::binary);
  std::string version;
  std::getline(in, version);
  if (version.rfind("# vtk DataFile Version 5", 0) != 0) return false;
  in.seekg(0);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.find(" vtktype") == std::string::npos) return false;
  bool renamed = false;
  for (const auto& [from, to] : names)
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + std::strlen(to))) {
      text.replace(at, std::strlen(from), to);
      renamed = true;
    }
  if (renamed) std::ofstream(copy, std::ios::binary) << text;
  return renamed;
}

// What `reader` made of `path`, run; a reader's warning is a file it could
// not read as declared (a truncated array reads as garbage, with only a
// warning): an error here. `whole` makes the output one data set.
vtkSmartPointer<vtkDataSet> output_of(vtkAlgorithm* reader, const std::string& path, const VtkSession& vtk,
                                      const std::function<vtkSmartPointer<vtkDataSet>(vtkDataObject*)>& whole) {
  const std::string as = "a VTK data set";
  update_reader(reader, vtk, path, as, true);
  vtkSmartPointer<vtkDataSet> data;
  try {
    data = whole(reader->GetOutputDataObject(0));
  } catch (const std::bad_alloc&) {
    refuse_memory(path, as);
  }
  vtk.refuse_complaints(path, as, true);
  if (!data || data->GetNumberOfPoints() == 0)
    throw DataError(path + ": cannot read it as " + as + ": no points in it");
  return data;
}

vtkSmartPointer<vtkDataSet> as_data_set(vtkDataObject* read) { return vtkDataSet::SafeDownCast(read); }

vtkSmartPointer<vtkDataSet> read_legacy(const std::string& path, const ReadRequest&, const VtkSession& vtk) {
  check_legacy_header(path);
  const ScratchFile renamed("types", ".vtk");
  auto reader = vtkSmartPointer<vtkDataSetReader>::New();
  reader->SetFileName(with_known_type_names(path, renamed.path()) ? renamed.path().c_str() : path.c_str());
  reader->ReadAllTensorsOn();
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllFieldsOn();
  return output_of(reader, path, vtk, as_data_set);
}

vtkSmartPointer<vtkXMLGenericDataObjectReader> xml_reader(const std::string& path) {
  check_xml_header(path);
  auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

vtkSmartPointer<vtkDataSet> read_xml(const std::string& path, const ReadRequest&, const VtkSession& vtk) {
  return output_of(xml_reader(path), path, vtk, as_data_set);
}

vtkSmartPointer<vtkDataSet> read_xml_parts(const std::string& path, const ReadRequest& request, const VtkSession& vtk) {
  return output_of(xml_reader(path), path, vtk, [&](vtkDataObject* read) { return merged(read, path, request.block); });
}

// VTKHDF is HDF5 inside, with a /VTKHDF group that says its type: a file
// of another kind gets a clear message before VTK's reader sees it (it
// reports a missing group as an error of HDF5's own).
vtkSmartPointer<vtkDataSet> read_vtk_hdf(const std::string& path, const ReadRequest&, const VtkSession& vtk) {
  if (file_head(path, 8).rfind("\x89HDF\r\n\x1a\n", 0) != 0)
    throw DataError(path + ": not a VTK HDF file: it is not HDF5 (no \"\\x89HDF\" signature)");
  auto reader = vtkSmartPointer<vtkHDFReader>::New();
  if (!reader->CanReadFile(path.c_str()))
    throw DataError(path + ": not a VTK HDF file: an HDF5 file without VTK's /VTKHDF group (Version, Type)");
  reader->SetFileName(path.c_str());
  return output_of(reader, path, vtk, as_data_set);
}

// The files that `element` and the elements in it name (a piece's Source,
// a block's or a step's file), as named in the file `from`.
void named_files(vtkXMLDataElement* element, const std::string& from, std::vector<std::string>& out) {
  for (const char* attribute : {"Source", "file"})
    if (const char* file = element->GetAttribute(attribute)) out.push_back(file_named_in(from, file));
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i) named_files(element->GetNestedElement(i), from, out);
}

std::vector<std::string> xml_parts(const std::string& path) {
  std::vector<std::string> files;
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(path.c_str());
  if (parser->Parse() && parser->GetRootElement()) named_files(parser->GetRootElement(), path, files);
  return files;
}

// A time series' data sets: (time, file) in the order of time.
std::vector<std::pair<double, std::string>> series_files(const std::string& path) {
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetFileName(path.c_str());
  vtkXMLDataElement* collection = parser->Parse() ? parser->GetRootElement() : nullptr;
  if (collection) collection = collection->FindNestedElementWithName("Collection");
  if (!collection) throw DataError(path + ": not a ParaView time series: no <Collection> in its <VTKFile>");
  std::vector<std::pair<double, std::string>> steps;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* data_set = collection->GetNestedElement(i);
    const char* file = data_set->GetAttribute("file");
    if (std::string(data_set->GetName()) != "DataSet" || !file) continue;
    double time = double(steps.size());
    data_set->GetScalarAttribute("timestep", time);
    // Parts of one step beyond the first are not read: a series of one
    // part each is what ParaView writes for a single data set.
    if (const char* part = data_set->GetAttribute("part"); part && std::string(part) != "0") continue;
    steps.emplace_back(time, file_named_in(path, file));
  }
  std::stable_sort(steps.begin(), steps.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  if (steps.empty()) throw DataError(path + ": its <Collection> lists no <DataSet file=...>");
  return steps;
}

std::vector<std::string> series_step_files(const std::string& path) {
  std::vector<std::string> files;
  for (const auto& [time, file] : series_files(path)) files.push_back(file);
  return files;
}

std::vector<double> series_step_times(const std::string& path) {
  std::vector<double> times;
  for (const auto& [time, file] : series_files(path)) times.push_back(time);
  return times;
}

}  // namespace

const FormatReader legacy_vtk_reader{read_legacy};
const FormatReader vtk_xml_reader{read_xml};
const FormatReader vtk_pieces_reader{read_xml_parts, nullptr, xml_parts, nullptr, true, false};
const FormatReader vtk_multiblock_reader{read_xml_parts, nullptr, xml_parts, nullptr, true, true};
const FormatReader vtk_series_reader{nullptr, series_step_files, nullptr, series_step_times};
const FormatReader vtk_hdf_reader{read_vtk_hdf};

}  // namespace hsb

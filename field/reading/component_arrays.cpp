#include "field/reading/component_arrays.h"

#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <optional>

#include "field/reading/component_order.h"
#include "field/reading/file_records.h"

namespace hsb {
namespace {

// A component's place: (row, column) of a tensor, or (index, −1) of a vector.
using Place = std::array<int, 2>;

struct Suffix {
  const char* text;
  Place place;
};

constexpr Suffix tensor_suffixes[] = {
    {"xx", {0, 0}}, {"yy", {1, 1}}, {"zz", {2, 2}}, {"xy", {0, 1}}, {"yx", {1, 0}}, {"yz", {1, 2}},
    {"zy", {2, 1}}, {"xz", {0, 2}}, {"zx", {2, 0}}, {"11", {0, 0}}, {"22", {1, 1}}, {"33", {2, 2}},
    {"12", {0, 1}}, {"21", {1, 0}}, {"23", {1, 2}}, {"32", {2, 1}}, {"13", {0, 2}}, {"31", {2, 0}}};
constexpr Suffix vector_suffixes[] = {{"x", {0, -1}}, {"y", {1, -1}}, {"z", {2, -1}}};

const std::string record_prefix = "hsb component order: ";
const std::string default_prefix = "hsb default component order: ";
const std::string note_prefix = "hsb reading note: ";
const std::string frame_prefix = "hsb tensor frame: ";
const std::string voxel_axes_prefix = "hsb voxel axes: ";
const std::string frame_note_prefix = "hsb tensor frame note: ";

// Whether `name` ends in `suffix`, case aside.
bool ends_in(const std::string& name, const char* suffix) {
  const std::size_t n = std::char_traits<char>::length(suffix);
  if (name.size() < n) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (std::tolower(static_cast<unsigned char>(name[name.size() - n + k])) != suffix[k]) return false;
  return true;
}

// The suffix `name` ends in, with a non-empty prefix before it.
template <std::size_t N>
std::optional<Suffix> suffix_of(const std::string& name, const Suffix (&suffixes)[N]) {
  for (const Suffix& s : suffixes)
    if (name.size() > std::char_traits<char>::length(s.text) && ends_in(name, s.text)) return s;
  return std::nullopt;
}

// The components of one quantity: its arrays by place.
struct ComponentSet {
  std::map<Place, std::string> names;
  bool clash = false;  // two arrays at one place (stress_xx and stress_XX)
  bool has(int r, int c) const { return names.count({r, c}) > 0; }
};

// The name a joined array takes: the prefix without its separator.
std::string joined_name(std::string prefix) {
  while (!prefix.empty() && (prefix.back() == '_' || prefix.back() == '-' || prefix.back() == '.' || prefix.back() == ' '))
    prefix.pop_back();
  return prefix;
}

// The one-component arrays of `attributes` that have `suffixes`' ends,
// grouped by prefix; `taken` names are left out.
template <std::size_t N>
std::map<std::string, ComponentSet> component_sets(vtkDataSetAttributes* attributes, const Suffix (&suffixes)[N],
                                                   bool (*excluded)(const std::string&)) {
  std::map<std::string, ComponentSet> sets;
  const vtkIdType tuples = attributes->GetNumberOfTuples();
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
    vtkDataArray* array = attributes->GetArray(i);
    if (!array || !array->GetName() || array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != tuples)
      continue;
    const std::string name = array->GetName();
    const std::optional<Suffix> suffix = suffix_of(name, suffixes);
    if (!suffix || excluded(name)) continue;
    // Letters and digits are separate families: S11 and Sxy are not one tensor.
    const bool digits = std::isdigit(static_cast<unsigned char>(suffix->text[0]));
    const std::string prefix = name.substr(0, name.size() - std::char_traits<char>::length(suffix->text));
    ComponentSet& set = sets[prefix + (digits ? "\n1" : "\na")];
    set.clash = set.clash || !set.names.emplace(suffix->place, name).second;
  }
  return sets;
}

bool never(const std::string&) { return false; }
// stress_xx is never the x of a vector "stress_x": that is how VTK's own
// Exodus reader splits a tensor into a vector and three scalars.
bool is_tensor_component(const std::string& name) {
  return std::any_of(std::begin(tensor_suffixes), std::end(tensor_suffixes),
                     [&](const Suffix& s) { return ends_in(name, s.text); });
}

// Replaces `set`'s arrays by one named `name` whose components are at
// `places` (an absent place is zero), and records the order.
void replace_by_joined(vtkDataSetAttributes* attributes, vtkFieldData* records, const ComponentSet& set,
                       const std::string& name, const std::vector<Place>& places) {
  auto joined = vtkSmartPointer<vtkDoubleArray>::New();
  joined->SetName(name.c_str());
  joined->SetNumberOfComponents(int(places.size()));
  joined->SetNumberOfTuples(attributes->GetNumberOfTuples());
  std::string said;
  for (std::size_t c = 0; c < places.size(); ++c) {
    const auto found = set.names.find(places[c]);
    vtkDataArray* part = found == set.names.end() ? nullptr : attributes->GetArray(found->second.c_str());
    for (vtkIdType t = 0; t < joined->GetNumberOfTuples(); ++t) joined->SetComponent(t, int(c), part ? part->GetComponent(t, 0) : 0.0);
    said += (c ? ", " : "") + (part ? found->second : std::string("0"));
  }
  for (const auto& [place, part] : set.names) attributes->RemoveArray(part.c_str());
  attributes->AddArray(joined);
  record_component_order(records, name, "joined from named components " + said);
}

// The places of a joined tensor, or none when `set` is not one: xx, yy
// and xy at least; a lower shear stands for its upper where only it is
// given; both of every pair make a full 3×3.
std::vector<Place> tensor_places(ComponentSet& set) {
  if (set.clash || !set.has(0, 0) || !set.has(1, 1) || !(set.has(0, 1) || set.has(1, 0))) return {};
  const Place pairs[3][2] = {{{0, 1}, {1, 0}}, {{1, 2}, {2, 1}}, {{0, 2}, {2, 0}}};
  int both = 0;
  for (const auto& pair : pairs) both += set.has(pair[0][0], pair[0][1]) && set.has(pair[1][0], pair[1][1]);
  if (both == 3 && set.has(2, 2))
    return {{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}, {2, 0}, {2, 1}, {2, 2}};
  if (both > 0) return {};  // some shears twice, some once: not a layout anyone writes
  for (const auto& pair : pairs)
    if (auto lower = set.names.find(pair[1]); lower != set.names.end()) {
      set.names.emplace(pair[0], lower->second);
      set.names.erase(lower);
    }
  const ComponentOrder::Entries& vtk = component_order("vtk")->entries;
  return std::vector<Place>(vtk.begin(), vtk.end());
}

}  // namespace

int tensor_name_rank(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  // Code_Aster's fields: SIEF_NOEU, SIGM_ELNO (stress), EPSI_NOEU (strain).
  if (n.find("stress") != std::string::npos || n.find("sigm") != std::string::npos ||
      n.find("sief") != std::string::npos || n == "s")
    return 0;
  if (n.find("strain") != std::string::npos || n.find("eps") != std::string::npos || n == "e") return 1;
  return 2;
}

void join_component_arrays(vtkDataSetAttributes* attributes, vtkFieldData* records) {
  for (auto& [key, set] : component_sets(attributes, tensor_suffixes, never)) {
    const std::string name = joined_name(key.substr(0, key.find('\n')));
    const std::vector<Place> places = tensor_places(set);
    if (places.empty() || name.empty() || attributes->GetAbstractArray(name.c_str())) continue;
    replace_by_joined(attributes, records, set, name, places);
  }
  for (auto& [key, set] : component_sets(attributes, vector_suffixes, is_tensor_component)) {
    const std::string name = joined_name(key.substr(0, key.find('\n')));
    if (set.clash || !set.has(0, -1) || !set.has(1, -1) || name.empty() || attributes->GetAbstractArray(name.c_str()))
      continue;
    replace_by_joined(attributes, records, set, name, {{0, -1}, {1, -1}, {2, -1}});
  }
}

void record_component_order(vtkFieldData* records, const std::string& name, const std::string& how) {
  add_record(records, record_prefix + name, {how});
}

std::string recorded_component_order(vtkDataSet* data, const std::string& name) {
  const std::vector<std::string> record = record_of(data, record_prefix + name);
  return record.empty() ? std::string() : record.front();
}

void record_reading_note(vtkFieldData* records, const std::string& name, const std::string& note) {
  add_record(records, note_prefix + name, {note});
}

std::string recorded_reading_note(vtkDataSet* data, const std::string& name) {
  const std::vector<std::string> record = record_of(data, note_prefix + name);
  return record.empty() ? std::string() : record.front();
}

void record_default_order(vtkFieldData* records, const std::string& name, const std::string& order,
                          const std::string& why) {
  add_record(records, default_prefix + name, {order, why});
}

DefaultOrder recorded_default_order(vtkDataSet* data, const std::string& name) {
  const std::vector<std::string> record = record_of(data, default_prefix + name);
  if (record.size() < 2) return {};
  return {record[0], record[1]};
}

namespace {

// Whether `name` is one of Code_Aster's tensor fields (SIEF_NOEU,
// SIGM_ELNO, EPSI_ELGA, ...; a result's name may come before it, as meshio
// reads a MED file: RESU____SIEF_NOEU).
bool code_aster_field(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  for (const char* field : {"SIEF_", "SIGM_", "EPSI_"})
    for (std::size_t at = name.find(field); at != std::string::npos; at = name.find(field, at + 1))
      if (at == 0 || name[at - 1] == '_') return true;
  return false;
}

// Whether `name` is one of Abaqus's tensor output variables as its
// exporters keep them: S (stress), E, LE, EE, PE, NE, THE (strains), ER
// (strain rate). Upper case, as Abaqus names them: a lower-case "s" or "e"
// says nothing of a writer.
bool abaqus_field(const std::string& name) {
  for (const char* field : {"S", "E", "LE", "EE", "PE", "NE", "THE", "ER"})
    if (name == field) return true;
  return false;
}

}  // namespace

void record_writer_orders(vtkDataSet* data) {
  const bool sfepy = data->GetPointData()->GetAbstractArray("node_groups") && data->GetCellData()->GetAbstractArray("mat_id");
  for (vtkDataSetAttributes* attributes : {static_cast<vtkDataSetAttributes*>(data->GetPointData()),
                                           static_cast<vtkDataSetAttributes*>(data->GetCellData())})
    for (int i = 0; i < attributes->GetNumberOfArrays(); ++i) {
      vtkDataArray* array = attributes->GetArray(i);
      if (!array || !array->GetName() || array->GetNumberOfComponents() != 6) continue;
      const std::string name = array->GetName();
      if (!recorded_component_order(data, name).empty() || !recorded_default_order(data, name).order.empty()) continue;
      if (sfepy)
        record_default_order(data->GetFieldData(), name, "sfepy",
                             "written by SfePy (its node_groups and mat_id arrays say so), which stores 11 22 33 12 13 23");
      else if (code_aster_field(name))
        record_default_order(data->GetFieldData(), name, "code_aster",
                             "its name is a Code_Aster field's, which stores SIXX SIYY SIZZ SIXY SIXZ SIYZ");
      else if (abaqus_field(name))
        record_default_order(data->GetFieldData(), name, "abaqus",
                             "its name is an Abaqus output variable's, which stores S11 S22 S33 S12 S13 S23");
    }
}

namespace {

void record_matrix(vtkFieldData* records, const std::string& name, const Mat3& m) {
  auto record = vtkSmartPointer<vtkDoubleArray>::New();
  record->SetName(name.c_str());
  for (int k = 0; k < 9; ++k) record->InsertNextValue(m(k / 3, k % 3));
  records->AddArray(record);
}

std::optional<Mat3> recorded_matrix(vtkDataSet* data, const std::string& name) {
  auto* record = vtkDoubleArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name.c_str()));
  if (!record || record->GetNumberOfValues() != 9) return std::nullopt;
  Mat3 m;
  for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = record->GetValue(k);
  if (!m.allFinite()) return std::nullopt;
  return m;
}

}  // namespace

void record_tensor_frame(vtkFieldData* records, const std::string& name, const Mat3& frame) {
  record_matrix(records, frame_prefix + name, frame);
}


std::optional<Mat3> recorded_tensor_frame(vtkDataSet* data, const std::string& name) {
  return recorded_matrix(data, frame_prefix + name);
}

void record_voxel_axes(vtkFieldData* records, const std::string& name, const Mat3& axes) {
  record_matrix(records, voxel_axes_prefix + name, axes);
}

std::optional<Mat3> recorded_voxel_axes(vtkDataSet* data, const std::string& name) {
  if (std::optional<Mat3> axes = recorded_matrix(data, voxel_axes_prefix + name)) return axes;
  auto* image = vtkImageData::SafeDownCast(data);
  if (!image) return std::nullopt;
  Mat3 direction;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) direction(r, c) = image->GetDirectionMatrix()->GetElement(r, c);
  return direction;
}

Mat3 fsl_axes(const Mat3& voxel_axes) {
  return voxel_axes * Vec3(voxel_axes.determinant() > 0.0 ? -1.0 : 1.0, 1.0, 1.0).asDiagonal();
}

void record_frame_note(vtkFieldData* records, const std::string& name, const FrameNote& note) {
  add_record(records, frame_note_prefix + name, {note.text, note.guess ? "guess" : "said"});
}

FrameNote recorded_frame_note(vtkDataSet* data, const std::string& name) {
  const std::vector<std::string> record = record_of(data, frame_note_prefix + name);
  if (record.size() != 2) return {};
  return {record[0], record[1] == "guess"};
}

}  // namespace hsb

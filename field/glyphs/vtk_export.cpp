#include "field/glyphs/vtk_export.h"

#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>


#include "base/partial_file.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_session.h"

namespace hsb {
namespace {

vtkSmartPointer<vtkDoubleArray> named_array(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

void set_matrix(vtkDoubleArray* a, vtkIdType i, const Mat3& m) {
  double t[9];
  for (int k = 0; k < 9; ++k) t[k] = m(k / 3, k % 3);
  a->SetTuple(i, t);
}

// Written under a temporary name and renamed, so no half-written file stays.
void write_polydata(vtkPolyData* poly, const std::string& path) {
  PartialFile file(path);
  const VtkSession vtk;
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  // Into memory, then to disk through PartialFile::write, which checks
  // every write: VTK's own file output ignores a full disk.
  writer->WriteToOutputStringOn();
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) {
    const std::string why = vtk.first_error();
    throw DataError(path + ": cannot write the file" + (why.empty() ? "" : ": " + why));
  }
  try {
    const std::string bytes = writer->GetOutputString();
    file.write(bytes.data(), bytes.size());
    file.commit();
  } catch (const std::runtime_error& e) {
    throw DataError(e.what());
  }
}

vtkSmartPointer<vtkPolyData> trajectories_polydata(const GlyphScene& scene) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto arc = vtkSmartPointer<vtkDoubleArray>::New();
  arc->SetName("arc_length");
  auto id = vtkSmartPointer<vtkIntArray>::New();
  id->SetName("trajectory");
  for (std::size_t t = 0; t < scene.trajectories.size(); ++t) {
    const std::vector<Vec3>& p = scene.trajectories[t].points;
    if (p.size() < 2) continue;  // a seed where no curve starts: nothing to draw
    lines->InsertNextCell(int(p.size()));
    double s = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i) s += (p[i] - p[i - 1]).norm();
      lines->InsertCellPoint(points->InsertNextPoint(p[i].x(), p[i].y(), p[i].z()));
      arc->InsertNextValue(s);
    }
    id->InsertNextValue(int(t));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  poly->GetPointData()->AddArray(arc);
  poly->GetCellData()->AddArray(id);
  return poly;
}

vtkSmartPointer<vtkPolyData> sources_polydata(const GlyphScene& scene, double glyph_scale,
                                              const std::vector<SourceArray>& more) {
  const vtkIdType n = vtkIdType(scene.sources.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  auto tensor = named_array("tensor", 9, n), glyph = named_array("glyph", 9, n);
  auto eigenvalues = named_array("eigenvalues", 3, n), radii = named_array("radii", 3, n);
  auto scalar = named_array("scalar", 1, n);
  for (vtkIdType i = 0; i < n; ++i) {
    const GlyphSource& s = scene.sources[std::size_t(i)];
    vertices->InsertNextCell(1);
    vertices->InsertCellPoint(points->InsertNextPoint(s.centre.x(), s.centre.y(), s.centre.z()));
    set_matrix(tensor, i, s.axes * s.eigenvalues.asDiagonal() * s.axes.transpose());
    set_matrix(glyph, i, s.axes * (glyph_scale * s.radii).asDiagonal() * s.axes.transpose());
    eigenvalues->SetTuple(i, s.eigenvalues.data());
    radii->SetTuple(i, s.radii.data());
    scalar->SetValue(i, s.scalar);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(vertices);
  vtkPointData* data = poly->GetPointData();
  data->AddArray(tensor);
  data->AddArray(eigenvalues);
  data->AddArray(radii);
  data->SetScalars(scalar);
  data->SetTensors(glyph);
  for (const SourceArray& m : more) {
    if (m.values.size() != std::size_t(m.components) * std::size_t(n))
      throw std::invalid_argument("source array " + m.name + ": " + std::to_string(m.values.size()) +
                                  " values for " + std::to_string(n) + " sources of " +
                                  std::to_string(m.components) + " components");
    auto a = named_array(m.name.c_str(), m.components, n);
    for (vtkIdType i = 0; i < n; ++i) a->SetTuple(i, m.values.data() + std::size_t(i) * std::size_t(m.components));
    data->AddArray(a);
  }
  return poly;
}

}  // namespace

void write_glyph_scene_vtp(const GlyphScene& scene, double glyph_scale, const std::string& trajectories_path,
                           const std::string& sources_path, const std::vector<SourceArray>& more) {
  // Checked before either file is written.
  const vtkSmartPointer<vtkPolyData> sources = sources_polydata(scene, glyph_scale, more);
  write_polydata(trajectories_polydata(scene), trajectories_path);
  write_polydata(sources, sources_path);
}

}  // namespace hsb

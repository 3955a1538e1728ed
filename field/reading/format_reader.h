#pragma once
// How hsb reads one data format: the hooks behind an entry of the format
// registry (field/reading/data_formats.h). Each reader defines its own
// FormatReader beside its code; dataset_reading.cpp calls only these hooks,
// so adding a format is one reader and one registry line. Internal to
// field/: it names VTK types.

#include <string>
#include <vector>

#include <vtkDataSet.h>
#include <vtkSmartPointer.h>

#include "field/reading/vtk_session.h"

namespace hsb {

// What a scene asks of a file beyond its name.
struct ReadRequest {
  int step = -1;      // a time step's index (-1: the first)
  std::string block;  // one block of a multiblock or Exodus file ("": all, merged)
  // A volume of one value per voxel (a mask), where the volume formats
  // (NRRD, NIfTI) otherwise expect tensors or vectors.
  bool scalar = false;
};

// The hooks are called with a VtkSession held, and those that parse the
// user's file in a child process
// (dataset_reading.cpp): VTK's parsers trust what a file declares.
struct FormatReader {
  // The data set in `path`, read as the request asks (pieces and blocks
  // merged into one grid), before the checks every format gets. Checks
  // the file's own signature first. Runs in a child process. Throws
  // DataError naming the file. Null for a series, whose steps are files
  // of other formats (step_files).
  vtkSmartPointer<vtkDataSet> (*read)(const std::string& path, const ReadRequest& request, const VtkSession& vtk) =
      nullptr;
  // A series only: the file holding each of its steps, in order.
  std::vector<std::string> (*step_files)(const std::string& path) = nullptr;
  // The other files the data is made of (pieces, blocks, a detached data
  // file): each asked before the data is read (none may be a FIFO or a
  // device), and hashed for --skip-existing; null: none.
  std::vector<std::string> (*parts)(const std::string& path) = nullptr;
  // The times of its steps in order, none for data of one step; null: the
  // format has no steps.
  std::vector<double> (*times)(const std::string& path) = nullptr;
  // Pieces or blocks whose shared points are joined into one after reading.
  bool joins_pieces = false;
  // data.block picks one of its blocks.
  bool has_blocks = false;
  // Parsed by hsb's own code, which checks every count the file declares
  // against the bytes it has before trusting it (and is fuzzed to do so):
  // read in this process, without a child's copy of what VTK read.
  bool in_process = false;
};

// The readers, each defined beside its code.
extern const FormatReader legacy_vtk_reader;      // vtk_formats.cpp
extern const FormatReader vtk_xml_reader;         // vtk_formats.cpp
extern const FormatReader vtk_pieces_reader;      // vtk_formats.cpp
extern const FormatReader vtk_multiblock_reader;  // vtk_formats.cpp
extern const FormatReader vtk_series_reader;      // vtk_formats.cpp
extern const FormatReader vtk_hdf_reader;         // vtk_formats.cpp
extern const FormatReader exodus_reader;          // exodus_reading.cpp
extern const FormatReader nrrd_reader;            // nrrd_reading.cpp
extern const FormatReader nifti_reader;           // nifti_reading.cpp
extern const FormatReader mif_reader;             // mif_reading.cpp
extern const FormatReader frd_reader;             // frd_reading.cpp
extern const FormatReader med_reader;             // med_reading.cpp
extern const FormatReader gmsh_reader;            // gmsh_reading.cpp
extern const FormatReader xdmf_reader;            // xdmf_reading.cpp

}  // namespace hsb

// libFuzzer target: bytes as a tensor data file, its format chosen by the
// first byte: even, legacy VTK (.vtk); odd below 128, VTK XML (.vtu); odd
// from 128, by the next bits NIfTI, Exodus II, NRRD, CalculiX .frd,
// MRtrix .mif, Gmsh .msh, MED or XDMF (the seeds' 129, 131 and 133 keep
// theirs). Any input must load or give one
// DataError (or ResourceError): never a crash, a hang, an uncaught
// exception or undefined behaviour.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "base/memory_budget.h"
#include "field/reading/data_error.h"
#include "field/reading/vtk_data.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // Inputs that hang a VTK reader are found (and said) all the same, in a
  // fraction of the fuzzer's own 10-second limit.
  hsb::set_trial_read_seconds(3.0);
  const char* const others[] = {".nii", ".exo", ".nrrd", ".frd", ".mif", ".msh", ".med", ".xdmf"};
  const char* extension = data[0] % 2 == 0 ? ".vtk" : data[0] < 128 ? ".vtu" : others[(data[0] >> 1) % 8];
  const std::string path = "/tmp/hsb_data_fuzzer_" + std::to_string(getpid()) + extension;
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  hsb::VtkFileSpec spec;
  spec.path = path;
  try {
    hsb::load_vtk_data(spec);
  } catch (const hsb::DataError&) {
  } catch (const hsb::ResourceError&) {
  }
  unlink(path.c_str());
  return 0;
}

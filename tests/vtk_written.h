#pragma once
// Test data written by VTK's own writers, with their defaults, as the
// tools users have write it.

#include <gtest/gtest.h>
#include <vtkDataObject.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>

namespace hsb {

// `data` written to `path` by VTK's `Writer` (a failed write fails the
// test); returns `path`.
template <class Writer>
std::string written_by(vtkDataObject* data, const std::filesystem::path& path) {
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(data);
  writer->SetFileName(path.string().c_str());
  EXPECT_EQ(writer->Write(), 1) << path;
  return path.string();
}

}  // namespace hsb

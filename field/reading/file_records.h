#pragma once
// What reading learnt about a file and later steps need (the component
// order a format records, the blocks a multiblock file had), kept as named
// string arrays in the data set's field data: they survive the copy the
// reading child writes back (dataset_reading.cpp), and `hsb info` never
// lists field data among the arrays. Internal to field/.

#include <string>
#include <vector>

class vtkDataSet;
class vtkFieldData;

namespace hsb {

// The record of the anatomical directions the world's axes point to, three
// letters ("RAS": x to the right, y anterior, z superior; "LPS"), kept by
// the readers whose formats say so (NIfTI's scanner space, NRRD's `space`).
inline constexpr const char* kAnatomicalFrame = "anatomical_frame";

// Stores `values` under `key` (replacing an earlier record of that key).
void add_record(vtkFieldData* records, const std::string& key, const std::vector<std::string>& values);

// The values stored under `key`, none when there is no such record.
std::vector<std::string> record_of(vtkDataSet* data, const std::string& key);

}  // namespace hsb

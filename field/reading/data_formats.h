#pragma once
// The data file formats hsb knows, in one place: each by its name, its
// extensions, a probe of its first bytes, and the reader that reads it.
// The scene reader, the command line's help, `hsb info` and the VTK reader
// all ask here, so a file of a format hsb does not read is named as what it
// is (a NRRD volume, a Gmsh mesh) with the list of what hsb reads, never
// mistaken for a scene and refused as bad TOML.

#include <string>
#include <vector>

namespace hsb {

struct FormatReader;  // how it is read: field/reading/format_reader.h (VTK inside)

struct DataFormat {
  std::string name;                     // "VTK XML unstructured grid"
  std::vector<std::string> extensions;  // lower case, with the dot: ".vtu", ".nii.gz"
  // Whether a file's first bytes (up to 1 KiB) are this format's; null for
  // a format without a signature.
  bool (*probe)(const std::string& head) = nullptr;
  // How hsb reads it; null: not read (yet), named in messages only.
  const FormatReader* reader = nullptr;
  // For a format hsb does not read: how to get one it does.
  std::string advice;
  // A format whose signature this one's files carry (Exodus is netCDF,
  // whose version 4 is HDF5 inside): such content is no other format.
  std::string container;
  bool readable() const { return reader != nullptr; }
};

const std::vector<DataFormat>& data_formats();

// The format `path`'s name ends in (the longest match: ".nii.gz" before
// ".gz"), else nullptr.
const DataFormat* format_by_extension(const std::string& path);

// The format the first bytes of the file at `path` say, else nullptr (also
// when it cannot be read).
const DataFormat* format_by_content(const std::string& path);

// `path`'s file name without its format's extension ("brain" for
// "a/brain.nii.gz"), or without its last extension when no format has it.
std::string file_stem(const std::string& path);

// Whether `path` names a data file hsb reads, by its extension.
bool is_readable_data_file(const std::string& path);

// Whether `path` looks like data of any known format (by extension, else
// by content), readable or not: such a file is never read as a scene.
bool is_known_data_file(const std::string& path);

// Why hsb cannot read `path` as data, in one line: its format, by
// extension and by content, what to do about it, and the formats hsb
// reads. "" when it reads it.
std::string unreadable_format_message(const std::string& path);

// What a file that is neither a scene (TOML that parses) nor data of a
// format hsb knows is, in one line: what its first bytes look like (text,
// quoted; or binary, in hex), and what hsb reads. `toml_error` is TOML's
// own word on it ("1:7: expected '='"), said last.
std::string unknown_file_message(const std::string& path, const std::string& toml_error);

// "legacy VTK (.vtk), VTK XML image data (.vti), ...": what hsb reads.
std::string readable_formats_text();

// ".vtk .vti .vtu .vts .vtr": the extensions hsb reads, for help texts.
std::string readable_extensions_text();

}  // namespace hsb

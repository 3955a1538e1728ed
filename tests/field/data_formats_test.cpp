// The registry of data formats: names and first bytes tell the formats
// apart, and a file hsb does not read is said as what it is.

#include <gtest/gtest.h>

#include <fstream>

#include "field/reading/data_formats.h"
#include "tests/temp_dir.h"

namespace hsb {
namespace {

std::string write(const std::string& name, const std::string& bytes) {
  const std::string path = (test_temp_dir("formats") / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string nifti_header() {
  std::string header(352, '\0');
  header[0] = char(348);  // sizeof_hdr, little-endian
  header[1] = char(1);
  header.replace(344, 4, std::string("n+1\0", 4));
  return header;
}

TEST(DataFormats, TheLongestExtensionNamesTheFormat) {
  ASSERT_NE(format_by_extension("brain.nii.gz"), nullptr);
  EXPECT_EQ(format_by_extension("brain.nii.gz")->name, "NIfTI");
  EXPECT_EQ(format_by_extension("BEAM.VTU")->name, "VTK XML unstructured grid");
  EXPECT_EQ(format_by_extension("notes.gz"), nullptr);
  EXPECT_EQ(format_by_extension("scene.toml"), nullptr);
  EXPECT_TRUE(is_readable_data_file("a/b/c.vtk"));
  EXPECT_TRUE(is_readable_data_file("c.pvtu"));
  EXPECT_TRUE(is_readable_data_file("c.msh"));
  EXPECT_FALSE(is_readable_data_file("c.inp"));
}

TEST(DataFormats, TheFirstBytesNameTheFormat) {
  EXPECT_EQ(format_by_content(write("a", "NRRD0004\ntype: float\n"))->name, "NRRD");
  EXPECT_EQ(format_by_content(write("b", "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\">"))->name,
            "VTK XML multiblock data set");
  EXPECT_EQ(format_by_content(write("c", "<VTKFile type='PUnstructuredGrid' version='1.0'>"))->name,
            "parallel VTK XML unstructured grid");
  EXPECT_EQ(format_by_content(write("d", nifti_header()))->name, "NIfTI");
  EXPECT_EQ(format_by_content(write("e", "$MeshFormat\n4.1 0 8\n"))->name, "Gmsh mesh");
  EXPECT_EQ(format_by_content(write("f", "# vtk DataFile Version 5.1\n"))->name, "legacy VTK");
  EXPECT_EQ(format_by_content(write("g", "[data]\nfile = \"x.vtu\"\n")), nullptr);
  EXPECT_EQ(format_by_content(write("h", "")), nullptr);
}

TEST(DataFormats, AFileStemLosesItsWholeExtension) {
  EXPECT_EQ(file_stem("scans/brain.nii.gz"), "brain");
  EXPECT_EQ(file_stem("beam.vtu"), "beam");
  EXPECT_EQ(file_stem("scene.v2.toml"), "scene.v2");
  EXPECT_EQ(file_stem("archive.tar.gz"), "archive.tar");
}

TEST(DataFormats, AFileHsbDoesNotReadIsSaidAsWhatItIs) {
  const std::string inp = write("bracket.inp", "*Heading\n bracket\n");
  const std::string message = unreadable_format_message(inp);
  EXPECT_EQ(message.rfind(inp + ": a file in the Abaqus input format (by its name and content), which hsb does not read: ", 0), 0u) << message;
  EXPECT_EQ(unreadable_format_message(write("helix.nrrd", "NRRD0004\n")), "");  // read since NRRD got its reader
  EXPECT_NE(message.find("hsb reads legacy VTK (.vtk), VTK XML image data (.vti)"), std::string::npos) << message;
  // Under a name hsb reads, the content is what it is.
  const std::string disguised = write("brain.vtu", nifti_header());
  EXPECT_NE(unreadable_format_message(disguised).find("a file in the NIfTI format (by its content)"), std::string::npos);
  // A Code_Aster result is HDF5 inside: MED by its name, not HDF5 by its
  // content, and read since MED got its reader.
  EXPECT_EQ(unreadable_format_message(write("result.rmed", std::string("\x89HDF\r\n\x1a\n", 8))), "");
  // Abaqus's own database: named, with what to do.
  const std::string odb = unreadable_format_message(write("result.odb", std::string("\x00\x01", 2)));
  EXPECT_NE(odb.find("a file in the Abaqus output database format (by its name), which hsb does not read: export"),
            std::string::npos) << odb;
  const std::string legacy = write("beam.vtu", "# vtk DataFile Version 4.2\n");
  EXPECT_NE(unreadable_format_message(legacy).find("give it its format's extension (.vtk)"), std::string::npos);
  // What it reads says nothing; nor does a readable name over unknown bytes
  // (the reader's own checks speak for those).
  EXPECT_EQ(unreadable_format_message(write("beam2.vtu", "<?xml version=\"1.0\"?><VTKFile type=\"UnstructuredGrid\">")), "");
  EXPECT_EQ(unreadable_format_message(write("noise.vtu", "\x01\x02garbage")), "");
  EXPECT_TRUE(is_known_data_file(write("nameless", "NRRD0005\n")));
  EXPECT_FALSE(is_known_data_file(write("scene.toml", "NRRD0005\n")));
}

TEST(DataFormats, AFileOfNoKnownKindSaysWhatItsFirstBytesAre) {
  const std::string text = write("plate.xyz", "    1C                                                 \n");
  const std::string said = unknown_file_message(text, "1:7: expected '='");
  EXPECT_EQ(said.rfind(text + ": neither a scene nor a data file hsb knows: it is text beginning \"    1C", 0), 0u)
      << said;
  EXPECT_NE(said.find("not TOML (1:7: expected '=')"), std::string::npos) << said;
  EXPECT_NE(said.find("hsb reads scenes (.toml) and legacy VTK (.vtk)"), std::string::npos) << said;
  const std::string binary = unknown_file_message(write("blob.bin", std::string("\x7f\x00\x01\xfe" "ELF", 7)), "1:1: x");
  EXPECT_NE(binary.find("it is binary, beginning 7f 00 01 fe 45 4c 46"), std::string::npos) << binary;
  EXPECT_NE(unknown_file_message(write("void.dat", ""), "").find("it is empty"), std::string::npos);
}

}  // namespace
}  // namespace hsb

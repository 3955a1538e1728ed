// The published colormap tables: every map present with its published size,
// spot values against the sources written out here, ColorBrewer's hex
// colours, Moreland's endpoints and neutral middle, the diverging flags, and
// luminance rising along the sequential maps.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "renderer/image/colormap_tables.h"

namespace hsb {
namespace {

const ColormapTable* find_table(const std::string& name) {
  for (const ColormapTable& table : colormap_tables())
    if (table.name != nullptr && name == table.name) return &table;
  return nullptr;
}

// One published entry: its index and its three values as printed in the source.
struct Entry {
  std::size_t index;
  double r, g, b;
};

void expect_entries(const std::string& name, const std::vector<Entry>& entries, double tolerance) {
  const ColormapTable* table = find_table(name);
  ASSERT_NE(table, nullptr) << name;
  for (const Entry& e : entries) {
    ASSERT_LT(e.index, table->colors.size()) << name;
    const auto& c = table->colors[e.index];
    EXPECT_NEAR(c[0], e.r, tolerance) << name << "[" << e.index << "] red";
    EXPECT_NEAR(c[1], e.g, tolerance) << name << "[" << e.index << "] green";
    EXPECT_NEAR(c[2], e.b, tolerance) << name << "[" << e.index << "] blue";
  }
}

double srgb_to_linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

double relative_luminance(const std::array<float, 3>& c) {
  return 0.2126 * srgb_to_linear(c[0]) + 0.7152 * srgb_to_linear(c[1]) + 0.0722 * srgb_to_linear(c[2]);
}

TEST(ColormapTables, EveryMapOnceWithItsPublishedSize) {
  const std::vector<std::pair<std::string, std::size_t>> expected{
      {"viridis", 256}, {"magma", 256}, {"cividis", 256}, {"coolwarm", 257}, {"RdBu", 11}};
  for (const auto& [name, size] : expected) {
    int count = 0;
    for (const ColormapTable& table : colormap_tables())
      if (table.name != nullptr && name == table.name) ++count;
    EXPECT_EQ(count, 1) << name;
    const ColormapTable* table = find_table(name);
    ASSERT_NE(table, nullptr) << name;
    EXPECT_EQ(table->colors.size(), size) << name;
  }
  EXPECT_EQ(colormap_tables().size(), expected.size());
  ASSERT_FALSE(colormap_tables().empty());
  EXPECT_STREQ(colormap_tables().front().name, "viridis");
}

TEST(ColormapTables, EveryValueInTheUnitIntervalAndEverySourceNamed) {
  for (const ColormapTable& table : colormap_tables()) {
    ASSERT_NE(table.name, nullptr);
    ASSERT_NE(table.source, nullptr) << table.name;
    EXPECT_GT(std::string(table.source).size(), 10u) << table.name;
    EXPECT_GE(table.colors.size(), 2u) << table.name;
    for (std::size_t i = 0; i < table.colors.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(table.colors[i][k])) << table.name << "[" << i << "]";
        EXPECT_GE(table.colors[i][k], 0.0f) << table.name << "[" << i << "]";
        EXPECT_LE(table.colors[i][k], 1.0f) << table.name << "[" << i << "]";
      }
  }
}

// matplotlib lib/matplotlib/_cm_listed.py, _viridis_data.
TEST(ColormapTables, ViridisMatchesMatplotlib) {
  expect_entries("viridis",
                 {{0, 0.267004, 0.004874, 0.329415},
                  {64, 0.229739, 0.322361, 0.545706},
                  {127, 0.128729, 0.563265, 0.551229},
                  {128, 0.127568, 0.566949, 0.550556},
                  {192, 0.369214, 0.788888, 0.382914},
                  {255, 0.993248, 0.906157, 0.143936}},
                 1e-6);
}

// matplotlib lib/matplotlib/_cm_listed.py, _magma_data.
TEST(ColormapTables, MagmaMatchesMatplotlib) {
  expect_entries("magma",
                 {{0, 0.001462, 0.000466, 0.013866},
                  {64, 0.316654, 0.071690, 0.485380},
                  {127, 0.709962, 0.212797, 0.477201},
                  {128, 0.716387, 0.214982, 0.475290},
                  {192, 0.986700, 0.535582, 0.382210},
                  {255, 0.987053, 0.991438, 0.749504}},
                 1e-6);
}

// matplotlib lib/matplotlib/_cm_listed.py, _cividis_data.
TEST(ColormapTables, CividisMatchesMatplotlib) {
  expect_entries("cividis",
                 {{0, 0.000000, 0.135112, 0.304751},
                  {64, 0.263738, 0.307831, 0.422789},
                  {127, 0.485141, 0.482451, 0.470384},
                  {128, 0.488697, 0.485318, 0.471008},
                  {192, 0.736488, 0.680629, 0.424028},
                  {255, 0.995737, 0.909344, 0.217772}},
                 1e-6);
}

// Moreland's CoolWarmFloat257.csv.
TEST(ColormapTables, CoolwarmMatchesMorelandsFloatTable) {
  expect_entries("coolwarm",
                 {{0, 0.2298057, 0.298717966, 0.753683153},
                  {64, 0.552953156, 0.688929332, 0.995375608},
                  {128, 0.865395197, 0.86541021, 0.865395561},
                  {192, 0.958003065, 0.602842431, 0.481775914},
                  {256, 0.705673158, 0.01555616, 0.150232812}},
                 1e-6);
}

// The endpoints Moreland publishes in bytes, and his neutral grey in the middle.
TEST(ColormapTables, CoolwarmEndpointsAndNeutralMiddle) {
  const ColormapTable* table = find_table("coolwarm");
  ASSERT_NE(table, nullptr);
  const std::size_t n = table->colors.size();
  ASSERT_EQ(n % 2, 1u);  // an entry exactly at the middle
  const auto& lo = table->colors.front();
  const auto& hi = table->colors.back();
  const auto& mid = table->colors[n / 2];
  const double lo_bytes[3] = {59, 76, 192}, hi_bytes[3] = {180, 4, 38};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(lo[k], lo_bytes[k] / 255.0, 1.0 / 255.0) << k;
    EXPECT_NEAR(hi[k], hi_bytes[k] / 255.0, 1.0 / 255.0) << k;
    EXPECT_NEAR(mid[k], 221.0 / 255.0, 2.0 / 255.0) << k;
  }
}

// The 33-entry byte table of Moreland's paper: every 8th entry of the
// 257-entry float table rounds to it.
TEST(ColormapTables, CoolwarmAgreesWithTheThirtyThreeByteTable) {
  const int bytes[33][3] = {
      {59, 76, 192},   {68, 90, 204},   {77, 104, 215},  {87, 117, 225},  {98, 130, 234},  {108, 142, 241},
      {119, 154, 247}, {130, 165, 251}, {141, 176, 254}, {152, 185, 255}, {163, 194, 255}, {174, 201, 253},
      {184, 208, 249}, {194, 213, 244}, {204, 217, 238}, {213, 219, 230}, {221, 221, 221}, {229, 216, 209},
      {236, 211, 197}, {241, 204, 185}, {245, 196, 173}, {247, 187, 160}, {247, 177, 148}, {247, 166, 135},
      {244, 154, 123}, {241, 141, 111}, {236, 127, 99},  {229, 112, 88},  {222, 96, 77},   {213, 80, 66},
      {203, 62, 56},   {192, 40, 47},   {180, 4, 38}};
  const ColormapTable* table = find_table("coolwarm");
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->colors.size(), 257u);
  for (std::size_t j = 0; j < 33; ++j)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(table->colors[8 * j][k] * 255.0, bytes[j][k], 0.5 + 1e-4) << j << " " << k;
}

// ColorBrewer RdBu, 11 classes, red at the low end.
TEST(ColormapTables, RdBuIsColorBrewersElevenClasses) {
  const char* const hex[11] = {"#67001f", "#b2182b", "#d6604d", "#f4a582", "#fddbc7", "#f7f7f7",
                               "#d1e5f0", "#92c5de", "#4393c3", "#2166ac", "#053061"};
  const ColormapTable* table = find_table("RdBu");
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->colors.size(), 11u);
  for (std::size_t i = 0; i < 11; ++i) {
    const std::string h(hex[i]);
    for (int k = 0; k < 3; ++k) {
      const long byte = std::strtol(h.substr(1 + 2 * std::size_t(k), 2).c_str(), nullptr, 16);
      EXPECT_NEAR(table->colors[i][k], double(byte) / 255.0, 1e-6) << hex[i] << " channel " << k;
    }
  }
}

TEST(ColormapTables, DivergingFlags) {
  const std::vector<std::pair<std::string, bool>> expected{
      {"viridis", false}, {"magma", false}, {"cividis", false}, {"coolwarm", true}, {"RdBu", true}};
  for (const auto& [name, diverging] : expected) {
    const ColormapTable* table = find_table(name);
    ASSERT_NE(table, nullptr) << name;
    EXPECT_EQ(table->diverging, diverging) << name;
  }
}

// The perceptually uniform sequential maps get lighter all the way along.
TEST(ColormapTables, SequentialMapsRiseInLuminance) {
  for (const char* name : {"viridis", "magma", "cividis"}) {
    const ColormapTable* table = find_table(name);
    ASSERT_NE(table, nullptr) << name;
    for (std::size_t i = 1; i < table->colors.size(); ++i)
      EXPECT_GT(relative_luminance(table->colors[i]), relative_luminance(table->colors[i - 1]))
          << name << "[" << i << "]";
  }
}

}  // namespace
}  // namespace hsb

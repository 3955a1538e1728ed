#include "field/glyphs/source_list.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "field/reading/data_error.h"

namespace hsb {
namespace {

struct Cell {
  std::string text;
  int column;  // 1-based, of its first character
};

std::vector<Cell> split(const std::string& line) {
  std::vector<Cell> cells;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    std::string text = line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t first = text.find_first_not_of(" \t\r");
    const std::size_t last = text.find_last_not_of(" \t\r");
    const int column = int(start + (first == std::string::npos ? 0 : first)) + 1;
    cells.push_back({first == std::string::npos ? "" : text.substr(first, last - first + 1), column});
    if (comma == std::string::npos) return cells;
    start = comma + 1;
  }
}

}  // namespace

std::vector<GlyphSource> read_source_list(const std::string& path, double glyph_extent) {
  std::ifstream in(path);
  if (!in) throw DataError(path + ": cannot open the source list");
  const auto fail = [&](int line, int column, const std::string& what) {
    throw DataError(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
  };

  std::map<std::string, std::size_t> columns;  // name → index
  std::vector<GlyphSource> sources;
  std::string line;
  int number = 0;
  std::size_t width = 0;
  while (std::getline(in, line)) {
    ++number;
    // Spreadsheets save UTF-8 with a byte-order mark: not part of the header.
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<Cell> cells = split(line);
    if (columns.empty()) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].text.empty()) fail(number, cells[i].column, "a column name, found an empty header cell");
        if (!columns.emplace(cells[i].text, i).second)
          fail(number, cells[i].column, "each column once, found \"" + cells[i].text + "\" twice");
      }
      width = cells.size();
      const auto has = [&](std::initializer_list<const char*> names) {
        for (const char* n : names)
          if (!columns.count(n)) return false;
        return true;
      };
      if (!has({"x", "y", "z"})) fail(number, 1, "a header with columns x, y and z (the centre)");
      if (!has({"r1", "r2", "r3"}) && !has({"r"})) fail(number, 1, "a header with columns r1, r2 and r3, or r");
      // A group of columns comes whole or not at all.
      const auto whole = [&](std::initializer_list<const char*> names, const char* what) {
        std::string present, missing;
        std::size_t at = cells.size();
        for (const char* n : names) {
          const auto it = columns.find(n);
          (it == columns.end() ? missing : present) += std::string(n) + " ";
          if (it != columns.end()) at = std::min(at, it->second);
        }
        if (!present.empty() && !missing.empty())
          fail(number, cells[at].column,
               std::string("all of the columns ") + what + ", found " + present + "without " + missing.substr(0, missing.size() - 1));
      };
      whole({"r1", "r2", "r3"}, "r1, r2, r3 (the radii)");
      whole({"ax", "ay", "az", "bx", "by", "bz"}, "ax, ay, az, bx, by, bz (two axes)");
      whole({"qw", "qx", "qy", "qz"}, "qw, qx, qy, qz (a quaternion)");
      whole({"l1", "l2", "l3"}, "l1, l2, l3 (the signed eigenvalues)");
      continue;
    }
    if (cells.size() != width)
      fail(number, cells.back().column,
           std::to_string(width) + " values as in the header, found " + std::to_string(cells.size()));
    const auto value = [&](const char* name) {
      const Cell& cell = cells[columns.at(name)];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(cell.text.c_str(), &end);
      if (cell.text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        fail(number, cell.column, std::string(name) + ": a finite number, found \"" + cell.text + "\"");
      return v;
    };
    const auto positive = [&](const char* name) {
      const double v = value(name);
      if (!(v > 0.0)) fail(number, cells[columns.at(name)].column, std::string(name) + ": a size > 0, found " + cells[columns.at(name)].text);
      return v;
    };
    GlyphSource s;
    s.centre = Vec3(value("x"), value("y"), value("z"));
    // The ray tracer keeps rays in single precision: nothing beyond ±1e17.
    for (const char* axis : {"x", "y", "z"})
      if (!(std::fabs(value(axis)) <= 1e17))
        fail(number, cells[columns.at(axis)].column,
             std::string(axis) + ": a coordinate within ±1e17 (the ray tracer's single-precision range), found " +
                 cells[columns.at(axis)].text);
    s.eigenvalues = columns.count("r1") ? Vec3(positive("r1"), positive("r2"), positive("r3"))
                                        : Vec3::Constant(positive("r"));
    s.radii = s.eigenvalues / glyph_extent;
    if (columns.count("ax")) {
      const Vec3 a(value("ax"), value("ay"), value("az")), b(value("bx"), value("by"), value("bz"));
      const Vec3 c = a.cross(b);
      if (!(a.norm() > 0.0) || !(c.norm() > 1e-9 * a.norm() * b.norm()))
        fail(number, cells[columns.at("ax")].column, "two axes that are neither zero nor parallel");
      s.axes.col(0) = a.normalized();
      s.axes.col(2) = c.normalized();
      s.axes.col(1) = s.axes.col(2).cross(s.axes.col(0));
    } else if (columns.count("qw")) {
      const Eigen::Quaterniond q(value("qw"), value("qx"), value("qy"), value("qz"));
      if (!(q.norm() > 0.0)) fail(number, cells[columns.at("qw")].column, "a quaternion that is not zero");
      s.axes = q.normalized().toRotationMatrix();
    }
    if (columns.count("scalar")) s.scalar = value("scalar");
    // The signed values the radii stand for: a signed glyph shows their signs.
    if (columns.count("l1")) s.eigenvalues = Vec3(value("l1"), value("l2"), value("l3"));
    sources.push_back(s);
  }
  if (columns.empty()) throw DataError(path + ": no header row: expected column names such as x, y, z, r");
  return sources;
}

}  // namespace hsb

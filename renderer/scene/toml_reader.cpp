#include "renderer/scene/toml_reader.h"

#include <cmath>
#include <sstream>

namespace hsb {
namespace {

// The largest coordinate a point may have (TableReader::position).
constexpr double kLargestCoordinate = 1e17;

}  // namespace

std::string source_location(const toml::source_region& where) {
  const std::string file = where.path ? *where.path : std::string("<scene>");
  if (file.rfind("--set ", 0) == 0) return file;
  return file + ":" + std::to_string(where.begin.line) + ":" + std::to_string(where.begin.column);
}

namespace {

// The first node at or below `node` that came from a file or a --set: a
// table that a --set created on its way to its value has no place of its
// own, and its value's is where it came from.
const toml::node* placed(const toml::node& node) {
  if (node.source().path) return &node;
  if (const toml::table* table = node.as_table())
    for (const auto& [key, child] : *table)
      if (const toml::node* found = placed(child)) return found;
  if (const toml::array* array = node.as_array())
    for (const toml::node& child : *array)
      if (const toml::node* found = placed(child)) return found;
  return nullptr;
}

}  // namespace

std::string source_location(const toml::node& node) {
  const toml::node* found = placed(node);
  return source_location(found ? found->source() : node.source());
}

std::string describe(const toml::node& node) {
  std::ostringstream out;
  switch (node.type()) {
    case toml::node_type::string: out << "string \"" << node.as_string()->get() << "\""; break;
    case toml::node_type::table: out << "a table"; break;
    case toml::node_type::array: out << "an array of " << node.as_array()->size(); break;
    case toml::node_type::boolean: out << (node.as_boolean()->get() ? "true" : "false"); break;
    case toml::node_type::integer: out << node.as_integer()->get(); break;
    case toml::node_type::floating_point: out << node.as_floating_point()->get(); break;
    default: out << "a " << node.type(); break;
  }
  return out.str();
}

TableReader::TableReader(const toml::table& table, std::string prefix, std::string where)
    : table_(table), prefix_(std::move(prefix)), where_(std::move(where)) {}

std::string TableReader::path(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

void TableReader::fail(const toml::node& at, std::string_view key, const std::string& what) const {
  throw SceneError(source_location(at) + ": " + path(key) + " " + what);
}

void TableReader::fail_at(std::string_view key, const std::string& what) const {
  if (const toml::node* node = table_.get(key)) fail(*node, key, what);
  throw SceneError(where_ + ": " + path(key) + " " + what);
}

const toml::node* TableReader::lookup(std::string_view key) {
  known_.emplace(key);
  return table_.get(key);
}

std::string TableReader::choice_error(const std::vector<std::string>& names) const {
  std::string text = "must be one of";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i ? ", \"" : " \"") + names[i] + "\"";
  return text;
}

double TableReader::number(std::string_view key, double fallback, NumberRange range) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  const std::optional<double> value = node->value<double>();  // integers convert
  if (!value || !(node->is_integer() || node->is_floating_point()))
    fail(*node, key, "must be a number, got " + describe(*node));
  const double v = *value;
  if (!std::isfinite(v) && !(range.allow_infinite && std::isinf(v)))
    fail(*node, key, "must be a finite number, got " + describe(*node));
  const bool low = range.lo_open ? !(v > range.lo) : !(v >= range.lo);
  if (std::isnan(v) || low || v > range.hi) {
    std::ostringstream text;
    if (range.hi == std::numeric_limits<double>::infinity())
      text << "must be " << (range.lo_open ? "> " : ">= ") << range.lo;
    else
      text << "must be in " << (range.lo_open ? "(" : "[") << range.lo << ", " << range.hi << "]";
    fail(*node, key, text.str() + ", got " + describe(*node));
  }
  return v;
}

std::optional<double> TableReader::optional_number(std::string_view key, NumberRange range) {
  if (!table_.contains(key)) {
    known_.emplace(key);
    return std::nullopt;
  }
  return number(key, 0.0, range);
}

std::optional<bool> TableReader::optional_boolean(std::string_view key) {
  if (!table_.contains(key)) {
    known_.emplace(key);
    return std::nullopt;
  }
  return boolean(key, false);
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  if (!table_.contains(key)) {
    known_.emplace(key);
    return std::nullopt;
  }
  return string(key, "");
}

int TableReader::integer(std::string_view key, int fallback, int lo, int hi) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  if (!node->is_integer()) fail(*node, key, "must be an integer, got " + describe(*node));
  const std::int64_t v = node->as_integer()->get();
  if (v < lo || v > hi)
    fail(*node, key,
         "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + describe(*node));
  return int(v);
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  if (!node->is_boolean()) fail(*node, key, "must be true or false, got " + describe(*node));
  return node->as_boolean()->get();
}

std::string TableReader::string(std::string_view key, const std::string& fallback) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  if (!node->is_string()) fail(*node, key, "must be a string, got " + describe(*node));
  return node->as_string()->get();
}

std::vector<double> TableReader::numbers(std::string_view key, std::size_t count) {
  const toml::node* node = lookup(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  const std::string expected =
      count ? "an array of " + std::to_string(count) + " numbers" : std::string("an array of numbers");
  if (!array || (count && array->size() != count))
    fail(*node, key, "must be " + expected + ", got " + describe(*node));
  std::vector<double> out;
  for (const toml::node& element : *array) {
    if (!(element.is_integer() || element.is_floating_point()))
      fail(element, key, "must be " + expected + ", got an element " + describe(element));
    if (!std::isfinite(*element.value<double>()))
      fail(element, key, "must be " + expected + " (finite), got an element " + describe(element));
    out.push_back(*element.value<double>());
  }
  return out;
}

std::vector<std::string> TableReader::strings(std::string_view key) {
  const toml::node* node = lookup(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  if (!array) fail(*node, key, "must be an array of strings, got " + describe(*node));
  std::vector<std::string> out;
  for (const toml::node& element : *array) {
    if (!element.is_string()) fail(element, key, "must be an array of strings, got an element " + describe(element));
    out.push_back(element.as_string()->get());
  }
  return out;
}

Vec3 TableReader::position(std::string_view key, const Vec3& fallback) {
  const Vec3 p = vec3(key, fallback);
  if (!(p.cwiseAbs().maxCoeff() <= kLargestCoordinate)) {
    std::ostringstream got;
    got << "must be within ±1e17 in every coordinate (the ray tracer's single-precision range), got [" << p.x()
        << ", " << p.y() << ", " << p.z() << "]";
    fail(*lookup(key), key, got.str());
  }
  return p;
}

Vec3 TableReader::vec3(std::string_view key, const Vec3& fallback) {
  if (!table_.contains(key)) {
    known_.emplace(key);
    return fallback;
  }
  const std::vector<double> v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

Rgb TableReader::color(std::string_view key, const Rgb& fallback) {
  const toml::node* node = lookup(key);
  if (!node) return fallback;
  if (const auto* s = node->as_string()) {
    const std::string& hex = s->get();
    unsigned r = 0, g = 0, b = 0;
    if (hex.size() == 7 && hex[0] == '#' && std::sscanf(hex.c_str() + 1, "%2x%2x%2x", &r, &g, &b) == 3)
      return {float(r) / 255.0f, float(g) / 255.0f, float(b) / 255.0f};
    fail(*node, key, "must be \"#rrggbb\" or [r, g, b], got " + describe(*node));
  }
  const std::vector<double> v = numbers(key, 3);
  for (double c : v)
    if (!(c >= 0.0 && c <= 1.0)) fail(*node, key, "components must be in [0, 1]");
  return {float(v[0]), float(v[1]), float(v[2])};
}

std::optional<TableReader> TableReader::table(std::string_view key) {
  const toml::node* node = lookup(key);
  if (!node) return std::nullopt;
  if (!node->is_table()) fail(*node, key, "must be a table, got " + describe(*node));
  return TableReader(*node->as_table(), path(key), source_location(*node));
}

std::vector<TableReader> TableReader::tables(std::string_view key) {
  const toml::node* node = lookup(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    fail(*node, key, "must be an array of tables ([[" + path(key) + "]]), got " + describe(*node));
  std::vector<TableReader> out;
  std::size_t i = 0;
  for (const toml::node& element : *array)
    out.emplace_back(*element.as_table(), path(key) + "[" + std::to_string(i++) + "]",
                     source_location(element));
  return out;
}

std::vector<Vec3> TableReader::points(std::string_view key) {
  const toml::node* node = lookup(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  if (!array) fail(*node, key, "must be an array of [x, y, z] points, got " + describe(*node));
  std::vector<Vec3> out;
  for (const toml::node& element : *array) {
    const toml::array* p = element.as_array();
    bool numeric = p && p->size() == 3;
    for (std::size_t k = 0; numeric && k < 3; ++k)
      numeric = (*p)[k].is_integer() || (*p)[k].is_floating_point();
    if (!numeric)
      fail(element, key, "must be an array of [x, y, z] points, got an element " + describe(element));
    Vec3 v;
    for (std::size_t k = 0; k < 3; ++k) {
      v[Eigen::Index(k)] = *(*p)[k].value<double>();
      if (!(std::fabs(v[Eigen::Index(k)]) <= kLargestCoordinate))
        fail((*p)[k], key, "must hold coordinates within ±1e17 (the ray tracer's single-precision range), got " +
                               describe((*p)[k]));
    }
    out.push_back(v);
  }
  return out;
}

void TableReader::finish() const {
  for (const auto& [key, node] : table_) {
    if (known_.count(key.str())) continue;
    std::string known_list;
    for (const std::string& k : known_) known_list += (known_list.empty() ? "" : ", ") + k;
    // A key from --set has no place in the file: name the argument instead.
    const std::string where = key.source().path ? source_location(key.source()) : source_location(node);
    throw SceneError(where + ": unknown key " + path(key.str()) +
                     (known_list.empty() ? std::string() : " (known here: " + known_list + ")"));
  }
}

}  // namespace hsb

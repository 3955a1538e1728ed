#include "renderer/scene/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <variant>
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
    : table_(table), prefix_(std::move(prefix)), where_(std::move(where)) {
  // "seeds.grid[2]" reads the keys of "seeds.grid".
  bool index = false;
  for (char c : prefix_) {
    index = c == '[' || (index && c != ']');
    if (!index && c != ']') schema_prefix_ += c;
  }
}

std::string TableReader::path(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

const KeySchema& TableReader::schema(std::string_view key) const {
  return scene_key(schema_prefix_.empty() ? std::string(key) : schema_prefix_ + "." + std::string(key));
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

const toml::node* TableReader::value_or_default(std::string_view key) {
  const toml::node* node = lookup(key);
  return node ? node : default_node(schema(key));
}

std::string TableReader::choice_error(const std::vector<std::string>& names) const {
  std::string text = "must be one of";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i ? ", \"" : " \"") + names[i] + "\"";
  return text;
}

namespace {

// A number of `node` within `range`, else the words for what is wrong.
std::variant<double, std::string> checked_number(const toml::node& node, const NumberRange& range,
                                                  const KeySchema& key) {
  const std::optional<double> value = node.value<double>();  // integers convert
  if (!value || !(node.is_integer() || node.is_floating_point())) return "must be a number, got " + describe(node);
  const double v = *value;
  if (!std::isfinite(v) && !(range.allow_infinite && std::isinf(v)))
    return "must be a finite number, got " + describe(node);
  const bool low = range.lo_open ? !(v > range.lo) : !(v >= range.lo);
  if (std::isnan(v) || low || v > range.hi) return "must be " + range_text(key) + ", got " + describe(node);
  return v;
}

}  // namespace

double TableReader::number(std::string_view key) {
  const KeySchema& k = schema(key);
  const toml::node* node = value_or_default(key);
  if (!node) throw std::logic_error("the schema has no default for " + k.path);
  const auto v = checked_number(*node, k.range, k);
  if (const std::string* what = std::get_if<std::string>(&v)) fail(*node, key, *what);
  return std::get<double>(v);
}

std::optional<double> TableReader::optional_number(std::string_view key) {
  if (!value_or_default(key)) return std::nullopt;
  return number(key);
}

int TableReader::integer(std::string_view key) {
  const KeySchema& k = schema(key);
  const toml::node* node = value_or_default(key);
  if (!node) throw std::logic_error("the schema has no default for " + k.path);
  if (!node->is_integer()) fail(*node, key, "must be an integer, got " + describe(*node));
  const std::int64_t v = node->as_integer()->get();
  if (double(v) < k.range.lo || double(v) > k.range.hi) fail(*node, key, "must be " + range_text(k) + ", got " + describe(*node));
  return int(v);
}

std::optional<int> TableReader::optional_integer(std::string_view key) {
  if (!value_or_default(key)) return std::nullopt;
  return integer(key);
}

bool TableReader::boolean(std::string_view key) {
  const toml::node* node = value_or_default(key);
  if (!node) throw std::logic_error("the schema has no default for " + schema(key).path);
  if (!node->is_boolean()) fail(*node, key, "must be true or false, got " + describe(*node));
  return node->as_boolean()->get();
}

std::optional<bool> TableReader::optional_boolean(std::string_view key) {
  if (!value_or_default(key)) return std::nullopt;
  return boolean(key);
}

std::string TableReader::string(std::string_view key) {
  const toml::node* node = value_or_default(key);
  if (!node) return "";
  if (!node->is_string()) fail(*node, key, "must be a string, got " + describe(*node));
  return node->as_string()->get();
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  if (!value_or_default(key)) return std::nullopt;
  return string(key);
}

std::vector<double> TableReader::numbers(std::string_view key) {
  const KeySchema& k = schema(key);
  const toml::node* node = value_or_default(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  const std::size_t count = k.count;
  const std::string expected =
      count ? "an array of " + std::to_string(count) + " numbers" : std::string("an array of numbers");
  if (!array || (count && array->size() != count))
    fail(*node, key, "must be " + expected + ", got " + describe(*node));
  std::vector<double> out;
  for (const toml::node& element : *array) {
    const auto v = checked_number(element, k.range, k);
    if (const std::string* what = std::get_if<std::string>(&v))
      fail(element, key, "must be " + expected + ", each " + range_text(k) + "; an element " + what->substr(what->find("got ") + 4));
    out.push_back(std::get<double>(v));
  }
  return out;
}

std::vector<std::string> TableReader::strings(std::string_view key) {
  const KeySchema& k = schema(key);
  const toml::node* node = value_or_default(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  if (!array) fail(*node, key, "must be an array of strings, got " + describe(*node));
  std::vector<std::string> out;
  for (const toml::node& element : *array) {
    if (!element.is_string()) fail(element, key, "must be an array of strings, got an element " + describe(element));
    const std::string& name = element.as_string()->get();
    if (!k.choices.empty() && std::find(k.choices.begin(), k.choices.end(), name) == k.choices.end())
      fail(element, key, "must name " + choice_error(k.choices).substr(5) + ", got \"" + name + "\"");
    out.push_back(name);
  }
  return out;
}

std::optional<Vec3> TableReader::read_vector(std::string_view key, const toml::node& node) {
  const KeySchema& k = schema(key);
  const toml::array* array = node.as_array();
  bool numeric = array && array->size() == 3;
  for (std::size_t i = 0; numeric && i < 3; ++i) numeric = (*array)[i].is_integer() || (*array)[i].is_floating_point();
  if (!numeric) fail(node, key, "must be [x, y, z], got " + describe(node));
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    v[Eigen::Index(i)] = *(*array)[i].value<double>();
    if (!(std::fabs(v[Eigen::Index(i)]) <= kLargestCoordinate))
      fail((*array)[i], key,
           "must have coordinates within ±1e17 (the ray tracer's single-precision range), got " + describe((*array)[i]));
  }
  if (k.type == KeyType::direction && v.norm() == 0.0) fail(node, key, "must not be zero");
  return v;
}

Vec3 TableReader::vector(std::string_view key) {
  const toml::node* node = value_or_default(key);
  if (!node) throw std::logic_error("the schema has no default for " + schema(key).path);
  return *read_vector(key, *node);
}

std::optional<Vec3> TableReader::optional_vector(std::string_view key) {
  const toml::node* node = value_or_default(key);
  if (!node) return std::nullopt;
  return read_vector(key, *node);
}

Rgb TableReader::color(std::string_view key) {
  const KeySchema& k = schema(key);
  const toml::node* node = value_or_default(key);
  if (!node) throw std::logic_error("the schema has no default for " + k.path);
  if (const auto* s = node->as_string()) {
    const std::string& hex = s->get();
    unsigned r = 0, g = 0, b = 0;
    if (hex.size() == 7 && hex[0] == '#' && std::sscanf(hex.c_str() + 1, "%2x%2x%2x", &r, &g, &b) == 3)
      return {float(r) / 255.0f, float(g) / 255.0f, float(b) / 255.0f};
    fail(*node, key, "must be \"#rrggbb\" or [r, g, b], got " + describe(*node));
  }
  const toml::array* array = node->as_array();
  if (!array || array->size() != 3) fail(*node, key, "must be \"#rrggbb\" or [r, g, b], got " + describe(*node));
  std::array<float, 3> rgb{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::optional<double> c = (*array)[i].value<double>();
    if (!c || !(*c >= 0.0 && *c <= 1.0))
      fail((*array)[i], key, "must be [r, g, b] with components in [0, 1], got " + describe((*array)[i]));
    rgb[i] = float(*c);
  }
  return {rgb[0], rgb[1], rgb[2]};
}

TableReader TableReader::table(std::string_view key) {
  static const toml::table empty;
  const toml::node* node = lookup(key);
  if (!node) return TableReader(empty, path(key), where_);
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
  const toml::node* node = value_or_default(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  if (!array) fail(*node, key, "must be an array of [x, y, z] points, got " + describe(*node));
  std::vector<Vec3> out;
  for (const toml::node& element : *array) {
    if (!element.is_array()) fail(element, key, "must be an array of [x, y, z] points, got an element " + describe(element));
    out.push_back(*read_vector(key, element));
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
    const std::string hint = nearest_key_hint(schema_prefix_.empty() ? std::string(key.str()) : schema_prefix_ + "." + std::string(key.str()));
    throw SceneError(where + ": unknown key " + path(key.str()) +
                     (hint.empty() ? known_list.empty() ? std::string() : " (known here: " + known_list + ")" : hint));
  }
}

}  // namespace hsb

#include "renderer/scene/toml_text.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

namespace hsb {
namespace {

struct Leaf {
  toml::source_position at;
  std::string path;
  const toml::node* node;
};

void collect(const toml::table& table, const std::string& prefix, std::vector<Leaf>& out) {
  for (const auto& [key, node] : table) {
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const toml::table* sub = node.as_table())
      collect(*sub, path, out);
    else
      out.push_back({key.source().begin, path, &node});
  }
}

}  // namespace

std::string toml_text(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) {
    char text[40];
    std::snprintf(text, sizeof text, "%.15g", f->get());
    std::string s = text;
    if (s.find_first_of(".eina") == std::string::npos) s += ".0";  // stays a float
    return s;
  }
  std::ostringstream out;
  node.visit([&](const auto& v) { out << v; });
  return out.str();
}

void for_each_leaf(const toml::table& table, const std::string& prefix,
                   const std::function<void(const std::string& path, const toml::node& node)>& leaf) {
  std::vector<Leaf> leaves;
  collect(table, prefix, leaves);
  std::stable_sort(leaves.begin(), leaves.end(), [](const Leaf& a, const Leaf& b) { return a.at < b.at; });
  for (const Leaf& l : leaves) leaf(l.path, *l.node);
}

toml::table* table_at_path(toml::table& root, std::string_view path) {
  toml::table* table = &root;
  for (std::size_t start = 0; table && start < path.size();) {
    const std::size_t dot = std::min(path.find('.', start), path.size());
    const std::string part(path.substr(start, dot - start));
    if (!table->contains(part)) table->insert(part, toml::table{});
    table = (*table)[part].as_table();
    start = dot + 1;
  }
  return table;
}

}  // namespace hsb

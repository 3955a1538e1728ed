#pragma once
// TOML values as text that --set reads back, and tables flattened to
// dotted key paths: how a [sweep] table and a [[panel]] table turn into
// overrides of the scene they belong to.

#include <toml++/toml.h>

#include <functional>
#include <string>

namespace hsb {

// A value as TOML text; a number as short as it was written (0.1, not
// 0.10000000000000001), since it may name an image.
std::string toml_text(const toml::node& node);

// Calls `leaf(path, node)` for every value under `table` that is not
// itself a table, its path dotted from `prefix` ("glyphs.spacing" = 0.1
// and [x.glyphs] spacing = 0.1 give the same path), in the order the
// values appear in the file (toml++ keeps tables sorted by key).
void for_each_leaf(const toml::table& table, const std::string& prefix,
                   const std::function<void(const std::string& path, const toml::node& node)>& leaf);

}  // namespace hsb

#pragma once
// What one `hsb render` call renders: every scene given, times every value
// of every swept key, and the share of that a cluster node takes.
//
// Sweeps: a --set whose value lists several values at its top level
// ("glyphs.spacing=0.02,0.05,0.1"; commas inside [ ], { } or quotes do
// not split) renders one image per value; a scene's [sweep] table does the
// same from the file ("glyphs.spacing" = [0.02, 0.05, 0.1]). Several swept
// keys give every combination. Each image is named after its values.
//
// Shards: item i (counting from 0, in the order above) belongs to shard
// (i mod N) + 1 of N, so N machines given 1/N … N/N render every item
// exactly once with no coordinator.

#include <string>
#include <vector>

namespace hsb {

struct BatchItem {
  std::string scene;                   // a scene or data file
  std::vector<std::string> overrides;  // --set key=value, then this item's swept values
  std::string variant;                 // its swept values, "glyphs.spacing=0.02"; "" without sweeps
};

// The values of one --set value: several for a sweep, else the value itself.
std::vector<std::string> split_sweep(const std::string& value);

// Every item of the batch, in order: scene by scene, then the product of
// the --set sweeps and the scene's own [sweep] table (last key fastest).
// A scene that cannot be read is one item; its error comes when it renders.
std::vector<BatchItem> expand_batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides);

struct Shard {
  int index = 1, count = 1;  // 1 ≤ index ≤ count
};

// "K/N"; throws std::invalid_argument with a message for anything else.
Shard parse_shard(const std::string& text);

// The items of `shard`: those at positions i with i mod N = K − 1.
std::vector<BatchItem> shard_items(const std::vector<BatchItem>& items, Shard shard);

// `file` with the variant before its extension: "fig09.png" and
// "glyphs.spacing=0.02" give "fig09_glyphs.spacing=0.02.png"; characters a
// file name should not hold become '_'.
std::string file_for_variant(const std::string& file, const std::string& variant);

}  // namespace hsb

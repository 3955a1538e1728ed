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

#include <cstddef>
#include <string>
#include <vector>

#include "renderer/app/series_scale.h"

namespace hsb {

struct BatchItem {
  std::string scene;                   // a scene or data file
  std::vector<std::string> overrides;  // --set key=value, then this item's swept values
  std::string variant;                 // its swept values, "glyphs.spacing=0.02"; "" without sweeps
  std::string error;                   // why it cannot render (file:line:column: ...), or ""
  // The overrides that came from the scene's [sweep] table, each with the
  // file:line:column of its value there: an error about one names that
  // place, not a --set the user never typed (see located_error()).
  std::vector<std::pair<std::string, std::string>> sweep_origins;
  // A step of a time series whose steps the batch made (one image per
  // step): every step, to share one glyph scale and colour range
  // (series_scale.h). Empty otherwise.
  std::vector<SeriesMember> series;
};

// `message` with a leading "--set KEY=VALUE: " that names one of the
// item's sweep values replaced by where that value stands in the scene.
std::string located_error(const BatchItem& item, const std::string& message);

// The values of one --set value: several for a sweep, else the value itself.
std::vector<std::string> split_sweep(const std::string& value);

struct Shard {
  int index = 1, count = 1;  // 1 ≤ index ≤ count
};

// "K/N"; throws std::invalid_argument with a message for anything else.
Shard parse_shard(const std::string& text);

// Every item of the batch, in order: scene by scene, then the product of
// the --set sweeps and the scene's own [sweep] table (last key fastest).
// Items are made when asked for, never all at once: four swept keys of a
// hundred values each are 10⁸ items, and a cluster node takes its share of
// them by position. A scene that cannot be read is one item; its error
// comes when it renders. A sweep with no values is one item that carries
// its error.
class Batch {
 public:
  // Throws std::invalid_argument when the items would not fit a count.
  // `as_series`: the scenes given are the steps of one series (--series),
  // sharing one glyph scale and colour range; they must make the same
  // number of images (the same sweeps), or it throws.
  Batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides, bool as_series = false);

  std::size_t size() const { return size_; }
  BatchItem item(std::size_t position) const;

  // How many items `shard` holds, and the position of its j-th: shard K of
  // N holds the positions i with i mod N = K − 1.
  std::size_t shard_size(Shard shard) const;
  static std::size_t shard_position(Shard shard, std::size_t j) {
    return std::size_t(shard.index - 1) + j * std::size_t(shard.count);
  }

 private:
  struct SweptKey {
    std::string key;
    std::vector<std::string> values;  // each as TOML text
    std::vector<std::string> where;   // each value's file:line:column; empty for --set sweeps
  };
  struct Scene {
    std::string path;
    std::vector<SweptKey> swept;  // the --set sweeps, then the scene's [sweep] table
    std::string error;
    std::size_t first = 0, count = 1;  // its items' positions
    bool series = false;  // its first swept key is the data.step the batch added
  };
  // The overrides of `scene`'s item `offset` (its position within the
  // scene), and the variant they make.
  std::vector<std::string> overrides_at(const Scene& scene, std::size_t offset, BatchItem* item) const;
  // What shares one scale with `scene`'s item `offset`: that item at every
  // step of its own series, and at every scene of a --series.
  std::vector<SeriesMember> series_of(const Scene& scene, std::size_t offset) const;
  std::vector<std::string> fixed_;  // the --set values that are not sweeps
  std::vector<Scene> scenes_;
  std::size_t size_ = 0;
  bool as_series_ = false;
};

// Every item, in order (for a batch known to be small).
std::vector<BatchItem> expand_batch(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides,
                                    bool as_series = false);

// `file` with the variant before its extension: "fig09.png" and
// "glyphs.spacing=0.02" give "fig09_glyphs.spacing=0.02.png"; characters a
// file name should not hold become '_'.
std::string file_for_variant(const std::string& file, const std::string& variant);

}  // namespace hsb

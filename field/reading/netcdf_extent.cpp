#include "field/reading/netcdf_extent.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "field/reading/data_error.h"

namespace hsb {
namespace {

constexpr std::uint64_t most = std::numeric_limits<std::uint64_t>::max();

// a × b, or the most a std::uint64_t holds where that overflows: no file
// is that large, so a product that overflows is one the file lacks.
std::uint64_t times(std::uint64_t a, std::uint64_t b) { return a != 0 && b > most / a ? most : a * b; }
std::uint64_t plus(std::uint64_t a, std::uint64_t b) { return b > most - a ? most : a + b; }
std::uint64_t padded(std::uint64_t n) { return n % 4 == 0 ? n : plus(n, 4 - n % 4); }

// The header's bytes, read as the parse needs them (an Exodus header is a
// few kilobytes; the data after it is never read here).
class HeaderBytes {
 public:
  HeaderBytes(const std::string& path, std::uint64_t size) : in_(path, std::ios::binary), path_(path), size_(size) {}

  // The next `n` bytes. Throws DataError where the file ends before them.
  const unsigned char* take(std::uint64_t n) {
    if (n > size_ - at_)
      throw DataError(path_ + ": the file is cut short: its netCDF header runs past its end (" +
                      std::to_string(size_) + " bytes)");
    if (at_ + n > bytes_.size()) {
      const std::uint64_t had = bytes_.size();
      bytes_.resize(std::size_t(std::min(size_, std::max(at_ + n, 2 * had + 65536))));
      in_.seekg(std::streamoff(had));
      in_.read(reinterpret_cast<char*>(bytes_.data() + had), std::streamsize(bytes_.size() - had));
      if (std::uint64_t(in_.gcount()) != bytes_.size() - had)
        throw DataError(path_ + ": cannot read its netCDF header");
    }
    const unsigned char* at = bytes_.data() + at_;
    at_ += n;
    return at;
  }
  // A big-endian whole number of `width` bytes (4 or 8), as netCDF stores them.
  std::uint64_t number(int width) {
    const unsigned char* b = take(std::uint64_t(width));
    std::uint64_t n = 0;
    for (int i = 0; i < width; ++i) n = n << 8 | b[i];
    return n;
  }
  void skip(std::uint64_t n) { take(n); }

 private:
  std::ifstream in_;
  std::string path_;
  std::uint64_t size_ = 0, at_ = 0;
  std::vector<unsigned char> bytes_;
};

// The sizes of netCDF's types (NC_BYTE ... NC_UINT64), 0 for none.
std::uint64_t type_size(std::uint64_t type) {
  static const std::uint64_t sizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
  return type < std::size(sizes) ? sizes[type] : 0;
}

// The widths of the header's numbers in one version of the format.
struct Widths {
  int count;   // NON_NEG: lengths, counts, sizes
  int offset;  // OFFSET: where a variable's data begins
};

// A list's element count: 0 for an absent list, nothing for a tag that is
// neither absent nor `tag`.
std::optional<std::uint64_t> list_size(HeaderBytes& h, const Widths& w, std::uint64_t tag) {
  const std::uint64_t found = h.number(4);
  const std::uint64_t count = h.number(w.count);
  if (found == tag || (found == 0 && count == 0)) return count;
  return std::nullopt;
}

void skip_name(HeaderBytes& h, const Widths& w) { h.skip(padded(h.number(w.count))); }

// An attribute list; false for a type this does not know.
bool skip_attributes(HeaderBytes& h, const Widths& w) {
  const std::optional<std::uint64_t> count = list_size(h, w, 0x0C);
  if (!count) return false;
  for (std::uint64_t i = 0; i < *count; ++i) {
    skip_name(h, w);
    const std::uint64_t size = type_size(h.number(4));
    if (size == 0) return false;
    h.skip(padded(times(h.number(w.count), size)));
  }
  return true;
}

// One variable's place: where its data begins, how many bytes it has (in
// each record, for a record variable).
struct Variable {
  std::uint64_t begin = 0;
  std::uint64_t bytes = 0;
  bool record = false;
};

}  // namespace

std::optional<NetcdfExtent> netcdf_classic_extent(const std::string& path) {
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error || size < 4) return std::nullopt;
  HeaderBytes h(path, size);
  const unsigned char* magic = h.take(4);
  if (magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F' || (magic[3] != 1 && magic[3] != 2 && magic[3] != 5))
    return std::nullopt;
  // CDF-1: 32-bit offsets; CDF-2 (64-bit offset): 64-bit; CDF-5 (64-bit data): 64-bit counts too.
  const Widths w{magic[3] == 5 ? 8 : 4, magic[3] == 1 ? 4 : 8};
  const std::uint64_t records = h.number(w.count);
  const bool streaming = records == (w.count == 8 ? most : 0xFFFFFFFFu);  // a count left to the file's size

  const std::optional<std::uint64_t> dimension_count = list_size(h, w, 0x0A);
  if (!dimension_count) return std::nullopt;
  std::vector<std::uint64_t> dimensions;  // 0: the record dimension
  for (std::uint64_t i = 0; i < *dimension_count; ++i) {
    skip_name(h, w);
    dimensions.push_back(h.number(w.count));
  }
  if (!skip_attributes(h, w)) return std::nullopt;

  const std::optional<std::uint64_t> variable_count = list_size(h, w, 0x0B);
  if (!variable_count) return std::nullopt;
  std::vector<Variable> variables;
  for (std::uint64_t i = 0; i < *variable_count; ++i) {
    skip_name(h, w);
    Variable v;
    std::uint64_t values = 1;
    const std::uint64_t rank = h.number(w.count);
    for (std::uint64_t d = 0; d < rank; ++d) {
      const std::uint64_t id = h.number(w.count);
      if (id >= dimensions.size()) return std::nullopt;
      if (d == 0 && dimensions[std::size_t(id)] == 0) v.record = true;
      else values = times(values, dimensions[std::size_t(id)]);
    }
    if (!skip_attributes(h, w)) return std::nullopt;
    const std::uint64_t value_size = type_size(h.number(4));
    if (value_size == 0) return std::nullopt;
    h.skip(std::uint64_t(w.count));  // vsize: capped for large variables, so computed instead
    v.begin = h.number(w.offset);
    v.bytes = times(values, value_size);
    variables.push_back(v);
  }

  // A record holds every record variable, each padded to 4 bytes, but for
  // a file of one record variable (the netCDF library's layout).
  std::uint64_t record_size = 0;
  int record_variables = 0;
  for (const Variable& v : variables)
    if (v.record) record_size = plus(record_size, padded(v.bytes)), ++record_variables;
  if (record_variables == 1)
    for (const Variable& v : variables)
      if (v.record) record_size = v.bytes;

  // The end of the fixed data, and of each record's data.
  std::uint64_t fixed_end = 0, record_end = 0;
  for (const Variable& v : variables) {
    std::uint64_t& end = v.record ? record_end : fixed_end;
    end = std::max(end, plus(v.begin, v.bytes));
  }
  NetcdfExtent extent;
  extent.file_size = size;
  extent.records_held = record_variables == 0 || record_size == 0 ? records
                        : size < record_end                       ? 0
                                                                  : (size - record_end) / record_size + 1;
  extent.records = streaming ? extent.records_held : records;
  extent.records_held = std::min(extent.records_held, extent.records);
  extent.bytes = fixed_end;
  if (record_variables > 0 && extent.records > 0)
    extent.bytes = std::max(extent.bytes, plus(record_end, times(extent.records - 1, record_size)));
  return extent;
}

}  // namespace hsb

#pragma once
// How many bytes a netCDF classic file (CDF-1, CDF-2 or CDF-5: the Exodus
// II that SEACAS, MOOSE, Cubit and VTK write) must have, from what its
// header declares. The netCDF library reads past a file's end as zeros
// (its fill value), without an error: a file cut short, or a header that
// claims more time steps than the file holds, reads as a field of zeros.
// Internal to field/.

#include <cstdint>
#include <optional>
#include <string>

namespace hsb {

struct NetcdfExtent {
  std::uint64_t bytes = 0;    // the least size that holds every variable at every record
  std::uint64_t records = 0;  // the records (an Exodus file's time steps) the header declares
  // Of those, how many the file's bytes hold whole (all of them when it
  // has `bytes`).
  std::uint64_t records_held = 0;
  std::uint64_t file_size = 0;
};

// The extent of the netCDF classic file at `path`; nothing for a file of
// another kind (netCDF-4, which is HDF5 inside) or a header this does not
// follow (the netCDF library then says what is wrong). Throws DataError
// for a file cut short inside its header.
std::optional<NetcdfExtent> netcdf_classic_extent(const std::string& path);

}  // namespace hsb

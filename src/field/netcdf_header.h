// The counts in a classic netCDF header (CDF-1, CDF-2 64-bit offset, CDF-5) checked
// against the file's length with plain reads, before libnetcdf opens the file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace sm::field {

/// nc_open allocates what a classic header declares (arrays of dimensions, attributes,
/// variables and dimension ids, attribute values) before it looks at the file's length,
/// so a hostile header of a few hundred bytes asks for gigabytes. This walks the header
/// (layout: the netCDF classic format specification) and refuses it when a list's
/// declared count times the fewest bytes one item takes, or an attribute's values,
/// exceed the bytes left in the file. Returns the reason, or nullopt when every count
/// fits. A variable or attribute type outside the format's types is refused too
/// (libnetcdf 4.9 divides by zero on NC_STRING in a CDF-5 header), and so is a header
/// the file ends inside (libnetcdf decodes past the end). Files that are not classic
/// netCDF (HDF5-based netCDF-4, anything else) and headers libnetcdf refuses on its own
/// (a non-empty list with the wrong tag) are left to nc_open.
std::optional<std::string> check_netcdf_header_counts(const std::filesystem::path& file);

}  // namespace sm::field

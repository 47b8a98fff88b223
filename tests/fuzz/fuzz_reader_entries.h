// Entry functions of the file-reader fuzz targets, one per reader, shared by the
// libFuzzer binaries (fuzz_<reader>) and the corpus replay test (fuzz_readers_replay,
// any compiler). Each reads one input, accepts a clean error, checks what a successful
// read returns (aborting on a violation, so the fuzzer reports it) and never throws.
#pragma once

#include <cstddef>
#include <cstdint>

namespace sm::fuzz {

void run_gshhs_input(const std::uint8_t* data, std::size_t size);
void run_lonlat_text_input(const std::uint8_t* data, std::size_t size);
/// The first byte picks the coordinate kind (mod 4: lonlat, lonlat_degrees, utm,
/// cartesian) and, for UTM, the zone (1 + byte / 4 mod 60); the rest is the text.
void run_loops2_input(const std::uint8_t* data, std::size_t size);
/// Input = 8-byte header (two little-endian uint32: .shp length, .shx length) then the
/// .shp bytes, the .shx bytes and, for what remains, the .dbf. A .shx length of 0
/// writes no .shx, so the index is rebuilt (read_shapefile). Lengths past the end of the
/// input are cut to what is there.
void run_shapefile_input(const std::uint8_t* data, std::size_t size);
/// The input is written to a temporary .nc file and read with read_netcdf_grid.
void run_netcdf_input(const std::uint8_t* data, std::size_t size);
void run_esri_input(const std::uint8_t* data, std::size_t size);
/// The input is written to a temporary .nc file and read with read_gshhg_binned (every
/// level, then the grounding line in a Region across the dateline).
void run_gshhg_binned_input(const std::uint8_t* data, std::size_t size);

}  // namespace sm::fuzz

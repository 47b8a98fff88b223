#!/bin/sh
# Regenerates the small hostile grids of this folder from small.cdl (ncgen and
# coreutils only; run from tests/data/grids).
set -eu
ncgen -k classic -o small.nc small.cdl
ncgen -k nc4 -o small_nc4.nc small.cdl
# Cut to half their bytes: classic data past the cut would read as zeros.
head -c $(( $(wc -c < small.nc) / 2 )) small.nc > truncated_half.nc
head -c $(( $(wc -c < small_nc4.nc) / 2 )) small_nc4.nc > truncated_half_nc4.nc
# Cut inside the values of z (the last 64 of its 128 bytes): the header and the
# coordinates are whole, and libnetcdf opens the file.
head -c $(( $(wc -c < small.nc) - 64 )) small.nc > truncated_z.nc
# Packing attributes that cannot be right.
sed 's/z:scale_factor = 1\. ;/z:scale_factor = 1e300 ;/' small.cdl | ncgen -k classic -o scale_1e300.nc
sed 's/z:add_offset = 0\. ;/z:add_offset = NaN ;/' small.cdl | ncgen -k classic -o offset_nan.nc
sed 's/z:scale_factor = 1\. ;/z:scale_factor = 0. ;/' small.cdl | ncgen -k classic -o scale_zero.nc
# Latitudes past the pole.
sed 's/ lat = 40, 41, 42, 43, 44, 45, 46 ;/ lat = 87, 88, 89, 90, 91, 92, 93 ;/' small.cdl | ncgen -k classic -o lat_past_pole.nc
# Depth grids for a list of grids by priority that disagree: units m vs km, and
# latitude_longitude vs transverse_mercator.
ncgen -k classic -o depth_m.nc depth_m.cdl
ncgen -k classic -o depth_km.nc depth_km.cdl
ncgen -k classic -o depth_utm.nc depth_utm.cdl

#!/usr/bin/python3
"""A grid axis that cannot be read as regular is an error located at the script statement
that loads the grid: netCDF bathymetry whose longitude or latitude axis holds a
NaN, goes back, repeats a value, or is unevenly spaced, and a structured grid (Field
Structured) whose axis has a NaN spacing. Each run exits 1 with
"g.geo:LINE:COL: error: ..." naming the file, the axis and the index, and writes no
mesh; an evenly decreasing axis is a valid grid and the run writes its mesh.

    grid_axes.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed); 77: ncgen is missing.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile

from checks import check, exit_status, main_with_binary


CDL = """netcdf g {{
dimensions:
	lon = 5 ;
	lat = 4 ;
variables:
	double lon(lon) ;
		lon:units = "degrees_east" ;
	double lat(lat) ;
		lat:units = "degrees_north" ;
	double z(lat, lon) ;
data:
 lon = {lon} ;
 lat = {lat} ;
 z = -100, -100, -100, -100, -100, -100, -100, -100, -100, -100,
     -100, -100, -100, -100, -100, -100, -100, -100, -100, -100 ;
}}
"""
LON = "0, 1, 2, 3, 4"
LAT = "40, 41, 42, 43"

# The statement that loads the grid is line 3; the mesh after it is what -o would write.
SCRIPT = """Field[1] = {kind};
x = 0;
Field[1].FileName = "{grid}";
h = FieldValue(1, 0.5, 0.5, 0);
Point(1) = {{0, 0, 0, 0.3}}; Point(2) = {{1, 0, 0, 0.3}}; Point(3) = {{1, 1, 0, 0.3}};
Line(1) = {{1, 2}}; Line(2) = {{2, 3}}; Line(3) = {{3, 1}};
Curve Loop(1) = {{1, 2, 3}}; Plane Surface(1) = {{1}};
"""

CASES = [
    # name, lon, lat, what the message must hold
    ("lon_nan", "0, 1, NaN, 3, 4", LAT, "longitude axis 'lon' holds nan at index 2"),
    ("lat_nan", LON, "40, 41, 42, NaN", "latitude axis 'lat' holds nan at index 3"),
    ("lon_back", "0, 1, 2, 1.5, 4", LAT, "longitude axis 'lon' is not monotonic: value 1.5 at index 3 after 2 at index 2"),
    ("lat_back", LON, "43, 42, 43, 40", "latitude axis 'lat' is not monotonic: value 43 at index 2 after 42 at index 1"),
    ("lon_repeat", "0, 1, 1, 3, 4", LAT, "longitude axis 'lon' repeats the value 1 at index 2 (as index 1)"),
    ("lat_irregular", LON, "40, 41, 42.5, 43", "latitude axis 'lat' is not evenly spaced: value 42.5 at index 2, expected 42"),
    ("lon_irregular", "0, 1, 2, 3, 5", LAT, "longitude axis 'lon' is not evenly spaced: value 1 at index 1, expected 1.25"),
]



def run(stereomesh, d, kind, grid):
    with open(os.path.join(d, "g.geo"), "w") as f:
        f.write(SCRIPT.format(kind=kind, grid=grid))
    out = os.path.join(d, "out.msh")
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([stereomesh, "-2", "g.geo", "-o", "out.msh"], cwd=d, capture_output=True, text=True,
                       timeout=120)
    return r, os.path.exists(out)


def refused(stereomesh, d, name, kind, grid, says):
    r, written = run(stereomesh, d, kind, grid)
    head = r.stderr.splitlines()[0] if r.stderr else ""
    check(r.returncode == 1, f"{name}: exit {r.returncode} (want 1)")
    check(head.startswith("g.geo:3:1: error: ") and grid in head and says in head,
          f"{name}: 'g.geo:3:1: error: ... {grid} ... {says}' (got {head!r})")
    check(not written, f"{name}: no output file")


def main(stereomesh):
    if shutil.which("ncgen") is None:
        print("ncgen is missing")
        return 77
    with tempfile.TemporaryDirectory() as d:
        def make(name, lon, lat):
            grid = name + ".nc"
            subprocess.run(["ncgen", "-k", "classic", "-o", os.path.join(d, grid)], check=True, text=True,
                           input=CDL.format(lon=lon, lat=lat))
            return grid

        for name, lon, lat, says in CASES:
            refused(stereomesh, d, name, "Bathymetry", make(name, lon, lat), says)

        # Evenly decreasing axes (north to south, east to west) are regular grids.
        r, written = run(stereomesh, d, "Bathymetry", make("both_down", "4, 3, 2, 1, 0", "43, 42, 41, 40"))
        check(r.returncode == 0 and written, f"decreasing axes: a valid grid, mesh written ({r.stderr[-300:]!r})")

        # A structured grid's axes are origin + k * spacing: a NaN spacing names its axis.
        # (binary, Gmsh's default format: 6 doubles, 3 int32, then the values).
        with open(os.path.join(d, "s.bin"), "wb") as f:
            f.write(struct.pack("<6d3i", 0, 0, 0, 0.5, float("nan"), 1, 3, 3, 1) + struct.pack("<9d", *[1.0] * 9))
        refused(stereomesh, d, "structured_nan", "Structured", "s.bin", "axis y has origin 0 and spacing nan")
    return exit_status()


if __name__ == "__main__":
    main_with_binary(main)

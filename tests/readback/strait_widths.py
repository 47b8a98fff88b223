#!/usr/bin/python3
"""Straits as wide as they are: the Danish straits meshed from the system's
GSHHG at full resolution (strait_widths_danish.geo, gamma 350 m in the straits), at
DeviationFactor 0 and 0.5. Each strait's width is measured across a fixed great-circle
section, from a point in the water to the nearest bank on either side: in the source
shoreline, read here from GMT's binned netCDF file with netCDF4 (not the project's
importer), and in the mesh, read with Gmsh's own reader (the boundary edges of its
triangles). With DeviationFactor 0.5 the straits at least 3 gamma wide must come out within
10% of their width in the data; the figures of both runs are printed (docs/coastlines.md,
"The curve within a bound of the data").

    strait_widths.py STEREOMESH
Exit 0: the checks hold; 1: a check failed; 77: a reader or the GSHHG file is missing.
"""
import os
import sys
import tempfile

from readback import check, finish, run_script
import gmsh
import netCDF4
import numpy as np

GSHHG = "/usr/share/gmt-gshhg/binned_GSHHS_f.nc"   # what Coastline[1] = GSHHG reads for "f"
BOX = (9.5, 13.2, 54.3, 56.3)                       # the script's Region, W E S N
RADIUS = 6371e3                                     # EarthRadius of stdlib/earth.geo
GAMMA = 350.0                                       # StraitSize of the script, at every section
# name, two ends of the section (lon, lat; the great circle through them, no farther than
# them), and a point of the strait's water on it.
SECTIONS = [
    ("Oresund, Helsingor-Helsingborg", (12.50, 56.04), (12.80, 56.04), (12.66, 56.04)),
    ("Great Belt, East Channel (Sprogo-Halsskov)", (10.80, 55.33), (11.25, 55.33), (11.05, 55.33)),
    ("Great Belt, West Channel (Knudshoved-Sprogo)", (10.80, 55.33), (11.25, 55.33), (10.88, 55.33)),
    ("Little Belt, Middelfart-Snoghoj", (9.73, 55.45), (9.73, 55.58), (9.73, 55.513)),
]


def unit(lon, lat):
    lon, lat = np.radians(lon), np.radians(lat)
    return np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], -1)


def source_segments():
    """The shoreline pieces of the bins meeting BOX, as (p, q) unit vectors of every source
    segment. GMT's layout (the comment of src/coast/read_gshhg_binned.cpp): square bins
    numbered row by row from the North-West; a segment's word holds its point count from
    bit 9; its points are unsigned 1/65535 fractions of the bin side from the bin's
    South-West corner. A shoreline crossing a bin side is cut there into two segments that
    share the crossing point, so the segments' own edges are the whole shoreline and no bin
    side is needed."""
    d = netCDF4.Dataset(GSHHG)
    d.set_auto_mask(False)
    bsize = float(d["Bin_size_in_minutes"][0]) / 60.0
    nx = int(d["N_bins_in_360_longitude_range"][0])
    first = d["Id_of_first_segment_in_a_bin"][:]
    nseg = d["N_segments_in_a_bin"][:]
    info = d["Embedded_npts_levels_exit_entry_for_a_segment"][:].astype(np.int64) & 0xFFFFFFFF
    start = d["Id_of_first_point_in_a_segment"][:]
    rel_lon, rel_lat = d["Relative_longitude_from_SW_corner_of_bin"], d["Relative_latitude_from_SW_corner_of_bin"]
    w, e, s, n = BOX
    p, q = [], []
    for row in range(int((90 - n) // bsize), int((90 - s) // bsize) + 1):
        for col in range(int(w // bsize), int(e // bsize) + 1):
            b = row * nx + col
            for seg in range(int(first[b]), int(first[b]) + int(nseg[b])):
                count, at = int(info[seg] >> 9), int(start[seg])
                dx = rel_lon[at:at + count].astype(np.int64) & 0xFFFF
                dy = rel_lat[at:at + count].astype(np.int64) & 0xFFFF
                pts = unit(col * bsize + dx * (bsize / 65535.0), 90.0 - (row + 1) * bsize + dy * (bsize / 65535.0))
                p.append(pts[:-1])
                q.append(pts[1:])
    d.close()
    return np.vstack(p), np.vstack(q)


def mesh_boundary(path):
    """The mesh's nodes (unit vectors) and the sides of its triangles used by one triangle
    only: the coast and the open boundary as meshed, whatever the file's line elements."""
    gmsh.initialize(["-v", "0"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    _, nodes = gmsh.model.mesh.getElementsByType(2)
    gmsh.finalize()
    xyz = xyz.reshape(-1, 3)
    xyz /= np.linalg.norm(xyz, axis=1)[:, None]
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    tri = index[nodes.astype(np.int64)].reshape(-1, 3)
    sides = np.sort(np.vstack([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    sides, uses = np.unique(sides, axis=0, return_counts=True)
    return xyz, tri, sides[uses == 1]


def width(a, b, mid, p, q):
    """Metres between the nearest crossings of the segments p[i]q[i] with the great circle
    a-b on either side of mid, or None when a side has none within the section."""
    nrm = np.cross(a, b)
    nrm /= np.linalg.norm(nrm)
    sp, sq = p @ nrm, q @ nrm
    hit = (sp > 0) != (sq > 0)
    p, q, sp, sq = p[hit], q[hit], sp[hit], sq[hit]
    x = p + (sp / (sp - sq))[:, None] * (q - p)
    x /= np.linalg.norm(x, axis=1)[:, None]
    along = np.arctan2(np.cross(mid, x) @ nrm, x @ mid)   # signed angle from mid
    # within the section: on the arc a-b (the great circle's other crossings are far away)
    on_arc = (np.cross(a, x) @ nrm >= 0) & (np.cross(x, b) @ nrm >= 0)
    ahead, behind = along[on_arc & (along > 0)], along[on_arc & (along < 0)]
    if len(ahead) == 0 or len(behind) == 0:
        return None
    return RADIUS * (ahead.min() - behind.max())


def in_mesh(point, xyz, tri):
    """Whether the unit vector lies in a triangle of the mesh (inside its three great
    circles): a strait closed by the mesh has no water at its section's point."""
    a, b, c = xyz[tri[:, 0]], xyz[tri[:, 1]], xyz[tri[:, 2]]
    s1 = np.einsum("ij,ij->i", np.cross(a, b), np.broadcast_to(point, a.shape))
    s2 = np.einsum("ij,ij->i", np.cross(b, c), np.broadcast_to(point, a.shape))
    s3 = np.einsum("ij,ij->i", np.cross(c, a), np.broadcast_to(point, a.shape))
    return bool(np.any(((s1 >= 0) & (s2 >= 0) & (s3 >= 0)) | ((s1 <= 0) & (s2 <= 0) & (s3 <= 0))))


def main(stereomesh):
    if not os.path.exists(GSHHG):
        print(f"skipped: no {GSHHG} (the gshhg-gmt package)")
        sys.exit(77)
    p, q = source_segments()
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for factor in (0.0, 0.5):
            if not run_script(stereomesh, "strait_widths_danish.geo", out, ["-setnumber", "Deviation", str(factor)],
                              f"the Danish straits meshed at DeviationFactor {factor}"):
                return
            xyz, tri, sides = mesh_boundary(os.path.join(out, "danish_straits.msh"))
            for name, a, b, mid in SECTIONS:
                a, b, mid = unit(*a), unit(*b), unit(*mid)
                data = width(a, b, mid, p, q)
                meshed = width(a, b, mid, xyz[sides[:, 0]], xyz[sides[:, 1]]) if in_mesh(mid, xyz, tri) else None
                rows.append((factor, name, data, meshed))
    print(f"{'DeviationFactor':>15}  {'strait':<46} {'data m':>8} {'mesh m':>8} {'ratio':>6}")
    for factor, name, data, meshed in rows:
        ratio = f"{meshed / data:6.3f}" if data and meshed else "closed"
        print(f"{factor:>15}  {name:<46} {data or 0:8.0f} {meshed or 0:8.0f} {ratio:>6}")
    for factor, name, data, meshed in rows:
        if factor == 0.0:
            check(data is not None, f"{name}: both banks in the source shoreline")
        if factor == 0.5 and data is not None and data >= 3 * GAMMA:
            check(meshed is not None and abs(meshed / data - 1) <= 0.10,
                  f"{name}, DeviationFactor 0.5: mesh width within 10% of the data's {data:.0f} m "
                  f"(at least 3 gamma = {3 * GAMMA:.0f} m)")
    # All four sections are wider than 3 gamma: the bound is checked on each.
    check(sum(1 for f, _, d, _ in rows if f == 0.5 and d and d >= 3 * GAMMA) == len(SECTIONS),
          "every section at least 3 gamma wide in the data")


main(sys.argv[1])
finish()

#!/usr/bin/python3
"""Pictures of a mesh on a sphere that `stereomesh -o X.svg|png` (the whole mesh in lon/lat)
does not draw, for docs/examples.md: the polar view (the PolarSphere's stereographic plane,
north pole in the middle, as the paper's Figure 11) or a lon/lat box (a close-up, such as
the paper's Figure 10). Same colours as stereomesh's pictures: triangles by quality rho from
blue (near 1) through white to red, edges thin blue-grey, curves (coasts and open
boundaries) red. Reads the mesh with Gmsh's reader (python3-gmsh).

usage: mesh_picture.py MESH.msh OUT.svg [--width PX] [--box WEST EAST SOUTH NORTH]
Then: rsvg-convert OUT.svg -o OUT.png && pngquant 64 OUT.png (Debian librsvg2-bin, pngquant).
"""
import sys

import gmsh
import numpy as np


def ramp(t):
    """stereomesh's quality ramp (io/picture.cpp): blue (0) to white (0.5) to red (1)."""
    t = np.clip(t, 0.0, 1.0)
    lo, mid, hi = np.array([49, 54, 149]), np.array([247, 247, 247]), np.array([165, 0, 38])
    s = np.where(t < 0.5, t / 0.5, (t - 0.5) / 0.5)[:, None]
    return np.where((t < 0.5)[:, None], lo + (mid - lo) * s, mid + (hi - mid) * s).round().astype(int)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    width = float(argv[argv.index("--width") + 1]) if "--width" in argv else 1000.0
    gmsh.initialize(["polar_picture", "-v", "0"])
    gmsh.open(argv[1])
    tags, coords, _ = gmsh.model.mesh.getNodes()
    xyz = coords.reshape(-1, 3)
    index = np.zeros(int(tags.max()) + 1, dtype=np.int64)
    index[tags.astype(np.int64)] = np.arange(len(tags))
    tris, lines = [], []
    for dim, out in ((2, tris), (1, lines)):
        types, _, nodes = gmsh.model.mesh.getElements(dim=dim)
        for t, n in zip(types, nodes):
            if t == (2 if dim == 2 else 1):
                out.append(index[n.astype(np.int64)].reshape(-1, dim + 1))
    gmsh.finalize()
    tri = np.concatenate(tris)
    seg = np.concatenate(lines) if lines else np.zeros((0, 2), dtype=np.int64)

    box = [float(v) for v in argv[argv.index("--box") + 1:argv.index("--box") + 5]] if "--box" in argv else None
    if box:
        # Lon/lat degrees, longitudes within 180 degrees of the box's west side (a box may
        # cross the dateline: 150 to 240); elements across the far seam are left out. The
        # x axis is shrunk by the cosine of the box's middle latitude, so shapes there are
        # true (an equirectangular map with that standard parallel).
        lon = np.degrees(np.arctan2(xyz[:, 1], xyz[:, 0]))
        lon = np.mod(lon - box[0] + 180, 360) - 180 + box[0]
        lat = np.degrees(np.arctan2(xyz[:, 2], np.hypot(xyz[:, 0], xyz[:, 1])))
        uv = np.column_stack([lon, lat])
        def near(el):
            x, y = uv[el][..., 0], uv[el][..., 1]
            return ((x.max(axis=1) - x.min(axis=1) < 180) & (x.max(axis=1) >= box[0]) & (x.min(axis=1) <= box[1])
                    & (y.max(axis=1) >= box[2]) & (y.min(axis=1) <= box[3]))
        tri, seg = tri[near(tri)], seg[near(seg)]
        k = np.cos(np.radians(0.5 * (box[2] + box[3])))
        uv[:, 0] *= k
        lo, hi = np.array([box[0] * k, box[2]]), np.array([box[1] * k, box[3]])
    else:
        # Stereographic projection from the south pole onto the plane z = 0 (Gmsh's
        # PolarSphere (u, v) up to a factor), the sphere's radius from the mesh.
        r = np.linalg.norm(xyz[np.unique(tri)], axis=1).mean()
        uv = xyz[:, :2] / (r + xyz[:, 2:3])
        used = np.unique(np.concatenate([tri.ravel(), seg.ravel()]))
        lo, hi = uv[used].min(axis=0), uv[used].max(axis=0)
    curve_w = max(1.5, width / 600.0)
    scale = (width - 2 * curve_w) / (hi[0] - lo[0])
    height = (hi[1] - lo[1]) * scale + 2 * curve_w
    px = np.column_stack([curve_w + (uv[:, 0] - lo[0]) * scale, curve_w + (hi[1] - uv[:, 1]) * scale])

    a, b, c = xyz[tri[:, 0]], xyz[tri[:, 1]], xyz[tri[:, 2]]
    la, lb, lc = (np.linalg.norm(b - c, axis=1), np.linalg.norm(c - a, axis=1), np.linalg.norm(a - b, axis=1))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    s = 0.5 * (la + lb + lc)
    with np.errstate(divide="ignore", invalid="ignore"):
        rho = np.where(area > 0, 8 * area**2 / (s * la * lb * lc), 0.0)
    fill = ramp(1 - rho)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
           f'viewBox="0 0 {width:.2f} {height:.2f}">',
           f'<rect width="{width:.2f}" height="{height:.2f}" fill="#f4f1ea"/>',
           f'<g stroke="#3a5a78" stroke-width="{max(0.15, width / 8000):.3f}" stroke-linejoin="round">']
    for k, t in enumerate(tri):
        p = px[t]
        out.append(f'<path d="M{p[0, 0]:.1f} {p[0, 1]:.1f}L{p[1, 0]:.1f} {p[1, 1]:.1f}L{p[2, 0]:.1f} {p[2, 1]:.1f}Z" '
                   f'fill="#{fill[k, 0]:02x}{fill[k, 1]:02x}{fill[k, 2]:02x}"/>')
    out.append("</g>")
    out.append(f'<g stroke="#b2182b" stroke-width="{curve_w:.2f}" stroke-linecap="round" fill="none">')
    for e in seg:
        p = px[e]
        out.append(f'<path d="M{p[0, 0]:.1f} {p[0, 1]:.1f}L{p[1, 0]:.1f} {p[1, 1]:.1f}"/>')
    out.append("</g></svg>")
    with open(argv[2], "w") as f:
        f.write("\n".join(out) + "\n")
    print(f"{argv[2]}: {len(tri)} triangles, {len(seg)} curve segments, {width:.0f} x {height:.0f} px")


if __name__ == "__main__":
    main(sys.argv)

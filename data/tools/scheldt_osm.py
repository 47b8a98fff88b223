#!/usr/bin/python3
"""Land polygons of the Westerschelde and Zeeschelde up to Antwerp from OpenStreetMap.

Input: an OSM extract in compact JSON (data/PROVENANCE.md, "osm/scheldt_osm.txt"):
  coast: natural=coastline ways, land on the LEFT, Google polyline (precision 1e-5, lat first);
  water: areas by kind (river, dock, harbour, canal, lock, water), each a list of rings.
Output: GMT multi-segment lon/lat text (docs/coastlines.md, "LonLatText"): the land of the
box W/E/S/N as closed counter-clockwise rings, level 1.

  water = the sea side of the coastline ways in the box  U  the kind=river areas
  land  = box - water, holes filled (ponds cut off from the estuary), pieces under
          MIN_AREA_KM2 dropped, simplified to TOLERANCE_DEG.

Only the river areas are water: the OSM coastline stops where the Zeeschelde is mapped as
a river (near the Dutch-Belgian border), so the river areas carry the estuary on to
Antwerp. Docks, harbour basins, canals and locks are left as land: Antwerp's docks and the
Ghent-Terneuzen canal lie behind locks (not tidal), and the few tidal basins are side
pockets a shelf model does not resolve.

Offline only (needs shapely: apt-get install python3-shapely); not a build or test step.
Usage: scheldt_osm.py antwerp.json W E S N > scheldt_osm.txt
"""
import json
import sys

from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import polygonize, unary_union

TOLERANCE_DEG = 5e-5     # ~4 m: far below the 150 m mesh size of the estuary
MIN_AREA_KM2 = 0.01      # islets and slivers no shelf mesh resolves


def decode(s):
    """Google polyline: zigzag varints of 5-bit chunks + 63, lat then lon, 1e-5 degrees."""
    pts, i, lat, lon = [], 0, 0, 0
    while i < len(s):
        vals = []
        for _ in range(2):
            r = sh = 0
            while True:
                b = ord(s[i]) - 63
                i += 1
                r |= (b & 31) << sh
                sh += 5
                if b < 32:
                    break
            vals.append(~(r >> 1) if r & 1 else r >> 1)
        lat += vals[0]
        lon += vals[1]
        pts.append((lon / 1e5, lat / 1e5))
    return pts


def km2(poly):
    # Area in km^2 at the box's latitude (the box spans 0.3 degrees).
    import math
    c = poly.centroid.y
    return poly.area * 111.32 ** 2 * math.cos(math.radians(c))


def main():
    src, w, e, s, n = sys.argv[1], *map(float, sys.argv[2:6])
    d = json.load(open(src))
    frame = box(w, s, e, n)
    coast = [LineString(decode(c)) for c in d["coast"]]
    # Faces of the box cut by the coastline; a face is land when a point just left of a
    # coastline segment on its boundary falls in it, water when a point just right does.
    faces = list(polygonize(unary_union([frame.exterior] + [c.intersection(frame) for c in coast])))
    votes = [0] * len(faces)
    eps = 1e-6
    for c in coast:
        p = list(c.coords)
        for a, b in zip(p, p[1:]):
            mx, my = (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
            dx, dy = b[0] - a[0], b[1] - a[1]
            L = (dx * dx + dy * dy) ** 0.5
            if L == 0 or not frame.contains(Point(mx, my)):
                continue
            left = Point(mx - eps * dy / L, my + eps * dx / L)
            right = Point(mx + eps * dy / L, my - eps * dx / L)
            for k, f in enumerate(faces):
                if f.contains(left):
                    votes[k] += 1
                if f.contains(right):
                    votes[k] -= 1
    sea = unary_union([f for f, v in zip(faces, votes) if v < 0])
    rivers = [Polygon(decode(r)).buffer(0) for wa in d["water"] if wa["k"] == "river" for r in wa["r"]]
    water = unary_union([sea] + rivers).intersection(frame)
    land = frame.difference(water)
    geoms = list(land.geoms) if hasattr(land, "geoms") else [land]
    rings = []
    for g in geoms:
        if g.geom_type != "Polygon" or km2(g) < MIN_AREA_KM2:
            continue
        g = Polygon(g.exterior).simplify(TOLERANCE_DEG, preserve_topology=True)
        if g.exterior.is_ccw is False:
            g = Polygon(list(g.exterior.coords)[::-1])
        rings.append(list(g.exterior.coords)[:-1])
    rings.sort(key=lambda r: (-len(r), r[0]))
    npts = sum(len(r) for r in rings)
    out = sys.stdout
    out.write("# OpenStreetMap (ODbL, (c) OpenStreetMap contributors), Westerschelde + Zeeschelde to Antwerp: "
              "land = box - (sea side of natural=coastline U water=river); cmd: data/tools/scheldt_osm.py "
              "antwerp.json %g %g %g %g\n" % (w, e, s, n))
    out.write("# segments=%d closed=%d open=0 wraps_pole=0 points=%d\n" % (len(rings), len(rings), npts))
    out.write("# columns: lon lat (degrees, WGS84); segment header: > key=value ...\n")
    for i, r in enumerate(rings, 1):
        out.write("> seg=%d level=1 npts=%d closed=1 wraps_pole=0 orientation=ccw\n" % (i, len(r)))
        for x, y in r:
            out.write("%.5f %.5f\n" % (x, y))
    sys.stderr.write("%d rings, %d points; sea faces %d of %d; %d river areas\n"
                     % (len(rings), npts, sum(v < 0 for v in votes), len(faces), len(rivers)))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The SVG pictures read back with Python's XML parser (a reader that is not ours): the
legend names every physical curve group (XML-escaped names come back as written), the colour
bar's title gives its units, the worst triangles are circled, and a box zoom draws only the
triangles that reach into the box, in a frame of the box's shape.

    picture_legend.py STEREOMESH
Exit 0: all checks hold; 1: a check failed (each is printed).
"""
import re
import sys
import tempfile
import xml.etree.ElementTree as ET

from readback import check, finish, run_script

NS = "{http://www.w3.org/2000/svg}"


def group(root, gid):
    return next((g for g in root.iter(NS + "g") if g.get("id") == gid), None)


def texts(g):
    return [t.text for t in g.iter(NS + "text")] if g is not None else []


def points(el):
    return [tuple(map(float, p.split(","))) for p in el.get("points").split()]


def main(stereomesh):
    with tempfile.TemporaryDirectory() as out:
        if not run_script(stereomesh, "picture_legend.geo", out, what="stereomesh drew the pictures"):
            finish()
        whole = ET.parse(f"{out}/whole.svg").getroot()
        zoom = ET.parse(f"{out}/zoom.svg").getroot()
        with open(f"{out}/whole.svg", "rb") as f:
            whole_bytes = f.read()

    legend = texts(group(whole, "legend"))
    print("legend:", legend)
    check(legend[0].startswith("quality rho"), "the quality key's title names rho")
    check(any(t.startswith("below the floor 0.3: ") for t in legend), "the key names the quality floor's class")
    check(any(t.startswith("worst 1%: ") for t in legend), "the key names the worst 1%")
    for name in ("coast", "open", "river & <mouth>"):
        check(name in legend, f"the legend names the physical curve group '{name}'")
    worst = [t for t in legend if t.startswith("the 3 worst triangles (rho ")]
    check(len(worst) == 1, "the legend gives the 3 worst triangles' rho range")
    check(len(list(group(whole, "marks").iter(NS + "circle"))) == 3, "three worst triangles circled")
    curves = group(whole, "curves")
    colours = {c.get("stroke") for c in curves.iter(NS + "polyline")}
    check(len(colours) == 3, f"three curve colours, one per group ({sorted(colours)})")
    check(b"&amp; &lt;mouth&gt;" in whole_bytes, "the group name is XML-escaped in the file")

    zoom_legend = texts(group(zoom, "legend"))
    check(zoom_legend[0] == "size: mean edge length (km, log scale)", "the size bar's title gives km")
    # Zoomed to the quarter x, y in [0.5, 1]: the frame is square (600 px + margins), and
    # fewer triangles, each reaching into the box.
    n_whole = len(list(group(whole, "triangles").iter(NS + "polygon")))
    n_zoom = len(list(group(zoom, "triangles").iter(NS + "polygon")))
    print(f"triangles: whole {n_whole}, zoom {n_zoom}")
    check(0 < n_zoom < n_whole, "the zoom draws fewer triangles")
    clip = next(zoom.iter(NS + "clipPath")).find(NS + "rect")
    w, h = float(clip.get("width")), float(clip.get("height"))
    check(abs(w - h) < 1e-6, f"the zoom's frame is the box's shape ({w} x {h})")
    x0, y0 = float(clip.get("x")), float(clip.get("y"))
    def meets(pts):
        xs, ys = [x for x, _ in pts], [y for _, y in pts]
        return max(xs) >= x0 and min(xs) <= x0 + w and max(ys) >= y0 and min(ys) <= y0 + h
    check(all(meets(points(p)) for p in group(zoom, "triangles").iter(NS + "polygon")),
          "every zoomed triangle reaches into the frame")
    # Open in the whole picture is drawn, in the zoom the coast at x = 0 is not.
    check(len(list(group(zoom, "curves").iter(NS + "polyline"))) < len(list(curves.iter(NS + "polyline"))),
          "curves outside the box are not drawn")
    check(not re.search(rb"nan|inf", whole_bytes, re.I), "no nan or inf in the file")
    finish()


if __name__ == "__main__":
    main(sys.argv[1])

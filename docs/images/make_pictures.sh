#!/usr/bin/env bash
# Remakes the example pictures of docs/examples.md (docs/images/*.png), each a few hundred KB.
#   docs/images/make_pictures.sh [BUILD_DIR]      (default: build; needs stereomesh built)
# Tools: stereomesh's own PNG pictures (lon/lat view, Mesh.PictureWidth), mesh_picture.py
# (python3-gmsh, python3-numpy) for the Arctic's polar view and the Bering Sea close-up,
# rsvg-convert (librsvg2-bin) for those SVGs, pngquant (64-colour palette) for every PNG.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
sm="$build/stereomesh"
for tool in rsvg-convert pngquant /usr/bin/python3; do
  command -v "$tool" > /dev/null || { echo "make_pictures.sh: $tool is missing" >&2; exit 2; }
done
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-pictures.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

mesh() {  # example, extra stereomesh arguments...
  local name="$1"; shift
  echo "make_pictures.sh: $name" >&2
  "$sm" -2 -nt 1 -v 1 "$root/examples/$name.geo" -setnumber EstimateStep 0 "$@" > /dev/null
}
small() {  # png in, png out: 64-colour palette
  pngquant --force --speed 1 64 -o "$2" "$1"
}

# The examples as stereomesh draws them (lon/lat view, triangles coloured by quality).
for name in gb_ireland north_sea_scheldt great_barrier_reef; do
  mesh "$name" -setnumber Mesh.PictureWidth 900 -o "$tmp/$name.png"
  small "$tmp/$name.png" "$here/$name.png"
done
mesh world_ocean -setnumber Mesh.PictureWidth 1000 -o "$tmp/world_ocean.png"
small "$tmp/world_ocean.png" "$here/world_ocean.png"
# The same mesh coloured by triangle size (Mesh.PictureColour 2: mean edge length, log scale).
mesh world_ocean -setnumber Mesh.PictureWidth 1000 -setnumber Mesh.PictureColour 2 -o "$tmp/world_ocean_size.png"
small "$tmp/world_ocean_size.png" "$here/world_ocean_size.png"

# Views stereomesh does not draw: a close-up of the world ocean (Bering Sea, a part of the
# paper's Figure 10) and the Arctic from above the pole (Figure 11).
mesh world_ocean -o "$tmp/world_ocean.msh"
/usr/bin/python3 "$here/mesh_picture.py" "$tmp/world_ocean.msh" "$tmp/bering.svg" --width 900 --box 160 210 45 66
rsvg-convert "$tmp/bering.svg" -o "$tmp/bering.png"
small "$tmp/bering.png" "$here/world_ocean_bering.png"
mesh arctic -o "$tmp/arctic.msh"
/usr/bin/python3 "$here/mesh_picture.py" "$tmp/arctic.msh" "$tmp/arctic.svg" --width 900
rsvg-convert "$tmp/arctic.svg" -o "$tmp/arctic.png"
small "$tmp/arctic.png" "$here/arctic.png"
# The Suez end of examples/mediterranean.geo with the passages left open and closed
# (docs/coastlines.md, "Passages, dams and seas").
mesh mediterranean -setnumber RegionalMinChannelWidth 0 -o "$tmp/med_open.msh"
mesh mediterranean -o "$tmp/med_closed.msh"
for c in open closed; do
  /usr/bin/python3 "$here/mesh_picture.py" "$tmp/med_$c.msh" "$tmp/suez_$c.svg" --width 600 --box 31.6 33.4 29.6 31.7
  rsvg-convert "$tmp/suez_$c.svg" -o "$tmp/suez_$c.png"
  small "$tmp/suez_$c.png" "$here/suez_$c.png"
done
ls -l "$here"/*.png >&2

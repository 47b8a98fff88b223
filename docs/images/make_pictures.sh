#!/usr/bin/env bash
# Remakes the pictures of docs/examples.md and docs/coastlines.md (docs/images/*.png), each a
# few hundred KB at most, all drawn by stereomesh itself (SVG/PNG scene of src/io/picture.h:
# colour bar, legend of the physical curve groups, graticule, the worst triangles circled).
#   docs/images/make_pictures.sh [BUILD_DIR]      (default: build; needs stereomesh built)
# Tools: stereomesh's PNG pictures (Mesh.PictureWidth, PictureView, PictureColour,
# PictureBox, PictureWorst, PicturePoints), pngquant (Debian; a 64-colour palette) for each.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
sm="$build/stereomesh"
command -v pngquant > /dev/null || { echo "make_pictures.sh: pngquant is missing" >&2; exit 2; }
tmp="$(mktemp -d "${TMPDIR:-/tmp}/sm-pictures.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

draw() {  # picture name, script, extra stereomesh arguments... (meshed with -2 unless -1 is given)
  local name="$1" script="$2"; shift 2
  local dim=-2
  [ "${1:-}" = -1 ] && { dim=-1; shift; }
  echo "make_pictures.sh: $name" >&2
  "$sm" "$dim" -nt 1 -v 1 "$script" -setnumber EstimateStep 0 "$@" -o "$tmp/$name.png" > /dev/null
  pngquant --force --speed 1 64 -o "$here/$name.png" "$tmp/$name.png"
}
example() { local name="$1" script="$2"; shift 2; draw "$name" "$root/examples/$script.geo" "$@"; }
width() { echo -setnumber Mesh.PictureWidth "$1"; }
box() { echo -setstring Mesh.PictureBox "$1"; }

# The examples, triangles coloured by quality (the 10 worst circled), lon/lat view with the
# cosine aspect of a regional frame.
for name in gb_ireland north_sea_scheldt great_barrier_reef; do
  example "$name" "$name" $(width 900)
done
example world_ocean world_ocean $(width 1000) -setnumber Mesh.PictureWorst 0
# The same mesh coloured by triangle size (mean edge length, log scale, km).
example world_ocean_size world_ocean $(width 1000) -setnumber Mesh.PictureColour 2 -setnumber Mesh.PictureWorst 0
# Zooms of the World Ocean (Mesh.PictureBox): the Strait of Gibraltar, the Danish straits
# coloured by the size criterion that sets the size there, and the Bering Sea across the
# dateline (W > E).
example world_ocean_gibraltar world_ocean $(width 800) $(box -9,-2,34,38.5)
example world_ocean_danish_straits world_ocean $(width 800) $(box 7,16,53.5,59.5) -setnumber Mesh.PictureColour 3
example world_ocean_bering world_ocean $(width 900) $(box 160,-150,45,66)
# The Arctic from above the pole (the PolarSphere's stereographic plane, Figure 11).
example arctic arctic $(width 900) -setnumber Mesh.PictureView 1

# Sizes on one scale, 20 to 300 km, for the pictures that compare.
same_scale="-setnumber Mesh.PictureColour 2 -setnumber Mesh.PictureWorst 0 -setnumber Mesh.PictureColourMin 20
  -setnumber Mesh.PictureColourMax 300"
# The paper's Figure 4: the World Ocean in the stereographic plane, Antarctica's ice front
# as the outer loop (the south pole is the projection's point at infinity), by size.
example figure4_world_stereographic world_ocean $(width 900) -setnumber Mesh.PictureView 1 $same_scale
# Figure 5: Great Britain and Ireland coarsened at 100 km, 15 km, 1.5 km and 150 m: the
# coastline B-splines (meshed 1D at 2 km, so that they are drawn smooth), with their
# control points at the two coarsest.
for gamma in 100000 15000 1500 150; do
  points=0
  [ "$gamma" -ge 15000 ] && points=1
  example "figure5_gamma_$gamma" gb_ireland_coarsening -1 -setnumber gamma "$gamma" -setnumber quiet 1 \
    -setnumber MeshAtAccuracy 0 -setnumber Mesh.MeshSizeMax 2000 $(width 450) -setnumber Mesh.PicturePoints "$points"
done
# The paper's f1 reading of the wavelength criterion beside the physical (tidal) one, both
# World Oceans coloured by size on the same scale.
example world_ocean_f1 world_ocean $(width 700) $same_scale
draw world_ocean_tidal "$here/world_ocean_tidal.geo" $(width 700) $same_scale

# The Suez end of examples/mediterranean.geo with the passages left open and closed
# (docs/coastlines.md, "Passages, dams and seas").
example suez_open mediterranean $(width 600) $(box 31.6,33.4,29.6,31.7) -setnumber RegionalMinChannelWidth 0
example suez_closed mediterranean $(width 600) $(box 31.6,33.4,29.6,31.7)
ls -l "$here"/*.png >&2

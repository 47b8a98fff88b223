#!/bin/sh
# An installed stereomesh runs with the source and build trees out of reach: install the
# build into a scratch prefix, then evaluate a copy of examples/world_ocean.geo from
# another folder (its Includes come from the prefix's stdlib, its grids from the prefix's
# data, its shorelines from the system), and import the installed Python module.
#   check_install.sh BUILD_DIR SOURCE_DIR
set -eu
build="$1" src="$2"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/sm-install.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
cmake --install "$build" --prefix "$scratch/prefix" > /dev/null
mkdir "$scratch/work"
cp "$src/examples/world_ocean.geo" "$scratch/work/ocean.geo"
cd "$scratch/work"
"$scratch/prefix/bin/stereomesh" --version | tee version.txt
grep -q "stdlib: $scratch/prefix/share/stereomesh/stdlib" version.txt
"$scratch/prefix/bin/stereomesh" -0 ocean.geo -setnumber CoastAccuracy 200e3 > out.txt 2> err.txt ||
  { cat out.txt err.txt; exit 1; }
grep -q "1 sea(s)" out.txt || { echo "the installed run printed no sea count:"; cat out.txt; exit 1; }
if [ -d "$scratch/prefix/lib/python3/dist-packages" ]; then
  PYTHONPATH="$scratch/prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import stereomesh
m = stereomesh.run('ocean.geo', setnumber={'CoastAccuracy': 400e3}, dim=0)
print('python module: ran', 'ocean.geo')"
fi
echo "installed binary ran from $scratch/work"

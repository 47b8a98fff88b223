#!/bin/sh
# The face pipeline's rooms keep their one-way dependencies (docs/kernel.md, "Meshing
# faces"): state (face_work.*, with mesh2d_options.h) <- steps <- pipeline (mesh2d.*).
# The step headers are the src/mesh headers that include face_work.h, the step sources
# the files that include a step header, the state and the pipeline left out. No step
# includes mesh2d.h; the state includes no step header. Run by CTest; the folder to check
# may be given (default: this checkout's src/mesh).
mesh="${1:-$(dirname "$0")/../../src/mesh}"
cd "$mesh" || exit 1
[ -f face_work.h ] && [ -f mesh2d.cpp ] || { echo "face_work.h or mesh2d.cpp missing in $mesh"; exit 1; }
headers=""
for f in *.h; do
  case "$f" in face_work.h | mesh2d.h | mesh2d_options.h) continue ;; esac
  grep -q '^#include "mesh/face_work.h"' "$f" && headers="$headers $f"
done
[ -n "$headers" ] || { echo "no header includes mesh/face_work.h"; exit 1; }
sources=""
for f in *.cpp; do
  case "$f" in face_work.cpp | mesh2d.cpp) continue ;; esac
  for h in $headers; do
    if grep -q "^#include \"mesh/$h\"" "$f"; then sources="$sources $f"; break; fi
  done
done
status=0
for f in $headers $sources; do
  if grep -n '^#include "mesh/mesh2d.h"' "$f"; then
    echo "step $f includes mesh2d.h (the pipeline)"
    status=1
  fi
done
for f in face_work.h face_work.cpp mesh2d_options.h; do
  for h in $headers mesh2d.h; do
    if grep -n "^#include \"mesh/$h\"" "$f"; then
      echo "$f (the state) includes $h"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "face rooms hold: state <- steps <- pipeline; steps:$headers;$sources"
exit $status

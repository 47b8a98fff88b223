#!/bin/sh
# A clone stands alone: no tracked file may name a folder beside the checkout (the data
# set the project was started from lies there on the developers' machines, not on a
# user's). Run by CTest; skipped (77) outside a git checkout.
root="$(cd "$(dirname "$0")/../.." && pwd)"
git -C "$root" rev-parse --git-dir > /dev/null 2>&1 || { echo "skipped: not a git checkout"; exit 77; }
# The pattern is spelled in two parts so that this file does not match itself.
outside='\.\./share''d|share''d/(data|tools|reference)([^A-Za-z0-9_]|$)'
hits="$(cd "$root" && git ls-files -z | xargs -0 grep -n -I -E "$outside" 2>/dev/null)"
if [ -n "$hits" ]; then
  echo "tracked files name a folder outside the repository:"
  echo "$hits"
  exit 1
fi
echo "no tracked file names a folder outside the repository ($(cd "$root" && git ls-files | wc -l) files)"

#!/usr/bin/env bash
# Regenerates the README's pictures in docs/images/ for the paper's four examples:
#  - the placed pairs (render) and their slices (scripts/make-slice-images.sh), as SVG: the
#    paper's Figures 1 and 6;
#  - their configuration spaces in 3D, space-*.png: the paper's Figures 2, 3, 5 and 7, as
#    `cslice view` draws them, screenshot in headless Chromium (viewer/tools/figures.cjs).
# Usage: scripts/make-figures.sh [BUILD_DIR]   (default: build)
# Needs cslice built there with the viewer (CSLICE_VIEWER=ON, the default), which also puts
# playwright-core in BUILD_DIR/viewer/node_modules, and Debian's chromium
# (bash scripts/install-deps.sh --browser).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
cslice="$build/cslice"
node_modules="$build/viewer/node_modules"
if [ ! -x "$cslice" ] || [ ! -d "$node_modules/playwright-core" ]; then
  echo "make-figures.sh: build cslice with the viewer first: cmake --build $build --target cslice_cli" >&2
  exit 1
fi
out="$root/docs/images"
mkdir -p "$out"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The README's telling configuration of each example (x,y,theta) and its caption.
render() {  # example pose title
  "$cslice" render "$root/examples/$1.json" --at "$2" --title "$3" -o "$out/$1.svg"
}
render knee 5,-3,0.5 "knee: femur at (5, -3, 0.5)"
render cam 0.885,-1.25,0.3 "cam at (0.885, -1.25, 0.3): 0.1 mm backlash each side"
render fixture 2.1,-0.7,0 "fixture: engaging configuration (2.1, -0.7, 0)"
render fastener 0,6,1.5707963267948966 "fastener: pin vertical above the slot"
echo "wrote $out/{knee,cam,fixture,fastener}.svg"
bash "$root/scripts/make-slice-images.sh" "$cslice"

NODE_PATH="$node_modules" node "$root/viewer/tools/figures.cjs" \
  --cslice "$cslice" --source "$root" --work "$work" --out "$out"

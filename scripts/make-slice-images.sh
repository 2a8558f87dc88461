#!/usr/bin/env bash
# Regenerates docs/images/slice-*.svg, the slices of the paper's examples (section 2).
# Usage: scripts/make-slice-images.sh [path/to/cslice]   (default: build/cslice)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cslice="${1:-$root/build/cslice}"
out="$root/docs/images"
mkdir -p "$out"
slice() {  # name example theta [extra options...]
  local name=$1 example=$2 theta=$3
  shift 3
  "$cslice" slice "$root/examples/$example.json" --theta "$theta" --svg "$out/slice-$name.svg" "$@"
}
slice knee knee 0.5 --mark 5,-3          # Figure 1
slice cam cam 0.3                        # Figure 3
slice fixture fixture 0 --mark 2.1,-0.7  # Figure 5
slice fastener-0 fastener 0              # Figure 6, pin horizontal
slice fastener-1.5708 fastener 1.5708    # Figure 6, pin vertical
echo "wrote $out/slice-*.svg"

#!/usr/bin/env bash
# Installs every build and test dependency of cslice from Debian 12 packages.
# Idempotent: safe to run again; apt-get skips what is already installed.
# Usage: install-deps.sh [--browser]
#   --browser  also Debian's chromium, which the viewer's browser test (tests/viewer) and
#              scripts/make-figures.sh drive headless; scripts/test-all.sh passes it.
set -euo pipefail
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps.sh: run as root (it calls apt-get)" >&2
  exit 1
fi
browser=0
for arg in "$@"; do
  case "$arg" in
    --browser) browser=1 ;;
    *) echo "install-deps.sh: unknown option '$arg' (expected --browser)" >&2; exit 2 ;;
  esac
done
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential cmake ninja-build pkg-config git
  libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev librapidcheck-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libtbb-dev libpugixml-dev libboost-dev
  clang-format
)
# The viewer (cslice view) is bundled with npm at build time (viewer/package-lock.json).
# Debian's npm only where there is none: a node installed otherwise (e.g. NodeSource's,
# which bundles npm) conflicts with Debian's npm package.
if ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi
if [ "$browser" -eq 1 ]; then
  packages+=(chromium)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
echo "install-deps.sh: all ${#packages[@]} packages present"

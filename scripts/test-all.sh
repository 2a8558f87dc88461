#!/usr/bin/env bash
# Installs dependencies (as root), builds everything (library, program, tests, benchmarks)
# and runs every test, the viewer's browser test in headless Chromium included.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --browser
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"

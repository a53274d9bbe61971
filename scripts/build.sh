#!/usr/bin/env bash
# Configures (Release, Ninja) and builds PoroSPH into build/ (or $POROSPH_BUILD_DIR).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${POROSPH_BUILD_DIR:-$root/build}"
"$root/scripts/install_deps.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "$(nproc)"

#!/usr/bin/env bash
# One command: install what is missing, build, and run the whole test suite (CTest + GoogleTest).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${POROSPH_BUILD_DIR:-$root/build}"
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"

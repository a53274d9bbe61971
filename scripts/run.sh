#!/usr/bin/env bash
# One command: install what is missing, build, and run a scene (default: the dam break).
#   scripts/run.sh [SCENE.toml] [coupler run options, e.g. --set run.dp=0.002 --out DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${POROSPH_BUILD_DIR:-$root/build}"
"$root/scripts/build.sh"
scene="$root/cases/dam_break/scene.toml"
if [ $# -gt 0 ] && [[ "$1" != -* ]]; then scene="$1"; shift; fi
exec "$build/bin/coupler" run "$scene" "$@"

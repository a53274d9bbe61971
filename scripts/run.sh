#!/usr/bin/env bash
# One command: install what is missing, build, and run a scene (default: the dam break).
#   scripts/run.sh [SCENE.toml] [coupler run options, e.g. --set run.dp=0.002 --out DIR]
# Without arguments it reruns the demo into runs/dam_break (--overwrite); with arguments they go to
# `coupler run` unchanged (give --overwrite to replace an earlier run in the same directory).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${POROSPH_BUILD_DIR:-$root/build}"
"$root/scripts/build.sh"
scene="$root/cases/dam_break/scene.toml"
if [ $# -eq 0 ]; then exec "$build/bin/coupler" run "$scene" --overwrite; fi
if [[ "$1" != -* ]]; then scene="$1"; shift; fi
exec "$build/bin/coupler" run "$scene" "$@"

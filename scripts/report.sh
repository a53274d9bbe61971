#!/usr/bin/env bash
# Validation report: install what is missing (incl. the plotting packages), build, then run
# tools/validation/report.py (reads finished runs in runs/validation/; --run first runs the missing
# cases, which takes hours; --only NAME ... restricts it). Writes docs/validation.md and
# docs/validation/*.png.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
missing=()
for p in python3-numpy python3-h5py python3-matplotlib; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
exec /usr/bin/python3 "$root/tools/validation/report.py" "$@"

#!/usr/bin/env bash
# Installs the Debian packages PoroSPH needs, only those missing (idempotent; needs root or sudo).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libzmq3-dev cppzmq-dev libhdf5-dev protobuf-compiler libprotobuf-dev
  googletest libgtest-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  python3 python3-numpy python3-h5py python3-matplotlib python3-zmq python3-protobuf
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "porosph: installing missing Debian packages: ${missing[*]}" >&2
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those missing.
# Facts behind the list: docs/toolchain.md (OpenBLAS pthread build for
# CHOLMOD, Debian's python3 for the figures).
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libsuitesparse-dev libopenblas0-pthread
  libhdf5-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libtinyxml2-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-h5py python3-numpy
  openmpi-bin libopenmpi-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

#!/usr/bin/env bash
# Installs the Debian 12 packages accsim builds against. Idempotent and quiet:
# it asks apt only for what is missing, so a second run costs a dpkg query.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libbullet-dev
  libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev libode-dev
  libopencv-dev
  pybind11-dev python3-dev python3-venv python3-numpy python3-pandas python3-matplotlib
  python3-cloudpickle python3-pytest
  libtorch-dev python3-torch libopenblas0-pthread
  libfastrtps-dev libfastcdr-dev fastddsgen fastdds-tools
  libgtest-dev libgmock-dev libbenchmark-dev clang-14 libclang-rt-14-dev
  nlohmann-json3-dev libyaml-cpp-dev libcli11-dev libspdlog-dev libcpp-httplib-dev
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${#missing[@]} Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

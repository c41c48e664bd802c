#!/usr/bin/env bash
# Installs capsubot's build and test dependencies from Debian 12 packages (idempotent).
# Quiet when everything is present; needs root (or sudo) only when something is missing.
set -euo pipefail

# The program and the library alone (scripts/build.sh --minimal): a compiler, CMake and the
# libraries the CLI links.
core=(build-essential cmake pkg-config libeigen3-dev libnlopt-cxx-dev libgsl-dev libfmt-dev
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev zlib1g-dev)
# Everything else: the tests, the benchmarks, the manual page, the Python module (and the
# pandas the docs' examples read CSVs with), MPI, gnuplot.
extras=(libgtest-dev libgmock-dev libbenchmark-dev help2man pybind11-dev python3-dev python3-numpy
  python3-pytest python3-matplotlib python3-pandas python3-pip python3-setuptools python3-wheel
  python3-venv libopenmpi-dev openmpi-bin gnuplot-nox)
# Usage: install-deps.sh [--minimal] [--figures]; gnuplot (for --plot, its tests and the figure
# script) comes with the extras; --figures adds it to a minimal installation.
packages=("${core[@]}")
minimal=0
for arg in "$@"; do
  case $arg in
    --minimal) minimal=1 ;;
    --figures) packages+=(gnuplot-nox) ;;
    *) echo "install-deps: unknown option $arg (expected --minimal or --figures)" >&2; exit 2 ;;
  esac
done
[[ $minimal -eq 1 ]] || packages+=("${extras[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    exec sudo "$0" "$@"
  fi
  echo "install-deps: missing Debian packages: ${missing[*]}" >&2
  echo "install-deps: run this script as root (apt-get needs it), or install them yourself" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

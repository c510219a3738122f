#!/usr/bin/env bash
# Installs every build, test and interop dependency of PruneSfM from Debian 12 packages, by name.
# Idempotent: a second run only re-checks. Nothing is downloaded outside apt.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libceres-dev libopencv-dev libopengv-dev libflann-dev libcereal-dev
  libgtest-dev libgmock-dev
  libigraph-dev libarpack2-dev libglpk-dev libplfit-dev libgmp-dev
  libsqlite3-dev libcli11-dev nlohmann-json3-dev libexif-dev
  sqlite3 python3
  libblas-dev libopenblas0-serial  # the BLAS behind libblas.so.3 (alternatives): brute-force matching and CHOLMOD, docs/dependencies.md
  chromium  # headless browser of the report's page test (tests/report/browser_test.cpp)
  clang libclang-rt-14-dev  # libFuzzer for the parsers' fuzz targets (scripts/fuzz.sh)
)
# Interop peers: the real COLMAP 3.8, used by tests/interop and bench/.
if [[ "${PRUNESFM_SKIP_COLMAP:-0}" != 1 ]]; then
  packages+=(colmap)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; fi
echo "install_deps: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get -o DPkg::Lock::Timeout=600 update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
  --no-install-recommends "${missing[@]}" >/dev/null
echo "install_deps: done"

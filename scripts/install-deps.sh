#!/usr/bin/env bash
# Installs the Debian 12 packages CAM Workbench needs to build, test and run.
# Idempotent: packages already present are skipped; apt-get runs only when something is missing.
# Usage: scripts/install-deps.sh [--external]   (--external adds the heavy peers: freecad, linuxcnc-uspace,
# and CGAL, measured beside our kernels by tests/bench/CgalBench.cpp but not used by the product)
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config git file dpkg-dev clang-format
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  libqt6opengl6-dev qt6-declarative-dev libgl-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libocct-ocaf-dev
  libeigen3-dev libvtk9-dev libqscintilla2-qt6-dev libpolyclipping-dev libminizip-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev clang-14 libclang-rt-14-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0 fonts-dejavu-core poppler-utils locales
)
if [[ "${1:-}" == "--external" ]]; then
  packages+=(freecad linuxcnc-uspace libcgal-dev)
fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# A locale that writes 1.5 as "1,5": the tests check that numbers in NC, files and messages do not
# follow it (Qt sets the C library's locale from the user's environment).
if ! locale -a | grep -qi '^de_DE\.utf-\?8$'; then
  echo "install-deps: generating the de_DE.UTF-8 locale for the decimal-comma tests"
  $sudo localedef -i de_DE -c -f UTF-8 de_DE.UTF-8
fi

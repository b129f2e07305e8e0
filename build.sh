#!/usr/bin/env bash
# wrenchkit's one entry point for a fresh Debian 12 machine (run as root, or with sudo available).
#   ./build.sh demo    install the Debian packages, build, run `wrenchkit demo`
#   ./build.sh test    install the Debian packages, build, run the whole test suite (CTest)
#   ./build.sh build   install and build only
#   ./build.sh stability   regenerate docs/stability.md (near-degenerate stress report)
#   ./build.sh gallery     regenerate the pictures of docs/gallery.md
# Environment: BUILD_DIR (default build), JOBS (default: number of cores), CXX (compiler).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(g++ cmake ninja-build ccache libgmp-dev libgtest-dev librapidcheck-dev
          pybind11-dev python3-dev python3-pytest python3-scipy)

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "build.sh: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build() {
  local dir="${BUILD_DIR:-build}"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWRENCHKIT_WERROR=ON >/dev/null
  cmake --build "$dir" -j "${JOBS:-$(nproc)}"
}

case "${1:-}" in
  demo)
    install_packages
    build
    "${BUILD_DIR:-build}/wrenchkit" demo
    ;;
  test)
    install_packages
    build
    ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j "${JOBS:-$(nproc)}"
    ;;
  build)
    install_packages
    build
    ;;
  stability)
    install_packages
    build
    "${BUILD_DIR:-build}/fuzz/stress_closure" --cases 400 --report docs > /dev/null
    echo "build.sh: wrote docs/stability.md and docs/stability.svg"
    ;;
  gallery)
    install_packages
    build
    docs/gallery/make_gallery.sh "${BUILD_DIR:-build}"
    ;;
  *)
    echo "usage: ./build.sh demo|test|build|stability|gallery" >&2
    exit 2
    ;;
esac

#!/usr/bin/env bash
# wrenchkit's one entry point for a fresh Debian 12 machine (run as root, or with sudo available).
#   ./build.sh demo    install the Debian packages, build, run `wrenchkit demo`
#   ./build.sh test    install the Debian packages, build, run the whole test suite (CTest)
#   ./build.sh build   install and build only
#   ./build.sh stability   regenerate docs/stability.md (near-degenerate stress report)
#   ./build.sh gallery     regenerate the pictures of docs/gallery.md
#   ./build.sh bench       run the benchmark suite (2–5 min) and regenerate docs/benchmarks.md + plots
# Environment: BUILD_DIR (default build), JOBS (default: number of cores), CXX (compiler).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(g++ cmake ninja-build ccache libgmp-dev libgtest-dev librapidcheck-dev)
# The benchmark suite and its peers (bench/; built and smoke-tested by `test` so it never rots).
PACKAGES+=(libbenchmark-dev libqhull-dev libcdd-dev libglpk-dev libcgal-dev)

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
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWRENCHKIT_WERROR=ON -DWRENCHKIT_BUILD_BENCH=ON >/dev/null
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
  bench)
    PACKAGES+=(python3)  # the report generator (standard library only)
    install_packages
    build
    out="${BUILD_DIR:-build}/bench/results.json"
    "${BUILD_DIR:-build}/bench/wrenchkit_bench" --benchmark_min_time=0.05 --benchmark_format=console \
      --benchmark_out_format=json --benchmark_out="$out"
    /usr/bin/python3 bench/make_report.py "$out" docs
    echo "build.sh: wrote docs/benchmarks.md and docs/benchmarks/*.svg"
    ;;
  *)
    echo "usage: ./build.sh demo|test|build|stability|gallery|bench" >&2
    exit 2
    ;;
esac

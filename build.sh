#!/usr/bin/env bash
# wrenchkit's one entry point for a fresh Debian 12 machine (run as root, or with sudo available).
#   ./build.sh demo    install the Debian packages, build, run `wrenchkit demo`
#   ./build.sh test    install the Debian packages, build, run the whole test suite (CTest), then
#                      the fuzz smoke: every libFuzzer target for FUZZ_SECONDS (default 20) each
#   ./build.sh fuzz [SECONDS]  build the libFuzzer targets (clang, ASan+UBSan) and run each for SECONDS
#                      (default 3600) on a copy of its committed corpus; a finding stops it (exit 1) and
#                      leaves the input in fuzz-findings/
#   ./build.sh build   install and build only
#   ./build.sh stability   regenerate docs/stability.md (near-degenerate stress report)
#   ./build.sh gallery     regenerate the pictures of docs/gallery.md
#   ./build.sh bench       run the benchmark suite (2–5 min) and regenerate docs/benchmarks.md + plots
# Environment: BUILD_DIR (default build), JOBS (default: number of cores), CXX (compiler).
set -euo pipefail
cd "$(dirname "$0")"

# CGAL (header-only): the mesh files' writers and the CGAL face (exact/cgal/), the tests' oracle, a bench peer.
PACKAGES=(g++ cmake ninja-build ccache libgmp-dev libcgal-dev libgtest-dev librapidcheck-dev clang libclang-rt-14-dev
          libboost-program-options-dev pybind11-dev python3-dev python3-pytest python3-scipy
          python3-numpy python3-dask python3-distributed python3-build)
# The benchmark suite and its peers (bench/; built and smoke-tested by `test` so it never rots).
PACKAGES+=(libbenchmark-dev libqhull-dev libcdd-dev libglpk-dev)

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

# The libFuzzer targets of fuzz/ in their own build (clang; every library instrumented), each run for
# $1 seconds on a scratch copy of its committed corpus (the committed seeds stay as they are).
fuzz() {
  local seconds="$1" dir="${FUZZ_BUILD_DIR:-build-fuzz}"
  CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWRENCHKIT_FUZZ=ON \
    -DWRENCHKIT_BUILD_TESTS=OFF >/dev/null
  cmake --build "$dir" -j "${JOBS:-$(nproc)}"
  mkdir -p fuzz-findings
  local target corpus work
  for target in fuzz_scene_parser fuzz_checker fuzz_structured; do
    case "$target" in
      fuzz_scene_parser) corpus=fuzz/corpus/scene ;;
      fuzz_checker) corpus=fuzz/corpus/checker ;;
      fuzz_structured) corpus=fuzz/corpus/structured ;;
    esac
    work=$(mktemp -d)
    cp -r "$corpus"/. "$work"/
    echo "build.sh: fuzzing $target for ${seconds}s"
    # ASan's allocator keeps freed memory (its 256 MB quarantine, and blocks never returned to the system): a long run's
    # resident memory grew ~60 MB a minute toward -rss_limit_mb with no leak (docs/fuzzing.md "Memory"). A smaller
    # quarantine still catches use after free; freed memory goes back to the system.
    if ! ASAN_OPTIONS="${ASAN_OPTIONS:-quarantine_size_mb=64:allocator_release_to_os_interval_ms=1000}" "$dir/fuzz/$target" "$work" -dict=fuzz/scene.dict -max_total_time="$seconds" -timeout=30 \
         -rss_limit_mb=2048 -malloc_limit_mb=1024 -artifact_prefix=fuzz-findings/"$target"- -print_final_stats=1 >"$work.log" 2>&1; then
      tail -n 40 "$work.log"
      echo "build.sh: $target found a problem; the input is in fuzz-findings/" >&2
      rm -rf "$work"
      return 1
    fi
    grep -E "^(Done|stat::number_of_executed_units)" "$work.log" | tail -n 1
    rm -rf "$work" "$work.log"
  done
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
    fuzz "${FUZZ_SECONDS:-20}"
    ;;
  fuzz)
    install_packages
    fuzz "${2:-3600}"
    ;;
  build)
    install_packages
    build
    ;;
  stability)
    install_packages
    build
    "${BUILD_DIR:-build}/fuzz/stress_report" --cases 1000 --report docs > /dev/null
    echo "build.sh: wrote docs/stability.md and docs/stability.svg"
    ;;
  gallery)
    install_packages
    build
    docs/gallery/make_gallery.sh "${BUILD_DIR:-build}"
    PYTHONPATH="${BUILD_DIR:-build}/python" /usr/bin/python3 docs/sliding/make_slices.py
    ;;
  bench)
    PACKAGES+=(python3)  # the report generator (standard library only)
    install_packages
    build
    out="${BUILD_DIR:-build}/bench/results.json" batch="${BUILD_DIR:-build}/bench/batch.json"
    "${BUILD_DIR:-build}/bench/wrenchkit_bench" --benchmark_min_time=0.05 --benchmark_format=console \
      --benchmark_out_format=json --benchmark_out="$out"
    "${BUILD_DIR:-build}/bench/batch_bench" --benchmark_min_time=0.2 --benchmark_out_format=json --benchmark_out="$batch"
    base=()
    if [ -n "${BENCH_BASELINE:-}" ]; then  # an earlier build's bench/ directory: before and after in one session
      "$BENCH_BASELINE/wrenchkit_bench" --benchmark_filter='^generic/6/|/1e-3/labels_' --benchmark_min_time=0.05 \
        --benchmark_out_format=json --benchmark_out="$out.baseline"
      "$BENCH_BASELINE/batch_bench" --benchmark_min_time=0.2 --benchmark_out_format=json --benchmark_out="$batch.baseline"
      base=(--baseline "$out.baseline" --baseline-batch "$batch.baseline")
    fi
    /usr/bin/python3 bench/make_report.py "$out" docs "./build.sh bench" --batch "$batch" "${base[@]}"
    echo "build.sh: wrote docs/benchmarks.md and docs/benchmarks/*.svg"
    ;;
  *)
    echo "usage: ./build.sh demo|test|build|fuzz [SECONDS]|stability|gallery|bench" >&2
    exit 2
    ;;
esac

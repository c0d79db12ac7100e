# Sourced by demo.sh and test.sh: installs what is missing from Debian 12, configures and builds.
# pm_setup [release|sanitize|fuzz] [optional packages...]  ->  sets PM_BUILD_DIR to the built tree.

PM_DEBIAN_PACKAGES=(build-essential cmake ninja-build pkg-config libvisp-dev libopencv-dev libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev libcli11-dev libpng-dev libjpeg-dev libxml2-dev libapriltag-dev libyaml-cpp-dev
  pybind11-dev python3-dev python3-numpy)

# Only for the tests: ViSP's images (the AprilTag benchmark test is skipped without them) and OpenCV's
# sample data (real stereo chessboard pairs and a calibration file; their tests are skipped without them);
# Doxygen and Graphviz for the API pages (the test docs_api builds them).
PM_TEST_PACKAGES=(visp-images-data opencv-doc xvfb doxygen graphviz python3-pytest python3-opencv)

# Only for the fuzz targets (scripts/fuzz.sh): clang, its libFuzzer runtime, its OpenMP.
PM_FUZZ_PACKAGES=(clang libclang-rt-14-dev libomp-dev)

# pm_missing packages...  ->  prints those not installed
pm_missing() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

# pm_install_deps [optional packages...]: the required ones or fail; the optional ones if we can.
pm_install_deps() {
  local missing optional
  missing=($(pm_missing "${PM_DEBIAN_PACKAGES[@]}" ${PM_EXTRA_PACKAGES[@]+"${PM_EXTRA_PACKAGES[@]}"}))
  optional=($(pm_missing "$@"))
  [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    [ ${#optional[@]} -gt 0 ] && echo "note: not installed (some tests will be skipped): ${optional[*]}" >&2
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "error: missing Debian packages; run as root: apt-get install ${missing[*]}" >&2
    return 1
  fi
  echo "installing: ${missing[*]} ${optional[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  [ ${#missing[@]} -eq 0 ] || apt-get install -y -qq "${missing[@]}" >/dev/null
  [ ${#optional[@]} -eq 0 ] || apt-get install -y -qq "${optional[@]}" >/dev/null ||
    echo "note: could not install ${optional[*]} (some tests will be skipped)" >&2
}

pm_setup() {
  local mode="${1:-release}" root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  shift || true
  local target=all
  [ "$mode" = fuzz ] && PM_EXTRA_PACKAGES=("${PM_FUZZ_PACKAGES[@]}")
  pm_install_deps "$@"
  # The sanitizers build keeps line tables only (-g1): ASan and UBSan reports name file and line; full
  # debug information only makes the build (which CI makes from scratch) longer to compile and link.
  case "$mode" in
    release)  PM_BUILD_DIR="$root/build";      set -- -DCMAKE_BUILD_TYPE=Release -DPM_SANITIZE=OFF ;;
    sanitize) PM_BUILD_DIR="$root/build-asan"; set -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPM_SANITIZE=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" ;;
    fuzz)     PM_BUILD_DIR="$root/build-fuzz"; target=pm_fuzz_all
              set -- -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DPM_FUZZ=ON -DPM_BUILD_APPS=OFF -DPM_BUILD_TESTS=OFF ;;
    *) echo "error: unknown build mode '$mode' (release, sanitize or fuzz)" >&2; return 2 ;;
  esac
  cmake -S "$root" -B "$PM_BUILD_DIR" -G Ninja "$@" >/dev/null
  cmake --build "$PM_BUILD_DIR" --target "$target" -j "$(nproc)"
  export PM_BUILD_DIR
}

#!/usr/bin/env bash
# The whole test suite through CTest: installs what is missing, builds, runs.
#   bash scripts/test.sh             Release build in build/
#   bash scripts/test.sh --sanitize  AddressSanitizer + UBSan build in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
mode=release
case "${1:-}" in
  "") ;;
  --sanitize) mode=sanitize ;;
  *) echo "usage: bash scripts/test.sh [--sanitize]" >&2; exit 2 ;;
esac
pm_setup "$mode" "${PM_TEST_PACKAGES[@]}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
# Two test programs at once, each with OpenMP's threads: waiting threads sleep instead of spinning
# on the cores the other program needs (OMP_WAIT_POLICY; the results are the same).
export OMP_WAIT_POLICY="${OMP_WAIT_POLICY:-passive}"
# The lab's models and trust calibrations made once and read back by the other tests (pm::lab::LabCache:
# found only for the same pass, rig and parameters), in a folder named by the sources, so that a change
# of code starts an empty one and the release and sanitizer runs of one tree share it (CI runs both).
fingerprint=$(find modules apps data cmake CMakeLists.txt -type f -print0 | sort -z | xargs -0 sha1sum | sha1sum | cut -c1-16)
export PM_LAB_CACHE="$PWD/.lab-cache/$fingerprint"
rm -rf .trust-cache
mkdir -p .lab-cache
find .lab-cache -mindepth 1 -maxdepth 1 ! -name "$fingerprint" -exec rm -rf {} +
ctest --test-dir "$PM_BUILD_DIR" --output-on-failure -j "$(nproc)"

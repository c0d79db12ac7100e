#!/usr/bin/env bash
# Fuzzes every loader of outside input with libFuzzer (clang, ASan + UBSan) for a bounded time.
#   bash scripts/fuzz.sh [--seconds N] [--seed S] [target ...]
#     N seconds per target (default 60); S libFuzzer's seed (default 0: a random one); all targets
# Seeds: fuzz/corpus/<target> (read only); the growing corpus: build-fuzz/corpus/<target>.
# Any crash makes the exit status 1; its input is in build-fuzz/findings/<target>/: fix the
# loader, then add the input to fuzz/regressions/<target>/ (the test suite replays it).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=60
seed=0
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+$ ]] && [ "$2" -gt 0 ] || { echo "error: --seconds needs a positive whole number" >&2; exit 2; }
               seconds=$2; shift 2 ;;
    --seed)    [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+$ ]] || { echo "error: --seed needs a whole number" >&2; exit 2; }
               seed=$2; shift 2 ;;
    -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "error: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
all=($(sed -n 's/^set(PM_FUZZ_TARGETS \(.*\))$/\1/p' fuzz/FuzzTargets.cmake))
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")
for t in "${targets[@]}"; do
  [[ " ${all[*]} " == *" $t "* ]] || { echo "error: unknown fuzz target '$t' (one of: ${all[*]})" >&2; exit 2; }
done
source scripts/setup.sh
pm_setup fuzz
export ASAN_OPTIONS="detect_leaks=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
status=0
for t in "${targets[@]}"; do
  corpus="$PM_BUILD_DIR/corpus/$t" findings="$PM_BUILD_DIR/findings/$t"
  mkdir -p "$corpus" "$findings"
  log="$PM_BUILD_DIR/fuzz_$t.log"
  printf 'fuzz_%-15s %4d s ... ' "$t" "$seconds"
  if "$PM_BUILD_DIR/fuzz/fuzz_$t" -max_total_time="$seconds" -seed="$seed" -rss_limit_mb=2048 -timeout=10 \
       -artifact_prefix="$findings/" "$corpus" "fuzz/corpus/$t" >"$log" 2>&1; then
    grep -o 'Done [0-9]* runs' "$log" | tail -1 | sed 's/Done \([0-9]*\) runs/\1 runs, no crash/'
  else
    echo "CRASH (see $log; the input is in $findings/)"
    grep -m3 -E 'ERROR|terminate|what\(\)' "$log" | sed 's/^/    /' || true
    status=1
  fi
done
exit $status

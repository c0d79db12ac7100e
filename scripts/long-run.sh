#!/usr/bin/env bash
# The long run of issue 8: pm-servo over N frames (100,000 by default: 55 min of a sinusoidal
# target at 30 fps, on the default evaluation budget, so deterministic) while this script samples
# the process's resident memory every 10 s. Writes DIR/ (pm-servo's outputs) and DIR/rss.csv, then
# prints the memory after the warm-up (the first tenth of the run), its largest value after that,
# the growth in %; pm-servo prints the error per tenth of the run (a drift would show there).
#   bash scripts/long-run.sh [--frames N] [--out DIR] [-- extra pm-servo options]
set -euo pipefail
cd "$(dirname "$0")/.."
frames=100000
out=results/long-run
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case "$frames" in ''|*[!0-9]*) echo "error: --frames needs a positive whole number" >&2; exit 2 ;; esac
[ "$frames" -ge 30 ] || { echo "error: --frames must be at least 30" >&2; exit 2; }
source scripts/setup.sh
pm_setup release
# pm-servo runs floor(duration * fps) + 1 frames.
duration=$(awk -v n="$frames" 'BEGIN { printf "%.4f", (n - 1) / 30 }')
mkdir -p "$(dirname "$out")"
rss="$(mktemp)"
trap 'rm -f "$rss"' EXIT
"$PM_BUILD_DIR/apps/pm-servo" --motion sine --duration-s "$duration" --no-video \
  --overlay-every 0 --out "$out" "$@" &
pid=$!
start=$(date +%s)
echo "elapsed_s,rss_kb" > "$rss"
while kill -0 "$pid" 2>/dev/null; do
  kb=$(awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$kb" ] && echo "$(( $(date +%s) - start )),$kb" >> "$rss"
  sleep 10
done
wait "$pid"
cp "$rss" "$out/rss.csv"
# Warm-up: the first tenth of the samples (the one at 0 s, taken as the program starts, aside);
# growth: the largest later sample against the last warm-up one.
awk -F, 'NR > 1 && $1 > 0 { ++n; t[n] = $1; r[n] = $2 }
  END {
    if (n < 2) { print "resident memory: too few samples to tell a growth (run longer)"; exit }
    w = int(n / 10); if (w < 1) w = 1
    mx = 0; for (i = w + 1; i <= n; ++i) if (r[i] > mx) mx = r[i]
    printf "resident memory: %.1f MB after the warm-up (%d s), at most %.1f MB after it: growth %.2f %%\n",
           r[w] / 1024, t[w], mx / 1024, 100 * (mx - r[w]) / r[w]
  }' "$out/rss.csv"

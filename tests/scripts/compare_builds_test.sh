#!/usr/bin/env bash
# scripts/compare-builds.sh against two fake build trees whose pm-servo writes a summary.json from its
# --seed (and, in the "after" tree, moves one seed's figure): the runs of --seeds land in their
# folders, the report gives each seed's key figures and their mean and range, the exit status says
# same (0) or different (1), and a malformed --seeds is a usage error (2).
set -euo pipefail
script="$(cd "$(dirname "$0")/../.." && pwd)/scripts/compare-builds.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

fake_build() { # dir shift-seed: pm-servo writes at rest = seed / 10 mm (+ 0.5 for seed shift-seed)
  mkdir -p "$1/apps"
  cat >"$1/apps/pm-servo" <<FAKE
#!/usr/bin/env bash
seed=1; out=""
while [ \$# -gt 0 ]; do
  case "\$1" in --seed) seed="\$2"; shift 2 ;; --out) out="\$2"; shift 2 ;; *) shift ;; esac
done
mkdir -p "\$out"
mm=\$(python3 -c "print(\$seed / 10 + (0.5 if \$seed == $2 else 0))")
printf '{"rms_error_mm": {"at_rest": %s}, "rms_rotation_error_deg": {"at_rest": 0.25}, "frames_servoed": 2000, "frames_servoed_on_wrong_pose": 0}\n' "\$mm" >"\$out/summary.json"
printf 't,x\n0,%s\n' "\$mm" >"\$out/frames.csv"
FAKE
  chmod +x "$1/apps/pm-servo"
}
fake_build "$work/a" 0
fake_build "$work/b" 0
fake_build "$work/c" 3

# the same behaviour: every seed the same, exit 0, the figures per seed and their spread
bash "$script" --cases servo-c12 --seeds 2,3 "$work/a" "$work/b" "$work/same" >"$work/same.txt" 2>"$work/same.err" ||
  fail "two builds that write the same outputs differ: $(cat "$work/same.txt" "$work/same.err")"
for f in "$work"/same/{before,after}/servo-c12/{,seed-2/,seed-3/}summary.json; do
  [ -f "$f" ] || fail "$f was not written"
done
grep -q "^servo-c12: same (6 files compared, 3 table rows)" "$work/same.txt" || fail "no 'same' verdict over the three runs: $(cat "$work/same.txt")"
grep -q "seed-3: 0.3 -> 0.3; 0.25 -> 0.25; 2000 -> 2000; 0 -> 0" "$work/same.txt" || fail "seed 3's figures: $(cat "$work/same.txt")"
grep -q "before, 3 seeds: at rest mm 0.2 \[0.1, 0.3\]" "$work/same.txt" || fail "the seeds' mean and range: $(cat "$work/same.txt")"

# one seed moved: exit 1, that seed's figure before -> after, the means apart
if bash "$script" --cases servo-c12 --seeds 2,3 "$work/a" "$work/c" "$work/moved" >"$work/moved.txt" 2>/dev/null; then
  fail "a build that moves seed 3's figure reads the same: $(cat "$work/moved.txt")"
fi
grep -q "^servo-c12: DIFFERENT" "$work/moved.txt" || fail "no DIFFERENT verdict: $(cat "$work/moved.txt")"
grep -q "seed-3: 0.3 -> 0.8;" "$work/moved.txt" || fail "seed 3's move: $(cat "$work/moved.txt")"
grep -q "seed-2: 0.2 -> 0.2;" "$work/moved.txt" || fail "seed 2 moved: $(cat "$work/moved.txt")"
grep -q "after, 3 seeds: at rest mm 0.3667 \[0.1, 0.8\]" "$work/moved.txt" || fail "the after side's mean: $(cat "$work/moved.txt")"

# the report alone from what is there: the same verdict
bash "$script" --cases servo-c12 --report-only "$work/a" "$work/b" "$work/same" >"$work/again.txt" || fail "--report-only"
grep -q "before, 3 seeds" "$work/again.txt" || fail "--report-only lost the seeds: $(cat "$work/again.txt")"

# a malformed list of seeds: a usage error, nothing run
status=0
bash "$script" --seeds 2,x "$work/a" "$work/b" "$work/bad" 2>"$work/bad.err" || status=$?
[ "$status" = 2 ] || fail "--seeds 2,x exited $status, not 2"
grep -q "^error: --seeds" "$work/bad.err" || fail "no error line for --seeds 2,x"
[ ! -e "$work/bad" ] || fail "--seeds 2,x left $work/bad behind"
echo "compare-builds: seeds run, reported and judged"

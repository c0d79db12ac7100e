#!/usr/bin/env bash
# Behaviour unchanged, shown by outputs: runs the same programs, with fixed seeds and an evaluation
# budget, from two builds, and compares what they wrote (frames.csv, summary.json and the other
# tables), timings aside.
#
#   bash scripts/compare-builds.sh [--cases LIST] [--seeds LIST] [--reuse] [--report-only] BEFORE_BUILD AFTER_BUILD OUT
#
#   BEFORE_BUILD, AFTER_BUILD  build trees (their apps/ hold the programs), e.g. ../before/build build
#   OUT                        OUT/before/<case>/ and OUT/after/<case>/ receive the outputs;
#                              OUT/report.txt the comparison
#   --cases LIST               comma-separated subset of: servo-c12, servo-r2, servo-c12-viper850,
#                              servo-r2-viper850, track-table2, detect-all, compare-table2 (default: all)
#   --seeds LIST               comma-separated further noise seeds for the servo and track cases,
#                              each run into OUT/<side>/<case>/seed-<N>/ and compared as well; the
#                              report gives their key figures per seed, before and after, with the
#                              mean and range (a change that moves the outputs is judged against the
#                              seeds' own spread: C12's rotation at rest is 0.23-0.46 deg over five)
#   --reuse                    keep OUT/before/<case> when it is already there (the "before" build
#                              is run once, the "after" build after each change)
#   --report-only              run nothing: compare what OUT/before and OUT/after already hold
#
# Exit status 0 when every case is the same, 1 when one differs (the report says where, and which of
# summary.json's figures moved, before -> after), 2 on a usage error. A value is "the same" when it is
# equal, or both numbers within 1e-9 relative (two absolute paths: the same last three components).
# Ignored (they measure the machine, not the behaviour): columns and keys named with the words ms, s,
# seconds, time, fps, wall or memory (but converged_after_s, simulated time), and the tracker's
# settings (their layout changed with the configuration file's version 2; the values they hold are
# compared through the outputs).
set -euo pipefail
cd "$(dirname "$0")/.."

usage() { sed -n '5,28p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
cases="servo-c12,servo-r2,servo-c12-viper850,servo-r2-viper850,track-table2,detect-all,compare-table2"
seeds=""
reuse=0
report_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --cases) [ $# -ge 2 ] || usage; cases="$2"; shift 2 ;;
    --seeds) [ $# -ge 2 ] || usage; seeds="$2"; shift 2
      [[ "$seeds" =~ ^[0-9]+(,[0-9]+)*$ ]] || { echo "error: --seeds takes seeds like 2,3,4, not '$seeds'" >&2; exit 2; } ;;
    --reuse) reuse=1; shift ;;
    --report-only) report_only=1; shift ;;
    -h|--help) usage ;;
    -*) echo "error: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -eq 3 ] || usage
before="$(cd "$1" && pwd)"; after="$(cd "$2" && pwd)"; out="$3"
for b in "$before" "$after"; do
  [ -x "$b/apps/pm-servo" ] || { echo "error: $b/apps/pm-servo not found (build that tree first)" >&2; exit 2; }
done
mkdir -p "$out"
out="$(cd "$out" && pwd)"

# case name -> program and arguments (fixed seeds: the programs' defaults; an evaluation budget)
args_of() {
  case "$1" in
    servo-c12)          echo "pm-servo --target C12 --no-video --quiet --budget-evals 800" ;;
    servo-r2)           echo "pm-servo --target R2 --no-video --quiet --budget-evals 800" ;;
    servo-c12-viper850) echo "pm-servo --target C12 --robot viper850 --no-video --quiet --budget-evals 800" ;;
    servo-r2-viper850)  echo "pm-servo --target R2 --robot viper850 --no-video --quiet --budget-evals 800" ;;
    track-table2)       echo "pm-track --target C12 --quiet --budget-evals 800" ;;
    detect-all)         echo "pm-detect --all-targets --quiet --budget-evals 800 --max-time-s 3600" ;;
    compare-table2)     echo "pm-compare --target C12 --scenarios table2 --trackers ours-aa --quiet --budget-evals 800" ;;
    *) echo "error: unknown case '$1'" >&2; exit 2 ;;
  esac
}

seeded() { case "$1" in servo-*|track-*) return 0 ;; *) return 1 ;; esac; } # their programs take --seed

run_case() { # build side case [seed]
  local build="$1" side="$2" c="$3" dir="$out/$2/$3" cmd
  cmd="$(args_of "$c")"
  if [ -n "${4:-}" ]; then
    dir="$out/$2/$3/seed-$4"; cmd="$cmd --seed $4"
  fi
  if [ "$side" = before ] && [ "$reuse" = 1 ] && [ -f "$dir/summary.json" ]; then
    echo "  $side: kept from an earlier run" >&2
    return 0
  fi
  rm -rf "$dir"
  local t0=$SECONDS
  # shellcheck disable=SC2086
  local log="$out/$side-$c${4:+-seed-$4}.log"
  "$build/apps/"$cmd --out "$dir" >"$log" 2>&1 || { echo "error: $side $c${4:+ seed $4} failed (see $log)" >&2; return 1; }
  echo "  $side${4:+, seed $4}: $((SECONDS - t0)) s" >&2
}

IFS=',' read -r -a list <<<"$cases"
for c in "${list[@]}"; do
  args_of "$c" >/dev/null
  [ "$report_only" = 1 ] && continue
  echo "$c: $(args_of "$c")" >&2
  # the default seed keeps OUT/<side>/<case>/ as it was; the seeds' folders go inside it after it
  run_case "$before" before "$c"
  run_case "$after" after "$c"
  if seeded "$c" && [ -n "$seeds" ]; then
    IFS=',' read -r -a seed_list <<<"$seeds"
    for s in "${seed_list[@]}"; do
      run_case "$before" before "$c" "$s"
      run_case "$after" after "$c" "$s"
    done
  fi
done

python3 - "$out" "${list[@]}" <<'EOF'
import csv, json, math, os, re, sys

out, cases = sys.argv[1], sys.argv[2:]
# The key figures of a summary.json, per program (the servo's at rest, the tracker's over its frames).
KEY = {"servo": [("at rest mm", ("rms_error_mm", "at_rest")), ("at rest deg", ("rms_rotation_error_deg", "at_rest")),
                 ("servoed", ("frames_servoed",)), ("on a wrong pose", ("frames_servoed_on_wrong_pose",))],
       "track": [("rms mm", ("position_error_mm", "rms")), ("rms deg", ("rotation_error_deg", "rms")),
                 ("trusted", ("trusted_frames",)), ("wrong trusted", ("wrong_frames", "trusted"))]}
# Names that measure the machine: wall time, memory, speed.
TIMING = {"ms", "s", "seconds", "time", "fps", "wall", "memory"}  # words of a name (split at "_")
KEEP = {"converged_after_s", "hold_s", "move_s", "duration_s"}  # simulated time: behaviour
IGNORED_KEYS = {"tracker", "tracker_settings"}  # the configuration's layout (version 1 or 2)

ignored = set()
added = set()

def timing(name):
    t = name not in KEEP and any(w in TIMING for w in name.lower().split("_"))
    if t:
        ignored.add(name)
    return t

def settings(name, a, b):
    if name in IGNORED_KEYS and isinstance(a, dict) and isinstance(b, dict):
        ignored.add(name)
        return True
    return False

def tail(path):  # an absolute path names its checkout: compare what lies under it
    return "/".join(path.split("/")[-3:])

def same(a, b):
    if a == b:
        return True
    if isinstance(a, str) and isinstance(b, str) and a.startswith("/") and b.startswith("/"):
        return tail(a) == tail(b)
    try:
        x, y = float(a), float(b)
    except (TypeError, ValueError):
        return False
    if math.isnan(x) and math.isnan(y):
        return True
    return abs(x - y) <= 1e-9 * max(1.0, abs(x), abs(y))

def cmp_json(a, b, path, diffs):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if timing(k) or settings(k, a.get(k), b.get(k)):
                continue
            if k not in a or k not in b:
                diffs.append(f"{path}.{k}: only in {'after' if k in b else 'before'}")
            else:
                cmp_json(a[k], b[k], f"{path}.{k}", diffs)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            diffs.append(f"{path}: {len(a)} items before, {len(b)} after")
        for i, (x, y) in enumerate(zip(a, b)):
            cmp_json(x, y, f"{path}[{i}]", diffs)
    elif not same(a, b):
        diffs.append(f"{path}: {a!r} before, {b!r} after")

def figures(a, b, path, out):
    """The summary's numbers that moved, skipping lists of many items (per-target tables)."""
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) & set(b)):
            if not timing(k) and not settings(k, a[k], b[k]) and k != "by_tenth_of_the_run":
                figures(a[k], b[k], f"{path}.{k}" if path else k, out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool) and not same(a, b):
        out.append(f"{path} {a:.6g} -> {b:.6g}")

def cmp_csv(fa, fb, name, diffs):
    ra, rb = list(csv.reader(open(fa))), list(csv.reader(open(fb)))
    if not ra or not rb:
        diffs.append(f"{name}: empty")
        return 0
    head = ra[0]
    if ra[0] != rb[0]:
        gone = [h for h in ra[0] if h not in rb[0] and not timing(h)]
        if gone:
            diffs.append(f"{name}: columns gone after: {', '.join(gone)}")
            return 0
        added.update(h for h in rb[0] if h not in ra[0])
        # the columns both have, compared by name
        where = {h: i for i, h in enumerate(rb[0])}
        rb = [[r[where[h]] if where[h] < len(r) else "" for h in head if h in where] for r in rb]
        ra = [[r[i] if i < len(r) else "" for i, h in enumerate(head) if h in where] for r in ra]
        head = [h for h in head if h in where]
    cols = [i for i, h in enumerate(head) if not timing(h)]
    if len(ra) != len(rb):
        diffs.append(f"{name}: {len(ra) - 1} rows before, {len(rb) - 1} after")
    bad = 0
    for r, (x, y) in enumerate(zip(ra[1:], rb[1:]), 1):
        for i in cols:
            if i >= len(x) or i >= len(y) or not same(x[i], y[i]):
                if bad < 5:
                    diffs.append(f"{name} row {r} column {head[i]}: {x[i] if i < len(x) else '-'} before, "
                                 f"{y[i] if i < len(y) else '-'} after")
                bad += 1
    if bad > 5:
        diffs.append(f"{name}: {bad} values differ in all")
    return len(ra) - 1

def key_figures(path, keys):
    try:
        summary = json.load(open(path))
        values = []
        for _, where in keys:
            v = summary
            for k in where:
                v = v[k]
            values.append(float(v))
        return values
    except (OSError, ValueError, KeyError, TypeError):
        return None

def seed_spread(c, a, b):
    """The key figures per seed (the default and OUT/<side>/<case>/seed-N), before -> after, mean and range."""
    keys = KEY.get(c.split("-")[0])
    runs = sorted(n for n in os.listdir(a) if n.startswith("seed-")) if os.path.isdir(a) else []
    if not keys or not runs:
        return []
    lines = ["  key figures per seed, before -> after: " + "; ".join(n for n, _ in keys)]
    per = {"before": [], "after": []}
    for r in ["default"] + runs:
        sub = "" if r == "default" else r
        fa, fb = key_figures(os.path.join(a, sub, "summary.json"), keys), key_figures(os.path.join(b, sub, "summary.json"), keys)
        if fa is None or fb is None:
            lines.append(f"    {r}: missing")
            continue
        per["before"].append(fa)
        per["after"].append(fb)
        lines.append(f"    {r}: " + "; ".join(f"{x:.4g} -> {y:.4g}" for x, y in zip(fa, fb)))
    for side in ("before", "after"):
        v = per[side]
        if v:
            cols = list(zip(*v))
            lines.append(f"    {side}, {len(v)} seeds: " + "; ".join(
                f"{n} {sum(x) / len(x):.4g} [{min(x):.4g}, {max(x):.4g}]" for (n, _), x in zip(keys, cols)))
    return lines

report, failed = [], False
for c in cases:
    a, b = os.path.join(out, "before", c), os.path.join(out, "after", c)
    diffs, files, rows = [], 0, 0
    ignored.clear()
    for root, _, names in os.walk(a):
        for n in sorted(names):
            rel = os.path.relpath(os.path.join(root, n), a)
            fa, fb = os.path.join(a, rel), os.path.join(b, rel)
            if not (n.endswith(".csv") or n.endswith(".json")):
                continue
            if not os.path.exists(fb):
                diffs.append(f"{rel}: missing after")
                continue
            files += 1
            if n.endswith(".json"):
                cmp_json(json.load(open(fa)), json.load(open(fb)), rel, diffs)
            else:
                rows += cmp_csv(fa, fb, rel, diffs)
    verdict = "same" if not diffs else "DIFFERENT"
    if diffs:  # what moved: the summary's figures, before and after
        sa, sb = os.path.join(a, "summary.json"), os.path.join(b, "summary.json")
        if os.path.exists(sa) and os.path.exists(sb):
            moved = []
            figures(json.load(open(sa)), json.load(open(sb)), "", moved)
            diffs = ["figures: " + m for m in moved[:24]] + diffs
    failed |= bool(diffs)
    report.append(f"{c}: {verdict} ({files} files compared, {rows} table rows)")
    report += ["  " + d for d in diffs[:40]]
    report += seed_spread(c, a, b)
    report.append("  not compared (timings, settings' layout): " + ", ".join(sorted(ignored)))
if added:
    report.append("  columns added after (not compared): " + ", ".join(sorted(added)))
text = "\n".join(report) + "\n"
open(os.path.join(out, "report.txt"), "w").write(text)
print(text, end="")
sys.exit(1 if failed else 0)
EOF

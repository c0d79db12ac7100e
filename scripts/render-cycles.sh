#!/usr/bin/env bash
# The second renderer's fixed set of scenes: each lab toy exported (pm-export-scene) and rendered by
# Blender's Cycles (scripts/cycles/render.py) into a views folder and a sequence with its truth.
#   bash scripts/render-cycles.sh [DIR] [SCENE...]
# DIR: where the set is kept, outside the repository (default: $PM_CYCLES_DIR, else
# ~/.cache/visp-photomodel/cycles). SCENE: some of the names below (default: all). About 20 minutes
# a scene on 2 cores; an interrupted run resumes where it stopped. Needs a Release build (bash
# scripts/test.sh) and Blender (apt-get install blender). The tests that read the set find it at
# $PM_CYCLES_DIR or the default, and skip with a reason when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; esac
dir=${1:-${PM_CYCLES_DIR:-$HOME/.cache/visp-photomodel/cycles}}
shift || true
command -v blender >/dev/null || { echo "error: Blender is not installed (apt-get install blender)" >&2; exit 1; }
[ -x build/apps/pm-export-scene ] || { echo "error: no build/apps/pm-export-scene (build first: bash scripts/test.sh)" >&2; exit 1; }

# name: pm-export-scene's options. A toy of one hue (C06, and R2's skin), steep relief (R2, R1's
# cardboard sides), two backdrops (the sea bottom, a green cloth), one of them standing still.
# c05_cloth is held out of the design of issue 56: rendered with the others, measured once at the end.
declare -A scenes=(
  [c12_sea]="--target C12"
  [r2_sea]="--target R2"
  [r1_cloth]="--target R1 --backdrop cloth"
  [c06_cloth]="--target C06 --backdrop cloth"
  [r2_still]="--target R2 --backdrop cloth --still-backdrop"
  [c05_cloth]="--target C05 --backdrop cloth"
)
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(c12_sea r2_sea r1_cloth c06_cloth r2_still c05_cloth)
mkdir -p "$dir"
for n in "${names[@]}"; do
  [ -n "${scenes[$n]+x}" ] || { echo "error: unknown scene '$n' (${!scenes[*]})" >&2; exit 2; }
  if [ ! -f "$dir/$n/scene.json" ]; then
    # shellcheck disable=SC2086
    build/apps/pm-export-scene --out "$dir/$n" ${scenes[$n]}
  fi
  echo "rendering $n with Cycles into $dir/$n" >&2
  blender -b --factory-startup -P scripts/cycles/render.py -- "$dir/$n" --samples 16 2>&1 | grep -E "^(pass view|sequence frame|rendered|error)" || {
    echo "error: Blender failed on $n (run: blender -b --factory-startup -P scripts/cycles/render.py -- $dir/$n)" >&2; exit 1; }
done
echo "the set is in $dir" >&2

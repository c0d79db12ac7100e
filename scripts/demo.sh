#!/usr/bin/env bash
# The main job on the shipped defaults: installs what is missing, builds, then runs pm-servo:
# the PA-10 follows the C12 crab, moved through Table 2's steps by the TC-robot, by visual
# servoing on the photo-model tracker's pose; prints a short summary. Outputs (plots, video,
# CSV, summary.json) in results/servo/. Extra arguments go to pm-servo.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
pm_setup release
"$PM_BUILD_DIR/apps/pm-servo" --out results/servo "$@"

#!/usr/bin/env bash
# The main job on the shipped defaults: installs what is missing, builds, then makes the
# photo-model of the C12 crab from the simulated lab (the photos of the paper's Fig. 4) and
# prints a short summary. Outputs in results/demo/. Extra arguments go to pm-make-model.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/setup.sh
pm_setup release
"$PM_BUILD_DIR/apps/pm-make-model" --target C12 --out results/demo "$@"

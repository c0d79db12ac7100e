#!/usr/bin/env bash
# The docs check (CTest runs it as docs_commands; CI through scripts/test.sh):
#   1. runs the ```sh blocks of every docs/tutorial-*.md as written, two pages at a time, each page in a
#      fresh folder that holds data/, examples/ and build/ (links to the repository's and to the
#      build tree), with bash -euo pipefail: a command that fails fails the check;
#   2. checks every command line shown in README.md and docs/*.md (code blocks and `pm-...` spans):
#      the program exists and each --option it names is in that program's --help;
#   3. checks that every ```cpp block of docs/ is a verbatim part of a source file in examples/, and
#      every ```python block a verbatim part of a script in examples/python/.
# A tutorial that runs on sample data of a Debian package says so in a line of its own,
#   <!-- docs-check: needs PATH (PACKAGE) -->
# and is skipped, with a line that says why, when PATH is missing (a machine without that package).
# usage: bash scripts/docs-check.sh BUILD_DIR [--only PAGE.md]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: bash scripts/docs-check.sh BUILD_DIR [--only PAGE.md]}" && pwd)"
only="${3:-}"
[ "${2:-}" = "--only" ] || only=""
apps="$build/apps"
[ -x "$apps/pm-track" ] || { echo "error: no programs in $apps (build first)" >&2; exit 1; }
scratch="$(mktemp -d "${TMPDIR:-/tmp}/pm-docs-check.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# --- 2. options of every command shown --------------------------------------------------------
# Prints "file:line<TAB>command" for each command line of a code block (fenced or indented, with
# backslash continuations joined) and each `pm-...` span of the prose.
commands_of() {
  awk -v F="$1" '
    function flush() { if (cmd != "") print F ":" start "\t" cmd; cmd = "" }
    /^```/ { fenced = !fenced; flush(); next }
    {
      line = $0
      code = fenced || line ~ /^    /
      if (code) {
        sub(/^ +/, "", line); sub(/^\$ /, "", line)
        if (cmd != "") { cmd = cmd " " line } else if (line ~ /^pm-[a-z-]+( |$)/) { cmd = line; start = NR }
        if (cmd != "" && cmd ~ /\\$/) { sub(/\\$/, "", cmd); next }
        flush(); next
      }
      rest = line
      while (match(rest, /`pm-[a-z-]+ [^`]*`/)) {
        print F ":" NR "\t" substr(rest, RSTART + 1, RLENGTH - 2)
        rest = substr(rest, RSTART + RLENGTH)
      }
    }' "$1"
}
declare -A helptext
checked=0
for page in "$root"/README.md "$root"/docs/*.md; do
  while IFS=$'\t' read -r where cmd; do
    cmd="${cmd%%  #*}"; cmd="${cmd%% # *}"
    prog="${cmd%% *}"
    if [ ! -x "$apps/$prog" ]; then fail "${where#$root/}: no program $prog"; continue; fi
    if [ -z "${helptext[$prog]+x}" ]; then helptext[$prog]="$("$apps/$prog" --help 2>&1 || true)"; fi
    for opt in $(grep -oE '(^| )--[a-z][a-z0-9_-]*' <<<"$cmd" | tr -d ' ' | sort -u); do
      grep -qE -- "(^|[ ,\[])$opt([ =,]|$)" <<<"${helptext[$prog]}" ||
        fail "${where#$root/}: $prog has no option $opt (see $prog --help)"
    done
    checked=$((checked + 1))
  done < <(commands_of "$page")
done
echo "docs: $checked command lines checked against the programs' --help"

# --- 3. code shown is code built -----------------------------------------------------------------
# shown_in_examples LANG FILES...: every ```LANG block of docs/ is a verbatim part of one of FILES.
shown_in_examples() {
  local lang="$1" page block src found
  shift
  for page in "$root"/docs/*.md; do
    awk -v L="$lang" '$0 == "```" L { n++; on = 1; next } /^```/ { on = 0 } on { print > (OUT "." n) }' OUT="$scratch/$lang" "$page"
    for block in "$scratch/$lang".*; do
      [ -e "$block" ] || continue
      found=0
      for src in "$@"; do
        grep -qzF -- "$(cat "$block")" "$src" && { found=1; break; }
      done
      [ "$found" = 1 ] || fail "${page#$root/}: a $lang block is not in any file of examples/ (docs drifted from the code)"
      rm -f "$block"
    done
  done
}
mapfile -t cpp_sources < <(find "$root/examples" -name '*.cpp' -o -name 'CMakeLists.txt')
mapfile -t python_sources < <(find "$root/examples/python" -name '*.py')
shown_in_examples cpp "${cpp_sources[@]}"
shown_in_examples python "${python_sources[@]}"

# --- 1. run the tutorials --------------------------------------------------------------------------
# Two pages at a time (each in its own folder; the lab's programs build their models, which takes
# most of the time): the pages' outcomes are reported in their order once all have run.
run_page() { # run_page NAME DIR: the page's blocks in DIR; DIR/status holds "ran SECONDS" or "failed"
  local start
  start=$(date +%s)
  if (cd "$2" && bash run.sh > "$2/log" 2>&1); then
    echo "ran $(($(date +%s) - start))" > "$2/status"
  else
    echo failed > "$2/status"
  fi
}
pages=()
for page in "$root"/docs/tutorial-*.md; do
  name="$(basename "$page" .md)"
  [ -z "$only" ] || [ "$only" = "$name.md" ] || continue
  missing=""
  while read -r need what; do
    [ -e "$need" ] || missing="$need $what"
  done < <(sed -n 's/^<!-- docs-check: needs \([^ ]*\) \(.*\) -->$/\1 \2/p' "$page")
  if [ -n "$missing" ]; then
    echo "docs: $name.md skipped: it needs ${missing} (install it to run this page)"
    continue
  fi
  dir="$scratch/$name"
  mkdir -p "$dir"
  ln -s "$root/data" "$dir/data"
  ln -s "$root/examples" "$dir/examples"
  ln -s "$build" "$dir/build"
  {
    echo 'set -euo pipefail'
    awk '/^```sh/ { on = 1; n++; print "echo \"--- block " n "\" >&2"; next } /^```/ { on = 0 } on' "$page"
  } > "$dir/run.sh"
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n || true; done
  run_page "$name" "$dir" &
  pages+=("$name")
done
wait
for name in "${pages[@]}"; do
  dir="$scratch/$name"
  status="$(cat "$dir/status" 2>/dev/null || echo failed)"
  if [ "${status%% *}" = ran ]; then
    echo "docs: $name.md ran (${status#ran } s)"
  else
    tail -20 "$dir/log" >&2
    fail "$name.md: a command failed (its output above)"
  fi
done

if [ "$failures" -gt 0 ]; then
  echo "docs check: $failures failure(s)" >&2
  exit 1
fi
echo "docs check: passed"

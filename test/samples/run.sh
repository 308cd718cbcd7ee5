#!/usr/bin/env bash
# test/samples/run.sh: povml's coverage of POV-Ray's own sample scenes (`make samples`).
#
# Renders every .pov under the POV-Ray 3.7 sample directory (Debian package povray-examples) with
# povml and with POV-Ray at 160x120, single-threaded (+WT1), without antialiasing, each under a
# timeout, and writes docs/samples.tsv (one row per scene) and docs/samples.md (totals, the first
# blockers counted, the per-scene table). Per scene it records povml's status (renders, error,
# crash, timeout), povml's first error without its location, POV-Ray's status, the number of
# differing pixels (any channel, no tolerance; test/tools/imgdiff, lib/image/compare.ml) when both
# rendered, and the CPU seconds (user + system) of each render, with its wall seconds in the TSV.
#
# Each render runs in its own empty working directory under a temporary directory, with +L for the
# scene's own directory (its include files, image maps, data files) and the standard include
# directory; povml may write only there (--allow-write), so scenes that #fopen ... write work.
# Animation scenes are rendered alone, with clock = 0. Scenes are found with find -L, sorted.
#
# Environment:
#   ONLY=REGEX        only the scenes whose path (relative to the sample directory) matches REGEX
#                     (grep -E); the results then go to the temporary directory, not to docs/
#   SAMPLES_JOBS=N    scenes rendered at once (default 2; a scene renders with povml, then POV-Ray)
#   SAMPLES_TIMEOUT=S seconds allowed for each render (default 120)
#   SAMPLES_OUT=DIR   where samples.md and samples.tsv go (default docs/, or the temporary directory
#                     with ONLY)
#   SAMPLES_KEEP=1    keep the temporary directory (images, logs) instead of removing it
#   SAMPLES_DIR=DIR   the sample scenes (default /usr/share/povray-3.7/scenes)
#   POVRAY=PATH       POV-Ray's executable (default povray)
# Run from the repository root after dune build; prints the totals at the end.
set -euo pipefail

# ------------------------------------------------------------------------------------------------
# One scene: `run.sh --one WORKDIR RELPATH` appends nothing to stdout; it writes WORKDIR/rows/ID.tsv.

include_dir=/usr/share/povray-3.7/include

# The first error of a povml log without "file:line:col: error: " or "povml: ", with the lines that
# continue it (an #error's text) up to the source excerpt or the first note.
povml_message() {
  awk '
    !found && /(^|: )error: |^povml: |Fatal error|^Exception/ {
      found = 1; m = $0
      sub(/^.*: error: /, "", m); sub(/^error: /, "", m); sub(/^povml: /, "", m); next }
    found && (/^ *[0-9]* \| / || /: note: /) { exit }
    found && /[^[:space:]]/ { l = $0; gsub(/^[[:space:]]+|[[:space:]]+$/, "", l); m = m (m ~ / $/ ? "" : " ") l }
    /[^[:space:]]/ { last = $0 }
    END { if (!found) m = last; gsub(/\t/, " ", m); print substr(m, 1, 300) }' "$1"
}

# POV-Ray's first error ("Possible Parse Error: …" is a warning), with the lines it is wrapped into
# (they start with a space), without the "File … line N:" before or in it.
povray_message() {
  awk '
    !found && tolower($0) ~ /error/ && $0 !~ /Possible/ {
      found = 1; m = $0; sub(/^ +/, "", m); sub(/^File .* line [0-9]+: /, "", m); next }
    found && /^ / { l = $0; sub(/^ +/, "", l); m = m " " l; next }
    found { exit }
    /[^[:space:]]/ { last = $0 }
    END { if (!found) m = last; gsub(/\t/, " ", m); print substr(m, 1, 300) }' "$1"
}

# "user system wall" from GNU time's -o file (its last line; earlier lines say how the command ended)
# as "cpu<TAB>wall" in seconds.
times_of() {
  if [ -s "$1" ]; then tail -n1 "$1" | awk '{ printf "%.2f\t%.2f", $1 + $2, $3 }'; else printf -- '-\t-'; fi
}

one_scene() {
  local work=$1 rel=$2
  local scenes=${SAMPLES_DIR:-/usr/share/povray-3.7/scenes}
  local povml=${POVML:?} povray=${POVRAY:-povray} limit=${SAMPLES_TIMEOUT:-120}
  local scene=$scenes/$rel sdir id d rc
  sdir=$(dirname "$scene")
  id=${rel%.pov}; id=${id//\//__}
  d=$work/scenes/$id
  rm -rf "$d"; mkdir -p "$d/povml" "$d/povray"
  local size=(+W160 +H120 -D -V -A +FN +WT1)

  # povml, and POV-Ray below, read the same empty ini file: the system's would add its own size,
  # display and bounding threshold
  : >"$d/empty.ini"
  set +e
  (cd "$d/povml" && POVINI="$d/empty.ini" nice -n 15 /usr/bin/time -o "$d/povml.time" -f '%U %S %e' \
     timeout -k 5 "$limit" "$povml" "+I$scene" "+O$d/povml.png" "${size[@]}" "+L$sdir" \
     --allow-write "$d/povml" </dev/null >"$d/povml.log" 2>&1)
  rc=$?
  set -e
  local status msg
  if [ "$rc" -eq 0 ] && [ -s "$d/povml.png" ]; then status=renders; msg=""
  elif [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then status=timeout; msg="no image after ${limit} s"
  elif [ "$rc" -eq 70 ] || [ "$rc" -ge 128 ] || grep -q -E 'internal error|Fatal error|Raised at|^Exception' "$d/povml.log"; then
    status=crash; msg="$(povml_message "$d/povml.log") (exit $rc)"
  else status=error; msg=$(povml_message "$d/povml.log")
  fi

  # POV-Ray. On a busy machine its front end may give up "waiting for worker thread startup" at
  # once: then it is run again.
  local attempt
  for attempt in 1 2 3; do
    set +e
    (cd "$d/povray" && POVINI="$d/empty.ini" nice -n 15 /usr/bin/time -o "$d/povray.time" -f '%U %S %e' \
       timeout -k 5 "$limit" "$povray" "+I$scene" "+O$d/povray.png" "${size[@]}" "+L$sdir" "+L$include_dir" \
       </dev/null >"$d/povray.log" 2>&1)
    rc=$?
    set -e
    grep -q 'Timed out waiting for worker thread startup' "$d/povray.log" || break
    cp "$d/povray.log" "$d/povray-startup-$attempt.log"
  done
  local pstatus pmsg
  if [ "$rc" -eq 0 ] && [ -s "$d/povray.png" ]; then pstatus=renders; pmsg=""
  elif [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then pstatus=timeout; pmsg="no image after ${limit} s"
  elif [ "$rc" -ge 128 ]; then pstatus=crash; pmsg="$(povray_message "$d/povray.log") (exit $rc)"
  else pstatus=error; pmsg=$(povray_message "$d/povray.log")
  fi

  # differing pixels
  local diff="-"
  if [ "$status" = renders ] && [ "$pstatus" = renders ]; then
    local out
    if out=$(nice -n 15 "$IMGDIFF" "$d/povml.png" "$d/povray.png" 2>"$d/imgdiff.log"); then
      diff=$(printf '%s' "$out" | sed -E -n 's/^differing ([0-9]+)\/.*/\1/p')
    else
      diff="?"; msg="comparison failed: $(head -n1 "$d/imgdiff.log")"
    fi
  fi

  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$status" "$msg" "$pstatus" "$diff" \
    "$(times_of "$d/povml.time")" "$(times_of "$d/povray.time")" "$pmsg" >"$work/rows/$id.tsv"
}

if [ "${1:-}" = "--one" ]; then
  one_scene "$2" "$3"
  exit 0
fi

# ------------------------------------------------------------------------------------------------
# All scenes.

root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
scenes=${SAMPLES_DIR:-/usr/share/povray-3.7/scenes}
jobs=${SAMPLES_JOBS:-2}
export POVML=$root/_build/default/bin/main.exe
export IMGDIFF=$root/_build/default/test/tools/imgdiff.exe
for exe in "$POVML" "$IMGDIFF"; do
  [ -x "$exe" ] || { echo "run.sh: $exe is missing: run dune build first" >&2; exit 2; }
done
command -v "${POVRAY:-povray}" >/dev/null || { echo "run.sh: POV-Ray not found (apt-get install povray)" >&2; exit 2; }
[ -d "$scenes" ] || { echo "run.sh: no sample scenes in $scenes (apt-get install povray-examples)" >&2; exit 2; }
# POV-Ray complains on every run without a user configuration file
mkdir -p "$HOME/.povray/3.7" && touch "$HOME/.povray/3.7/povray.conf"

work=$(mktemp -d "${TMPDIR:-/tmp}/povml-samples.XXXXXX")
mkdir -p "$work/rows"
if [ "${SAMPLES_KEEP:-}" != 1 ]; then trap 'rm -rf "$work"' EXIT; fi
out=${SAMPLES_OUT:-}
if [ -z "$out" ]; then if [ -n "${ONLY:-}" ]; then out=$work; else out=$root/docs; fi; fi
mkdir -p "$out"

(cd "$scenes" && find -L . -name '*.pov' -type f | sed 's|^\./||' | LC_ALL=C sort) >"$work/all.txt"
if [ -n "${ONLY:-}" ]; then grep -E -- "$ONLY" "$work/all.txt" >"$work/list.txt" || true
else cp "$work/all.txt" "$work/list.txt"; fi
count=$(wc -l <"$work/list.txt")
[ "$count" -gt 0 ] || { echo "run.sh: no scene matches ONLY=$ONLY" >&2; exit 2; }

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then commit="$commit (with uncommitted changes)"; fi
started=$(date +%s)
echo "run.sh: $count scenes, $jobs at a time, ${SAMPLES_TIMEOUT:-120} s per render; work in $work" >&2

export SAMPLES_DIR SAMPLES_TIMEOUT POVRAY
tr '\n' '\0' <"$work/list.txt" | xargs -0 -P "$jobs" -n 1 bash "$root/test/samples/run.sh" --one "$work"
elapsed=$(( $(date +%s) - started ))

# ------------------------------------------------------------------------------------------------
# The TSV: the header, then the rows in the scenes' order.

tsv=$out/samples.tsv
{
  printf 'scene\tpovml\tpovml_error\tpovray\tdiffering_pixels\tpovml_cpu_s\tpovml_wall_s\tpovray_cpu_s\tpovray_wall_s\tpovray_error\n'
  while IFS= read -r rel; do
    id=${rel%.pov}; id=${id//\//__}
    if [ -s "$work/rows/$id.tsv" ]; then cat "$work/rows/$id.tsv"
    else printf '%s\tcrash\tthe sample script lost this scene\t-\t-\t-\t-\t-\t-\t\n' "$rel"; fi
  done <"$work/list.txt"
} >"$tsv"

# The first blockers, most frequent first (blockers.awk says what a blocker is).
blockers() {
  awk -F'\t' -f "$root/test/samples/blockers.awk" "$tsv" | LC_ALL=C sort -t$'\t' -k1,1nr -k2,2
}

# ------------------------------------------------------------------------------------------------
# The Markdown page.

md=$out/samples.md
total=$(awk 'END { print NR - 1 }' "$tsv")
read -r renders identical differ unpaired errors crashes timeouts prenders < <(awk -F'\t' 'NR > 1 {
    if ($2 == "renders") { r++; if ($5 == "0") i++; else if ($5 ~ /^[0-9]+$/) d++; else u++ }
    else if ($2 == "error") e++; else if ($2 == "crash") c++; else if ($2 == "timeout") t++
    if ($4 == "renders") p++ }
  END { print r+0, i+0, d+0, u+0, e+0, c+0, t+0, p+0 }' "$tsv")
totals="$renders of $total render with povml: $identical identical to POV-Ray, $differ differ"
[ "$unpaired" -eq 0 ] || totals="$totals, $unpaired not compared (POV-Ray gave no image)"
top=$(blockers | { grep -v -F '(POV-Ray fails too)' || true; } | head -n 12 | awk -F'\t' '{ printf "%s%s %d", (NR > 1 ? ", " : ""), $2, $1 }')
povray_version=$("${POVRAY:-povray}" --version 2>&1 | head -n1 || true)

{
  echo "# POV-Ray's sample scenes in povml"
  echo
  echo "The $total scenes of POV-Ray 3.7's own sample set (Debian package povray-examples, the .pov files"
  echo "under $scenes), each rendered with povml and with POV-Ray ($povray_version) at 160×120,"
  echo "\`+WT1 -A -D -V +FN\`, in an empty working directory with \`+L\` for the scene's directory, and"
  echo "${SAMPLES_TIMEOUT:-120} s allowed per render. Animation scenes are rendered alone (clock = 0)."
  echo "Made by \`make samples\` (test/samples/run.sh) on $(date -u +%Y-%m-%d) from povml commit $commit;"
  echo "the run took $elapsed s of wall time with ${jobs} scenes at a time. The same rows are in samples.tsv."
  echo
  echo "Differing pixels are those with any channel different (no tolerance), counted by"
  echo "test/tools/imgdiff (lib/image/compare.ml). Times are CPU seconds (user + system) of the"
  echo "whole process: parsing, rendering and writing the PNG (samples.tsv also has the wall seconds)."
  echo
  echo "## Totals"
  echo
  echo "- **$totals.**"
  echo "- povml: $errors stop at an error, $crashes crash, $timeouts time out."
  echo "- POV-Ray renders $prenders of $total."
  echo
  echo "## First blockers"
  echo
  echo "The keyword of povml's first error, counted over the scenes it stops: $top …"
  echo "The scenes POV-Ray cannot render either (its error, not a timeout) count as one row, whatever"
  echo "povml says; test/samples/blockers.awk says how a message becomes a keyword."
  echo
  echo "| scenes | first blocker |"
  echo "|---:|---|"
  blockers | awk -F'\t' '{ gsub(/\|/, "\\|", $2); printf "| %d | %s |\n", $1, $2 }'
  echo
  echo "## Scenes"
  echo
  echo "| scene | povml | povml's first error | POV-Ray | differing pixels | povml s | POV-Ray s |"
  echo "|---|---|---|---|---:|---:|---:|"
  awk -F'\t' 'NR > 1 {
      for (i = 1; i <= NF; i++) gsub(/\|/, "\\|", $i)
      e = ($3 == "" ? "" : "`" $3 "`")
      printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, e, $4, $5, $6, $8 }' "$tsv"
} >"$md"

echo "run.sh: wrote $md and $tsv in $elapsed s" >&2
[ "${SAMPLES_KEEP:-}" != 1 ] || echo "run.sh: images and logs kept in $work" >&2
echo "$totals"
echo "povml: $errors errors, $crashes crashes, $timeouts timeouts; POV-Ray renders $prenders of $total"
echo "first blockers: $top"

#!/usr/bin/env bash
# make bench: povml against POV-Ray 3.7 on the benchmark scenes, same switches, same thread count,
# several runs each, one after the other. Prints a Markdown table of median wall times, peak memory
# and the povml/POV-Ray ratio.
set -euo pipefail
cd "$(dirname "$0")/../.."
RUNS=${RUNS:-5}
THREADS=${THREADS:-2}
POVML=./_build/default/bin/main.exe
command -v povray >/dev/null || { echo "bench: POV-Ray (Debian package povray) is not installed" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "bench: /usr/bin/time (Debian package time) is not installed" >&2; exit 1; }
mkdir -p "$HOME/.povray/3.7" && touch "$HOME/.povray/3.7/povray.conf"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# scene|switches
CASES=(
  "scenes/bench/spheres.pov|+W640 +H480 +A0.3"
  "scenes/bench/spheres.pov|+W640 +H480 -A"
)

# median of the numbers on stdin
median() { sort -g | awk '{a[NR]=$1} END {if (NR%2) print a[(NR+1)/2]; else printf "%.4f\n", (a[NR/2]+a[NR/2+1])/2}'; }

# run_one LABEL CMD... : prints "seconds kilobytes" for each of RUNS runs
measure() {
  local out=$1; shift
  : > "$out"
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%e %M" -o "$tmp/t" "$@" >/dev/null 2>&1
    cat "$tmp/t" >> "$out"
  done
}

printf '| scene | switches | povml (s) | POV-Ray (s) | ratio | povml peak MB | POV-Ray peak MB |\n'
printf '|---|---|---:|---:|---:|---:|---:|\n'
for c in "${CASES[@]}"; do
  scene=${c%%|*}; sw=${c#*|}
  # shellcheck disable=SC2086
  measure "$tmp/ml" $POVML +I"$scene" +O"$tmp/ml.png" $sw -D +WT"$THREADS"
  # shellcheck disable=SC2086
  measure "$tmp/pov" povray +I"$scene" +O"$tmp/pov.png" $sw -D -V +WT"$THREADS"
  tm=$(awk '{print $1}' "$tmp/ml" | median); tp=$(awk '{print $1}' "$tmp/pov" | median)
  mm=$(awk '{print $2/1024}' "$tmp/ml" | median); mp=$(awk '{print $2/1024}' "$tmp/pov" | median)
  ratio=$(awk -v a="$tm" -v b="$tp" 'BEGIN {printf "%.2f", a/b}')
  printf '| %s | %s | %.3f | %.3f | %s | %.0f | %.0f |\n' "$(basename "$scene")" "$sw" "$tm" "$tp" "$ratio" "$mm" "$mp"
done
echo
echo "median of $RUNS runs each, $THREADS threads, $(nproc) cores; ratio = povml / POV-Ray wall time (below 1.00: povml is faster)"

#!/usr/bin/env bash
# make bench: povml against POV-Ray 3.7 on the benchmark scenes, same switches, both with the same
# thread count, several runs each, one program after the other. Prints a Markdown table of median
# times (parse, build = bounding, render, total wall) and peak memory, with the povml/POV-Ray
# ratio, then the render-time series of the sphere fields (1k, 10k, 100k and 1M spheres at one image size).
#
# The large scenes are generated into scenes/bench/generated/ by the generators in
# scenes/bench/gen/ (a 1,000,000-triangle mesh2 terrain, a 100,000-smooth-triangle mesh, sphere
# fields (one of a million spheres each with a texture of its own), a field of mixed shapes: boxes, cylinders, cones, discs, tori; with scenes/bench/gen_hfield.sh
# the 1024×1024 16-bit height map of scenes/bench/hfield.pov); scenes/bench/isosurface.pov times
# the compiled functions in isosurfaces' root searches. Both programs get +L of the scene's
# directory (POV-Ray does not look there for image files). RUNS (default 3) and
# THREADS (default 2) can be set in the environment; ONLY=PATTERN runs only the cases whose scene
# path contains PATTERN (e.g. ONLY=shapes).
set -euo pipefail
cd "$(dirname "$0")/../.."
RUNS=${RUNS:-3}
THREADS=${THREADS:-2}
POVML=./_build/default/bin/main.exe
GEN=./_build/default/scenes/bench/gen
OUT=scenes/bench/generated
command -v povray >/dev/null || { echo "bench: POV-Ray (Debian package povray) is not installed" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "bench: /usr/bin/time (Debian package time) is not installed" >&2; exit 1; }
mkdir -p "$HOME/.povray/3.7" && touch "$HOME/.povray/3.7/povray.conf"
mkdir -p "$OUT"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

[ -f "$OUT/terrain.pov" ] || "$GEN/gen_terrain.exe" "$OUT/terrain.pov"
[ -f "$OUT/smooth.pov" ] || "$GEN/gen_smooth.exe" "$OUT/smooth.pov"
for n in 1000 10000 100000 1000000; do [ -f "$OUT/spheres_$n.pov" ] || "$GEN/gen_spheres.exe" "$OUT/spheres_$n.pov" "$n"; done
[ -f "$OUT/colours_1000000.pov" ] || "$GEN/gen_spheres.exe" "$OUT/colours_1000000.pov" 1000000 colours
[ -f "$OUT/shapes_2000.pov" ] || "$GEN/gen_shapes.exe" "$OUT/shapes_2000.pov" 2000
[ -f "$OUT/hfield_1024.png" ] || bash scenes/bench/gen_hfield.sh "$OUT/hfield_1024.png"

# scene|switches
CASES=(
  "scenes/bench/spheres.pov|+W640 +H480 +A0.3"
  "$OUT/terrain.pov|+W640 +H480 -A"
  "$OUT/smooth.pov|+W640 +H480 -A"
  "$OUT/spheres_1000.pov|+W640 +H480 -A"
  "$OUT/spheres_10000.pov|+W640 +H480 -A"
  "$OUT/spheres_100000.pov|+W640 +H480 -A"
  "$OUT/spheres_1000000.pov|+W640 +H480 -A"
  "$OUT/colours_1000000.pov|+W640 +H480 -A"
  "scenes/bench/while_spheres.pov|+W640 +H480 -A"
  "$OUT/shapes_2000.pov|+W640 +H480 -A"
  "$OUT/shapes_2000.pov|+W640 +H480 +A0.3"
  "scenes/bench/textures.pov|+W640 +H480 +A0.3"
  "scenes/bench/hfield.pov|+W640 +H480 -A"
  "scenes/bench/isosurface.pov|+W640 +H480 -A"
)

median() { sort -g | awk '{a[NR]=$1} END {if (NR%2) print a[(NR+1)/2]; else printf "%.4f\n", (a[NR/2]+a[NR/2+1])/2}'; }

# the seconds in "... (1.234 seconds)" on the line starting with $1
secs() { grep -E "^ *$1" "$2" | head -1 | grep -o '([0-9.]* seconds)' | tr -d '(a-z )'; }

# measure FILE PARSE_LABEL BUILD_LABEL RENDER_LABEL CMD…: one line "parse build render wall kb" per run
measure() {
  local out=$1 pl=$2 bl=$3 rl=$4; shift 4
  : > "$out"
  for _ in $(seq "$RUNS"); do
    /usr/bin/time -f "%e %M" -o "$tmp/t" "$@" > "$tmp/log" 2>&1
    echo "$(secs "$pl" "$tmp/log") $(secs "$bl" "$tmp/log") $(secs "$rl" "$tmp/log") $(cat "$tmp/t")" >> "$out"
  done
}
col() { awk -v c="$1" '{print $c}' "$2" | median; }

printf '| scene | switches | | parse s | build s | render s | total s | peak MB | ratio (total) |\n'
printf '|---|---|---|---:|---:|---:|---:|---:|---:|\n'
for c in "${CASES[@]}"; do
  scene=${c%%|*}; sw=${c#*|}
  case $scene in *"${ONLY:-}"*) ;; *) continue ;; esac
  # shellcheck disable=SC2086
  measure "$tmp/ml" "Parse Time" "Bounding Time" "Render Time" $POVML +I"$scene" +L"$(dirname "$scene")" +O"$tmp/ml.png" $sw -D +WT"$THREADS"
  # shellcheck disable=SC2086
  measure "$tmp/pov" "Parse Time" "Bounding Time" "Trace Time" povray +I"$scene" +L"$(dirname "$scene")" +O"$tmp/pov.png" $sw -D -V +WT"$THREADS"
  tm=$(col 4 "$tmp/ml"); tp=$(col 4 "$tmp/pov")
  ratio=$(awk -v a="$tm" -v b="$tp" 'BEGIN {printf "%.2f", a/b}')
  printf '| %s | %s | povml | %.3f | %.3f | %.3f | %.3f | %.0f | **%s** |\n' "$(basename "$scene")" "$sw" \
    "$(col 1 "$tmp/ml")" "$(col 2 "$tmp/ml")" "$(col 3 "$tmp/ml")" "$tm" "$(awk '{print $5/1024}' "$tmp/ml" | median)" "$ratio"
  printf '| | | POV-Ray | %.3f | %.3f | %.3f | %.3f | %.0f | |\n' \
    "$(col 1 "$tmp/pov")" "$(col 2 "$tmp/pov")" "$(col 3 "$tmp/pov")" "$tp" "$(awk '{print $5/1024}' "$tmp/pov" | median)"
  case $scene in *spheres_*) echo "$(basename "$scene" .pov | sed 's/spheres_//') $(col 3 "$tmp/ml") $(col 3 "$tmp/pov")" >> "$tmp/series" ;; esac
done
echo
echo "median of $RUNS runs each, $THREADS threads, $(nproc) cores; ratio = povml / POV-Ray total wall time (below 1.00: povml is faster)."
echo "povml's parse time includes building each mesh's hierarchy; its build time is the compile step (the scene's hierarchy)."
[ -f "$tmp/series" ] || exit 0
echo
echo "Render time against the number of spheres (640x480, fixed image):"
echo
printf '| spheres | povml render s | POV-Ray trace s |\n|---:|---:|---:|\n'
while read -r n a b; do printf '| %s | %.3f | %.3f |\n' "$n" "$a" "$b"; done < "$tmp/series"

#!/bin/sh
# Renders every scene here with POV-Ray and with povml (test/tools/placed.exe) and compares them.
# Run from the repository root after `dune build`.
W=${W:-160}; H=${H:-120}
out=${OUT:-/tmp/povml-transforms}; mkdir -p "$out"
for f in test/transforms/*.pov; do
  n=$(basename "$f" .pov)
  povray +W$W +H$H -D -A +WT1 +I"$f" +O"$out/$n.pov.png" >/dev/null 2>"$out/$n.log" || { echo "$n: povray failed"; continue; }
  ./_build/default/test/tools/placed.exe "$f" "$out/$n.ml.png" $W $H || { echo "$n: povml failed"; continue; }
  printf "%-12s " "$n"; ./_build/default/test/tools/imgdiff.exe "$out/$n.pov.png" "$out/$n.ml.png" 2>/dev/null; ./_build/default/test/tools/imgdiff.exe "$out/$n.pov.png" "$out/$n.ml.png" -v 2>/dev/null | head -5
done

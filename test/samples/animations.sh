#!/usr/bin/env bash
# make animations: POV-Ray's sample animations rendered from their own .ini files with povml and
# with POV-Ray, each in a private copy of its directory, at a size given on the command line
# (SIZE, default "+W80 +H60": the frames are many), and compared frame for frame: the frame
# count, the file names and the pixels. Writes docs/animations.md.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
povml=$root/_build/default/bin/main.exe
imgdiff=$root/_build/default/test/tools/imgdiff.exe
scenes=${SAMPLES_DIR:-/usr/share/povray-3.7/scenes}
size=${SIZE:-+W80 +H60}
include_dir=${INCLUDE_DIR:-/usr/share/povray-3.7/include}
work=$(mktemp -d /tmp/povml-animations.XXXXXX)
trap 'rm -rf "$work"' EXIT
: > "$work/empty.ini"
out=$root/docs/animations.md
rows=$work/rows
: > "$rows"
total=0; same=0
for ini in "$scenes"/animations/*/*.ini; do
  dir=$(dirname "$ini"); name=$(basename "$ini")
  rm -rf "$work/p" "$work/m"; cp -r "$dir" "$work/p"; cp -r "$dir" "$work/m"; chmod -R u+w "$work/p" "$work/m"
  # shellcheck disable=SC2086
  t0=$(date +%s.%N)
  (cd "$work/p" && POVINI=$work/empty.ini timeout 600 povray "$name" -D $size +L"$include_dir" > ../p.log 2>&1)
  t1=$(date +%s.%N)
  # shellcheck disable=SC2086
  (cd "$work/m" && POVINI=$work/empty.ini timeout 600 "$povml" "$name" -D $size --allow-write . > ../m.log 2>&1)
  t2=$(date +%s.%N)
  pf=$(cd "$work/p" && ls ./*.png 2>/dev/null | sort | tr '\n' ' '); mf=$(cd "$work/m" && ls ./*.png 2>/dev/null | sort | tr '\n' ' ')
  np=$(echo "$pf" | wc -w); nm=$(echo "$mf" | wc -w)
  differ=0
  for f in $pf; do
    [ -f "$work/m/$f" ] || continue
    r=$("$imgdiff" "$work/p/$f" "$work/m/$f" 2>/dev/null || true)
    case $r in "differing 0/"*) ;; *) differ=$((differ + 1)) ;; esac
  done
  err=$(grep -m1 -E 'error' "$work/m.log" | sed 's/^[^ ]*: error: //' || true)
  total=$((total + 1))
  if [ "$np" -gt 0 ] && [ "$pf" = "$mf" ] && [ "$differ" = 0 ]; then verdict="identical"; same=$((same + 1))
  elif [ "$np" = 0 ] && [ "$nm" = 0 ]; then verdict="neither renders"
  elif [ "$nm" = 0 ]; then verdict="povml stops"
  else verdict="differs"; fi
  printf '| %s | %d | %d | %s | %d | %.1f | %.1f | %s | %s |\n' "${dir#$scenes/}/$name" "$np" "$nm" \
    "$([ "$pf" = "$mf" ] && echo same || echo differ)" "$differ" "$(echo "$t2 - $t1" | bc)" "$(echo "$t1 - $t0" | bc)" \
    "$verdict" "${err:+\`$err\`}" >> "$rows"
done
{
  echo "# POV-Ray's sample animations in povml"
  echo
  echo "Each of the sample set's animations (the .ini files under animations/ of Debian's povray-examples)"
  echo "rendered from its own .ini file by POV-Ray and by povml, each in a private copy of its directory,"
  echo "with \`-D $size\` added, and compared frame for frame (test/tools/imgdiff: no tolerance). Made by"
  echo "\`make animations\` (test/samples/animations.sh) on $(date -u +%Y-%m-%d) from povml commit $(cd "$root" && git rev-parse --short HEAD 2>/dev/null || echo unknown)."
  echo
  echo "**$same of $total render with frames identical to POV-Ray's, the same count under the same names.**"
  echo
  echo "| ini | POV-Ray frames | povml frames | names | differing frames | povml s | POV-Ray s | result | povml's error |"
  echo "|---|---:|---:|---|---:|---:|---:|---|---|"
  cat "$rows"
} > "$out"
echo "animations: $same of $total identical; wrote $out"

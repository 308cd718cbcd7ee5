#!/usr/bin/env bash
# Re-render the POV-Ray reference images listed in reference/manifest.tsv.
#
# Usage: reference/regen.sh [NAME ...]
#   With no arguments every manifest entry is rendered; otherwise only the named entries.
#
# Each entry is rendered with the real POV-Ray 3.7 as
#   POVINI=reference/povray.ini povray +I<scene> +O<tmp>/<name>.png -D -V +FN +WT2 <options>
#   (the image tests run povml with the same ini file)
#   (an entry may ask for one thread, +WT1, where POV-Ray is deterministic only so: crand)
# into a private directory under /tmp (Debian's povray.conf only lets POV-Ray write under /tmp
# and the current directory), then copied to reference/<name>.png.
# One line is printed per image; POV-Ray parse errors/warnings found in its output are shown
# on that line. The full POV-Ray log of a failed render is printed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$here")
manifest="$here/manifest.tsv"

if ! command -v povray >/dev/null 2>&1; then
  echo "regen.sh: error: 'povray' was not found in PATH." >&2
  echo "regen.sh: the reference images must be made with POV-Ray 3.7 (Debian/Ubuntu: apt-get install povray)." >&2
  exit 1
fi
version=$(povray --version 2>&1 | head -n 1 || true)
case "$version" in
  *3.7.*) ;;
  *) echo "regen.sh: warning: expected POV-Ray 3.7, got: $version" >&2 ;;
esac
[ -f "$manifest" ] || { echo "regen.sh: error: manifest not found: $manifest" >&2; exit 1; }

tmp=$(mktemp -d /tmp/povml-regen.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

want=("$@")
selected() {
  [ ${#want[@]} -eq 0 ] && return 0
  local w
  for w in "${want[@]}"; do [ "$w" = "$1" ] && return 0; done
  return 1
}

count=0; failed=0; lineno=0
while IFS=$'\t' read -r name scene options max_differing max_peak reason || [ -n "${name:-}" ]; do
  lineno=$((lineno + 1))
  [ "$lineno" -eq 1 ] && continue                       # header
  case "$name" in ''|'#'*) continue ;; esac
  selected "$name" || continue
  case "$scene" in /*) src="$scene" ;; *) src="$root/$scene" ;; esac   # POV-Ray's own samples: absolute
  if [ ! -f "$src" ]; then
    echo "FAIL  $name: scene not found: $scene"; failed=$((failed + 1)); continue
  fi
  out="$tmp/$name.png"; log="$tmp/$name.log"
  # shellcheck disable=SC2086  # options are deliberately word-split
  if (cd "$tmp" && POVINI="$here/povray.ini" povray +I"$src" +L"$(dirname "$src")" +O"$out" -D -V +FN +WT2 $options) >"$log" 2>&1 \
      && [ -s "$out" ]; then
    cp "$out" "$here/$name.png"
    # POV-Ray's messages: "Parse Error", "Possible Parse Error", "Parse Warning", "Warning: ...".
    # POV-Ray wraps its messages at 80 columns (continuation lines start with a space): unwrap,
    # then keep each message's kind and its first words, once each.
    notes=$(awk '
        /^ / && NR > 1 { cur = cur $0; next }
        { if (NR > 1) print cur; cur = $0 }
        END { print cur }' "$log" | awk '
        match($0, /(Possible Parse Error|Parse Error|Parse Warning|Warning):/) {
          kind = substr($0, RSTART, RLENGTH - 1); text = substr($0, RSTART + RLENGTH)
          gsub(/^ +| +$/, "", text); gsub(/  +/, " ", text)
          msg = kind ": " substr(text, 1, 70)
          if (!(msg in seen)) { seen[msg] = 1; out = out (out ? "; " : "") msg }
        }
        END { print out }' || true)
    printf 'ok    %-38s %-22s %s%s\n' "$name" "$options" "$scene" "${notes:+   [POV-Ray: $notes]}"
    count=$((count + 1))
  else
    echo "FAIL  $name ($scene $options):"
    sed 's/^/      /' "$log" | tail -n 40
    failed=$((failed + 1))
  fi
done < "$manifest"

echo "regen.sh: $count image(s) written to reference/, $failed failure(s)."
[ "$failed" -eq 0 ]

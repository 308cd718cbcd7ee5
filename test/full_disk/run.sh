#!/bin/bash
# A real full disk: a 256 KiB tmpfs mounted for the test and filled up. Each write povml makes
# there must fail with "No space left on device", exit status 5 (1 for a scene's own #write, a
# located scene error), the old file kept byte for byte and no temporary file left behind.
# Mounting needs root: where it is not possible the test says it is skipped and passes.
# test/cram/writes.t covers the same with /dev/full and a file size limit, everywhere.
set -u
povml=$(realpath "$1")
work=$(mktemp -d)
disk=$work/disk
cleanup() { umount "$disk" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
mkdir "$disk"
if ! why=$(mount -t tmpfs -o size=256k tmpfs "$disk" 2>&1); then
  why=${why%%$'\n'*}
  why=${why%.}
  echo "test/full_disk: skipped: cannot mount a tmpfs here (${why:-mount failed}; it needs root)"
  exit 0
fi
cd "$work" || exit 1
export POVINI=/dev/null
failures=0
fail() { echo "test/full_disk: FAIL: $*"; failures=$((failures + 1)); }

cat > s.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -3> look_at 0 }
light_source { <3, 5, -5>, rgb 1 }
sphere { 0, 1 pigment { granite scale 0.05 } }
POV

# [expect WHAT STATUS LINE CMD…] runs CMD, whose status must be STATUS and whose stderr must have
# LINE among its lines
cases=0
expect() {
  cases=$((cases + 1))
  local what=$1 status=$2 line=$3
  shift 3
  "$@" 2> err > /dev/null
  local got=$?
  [ "$got" = "$status" ] || fail "$what: exit status $got, not $status"
  grep -qxF -- "$line" err || { fail "$what: no line '$line' in:"; sed 's/^/    /' err; }
}
# [kept NAME] checks that the disk's file NAME is as it was before, and that no temporary file is
# left
kept() {
  cmp -s "$disk/$1" "$1.before" || fail "$1 was changed"
  if ls -A "$disk" | grep -q -e '\.part' -e '^\.povml'; then fail "a temporary file was left: $(ls -A "$disk")"; fi
}

# old images, then the disk filled up; the render processes' files go elsewhere (TMPDIR)
"$povml" s.pov +W64 +H48 -D +O"$disk/old.png" 2>/dev/null || fail "the first image was not written"
"$povml" s.pov +W64 +H48 -D +FP +O"$disk/old.ppm" 2>/dev/null || fail "the first PPM was not written"
"$povml" s.pov +W64 +H48 -D +O"$disk/frame1.png" 2>/dev/null || fail "the first frame was not written"
for f in old.png old.ppm frame1.png; do cp "$disk/$f" "$f.before"; done
dd if=/dev/zero of="$disk/fill" bs=4k 2>/dev/null
[ "$(df --output=avail "$disk" | tail -1)" -eq 0 ] || fail "the disk is not full: $(df "$disk")"

expect "PNG" 5 "$disk/old.png: error: cannot write the image: No space left on device; the old file is kept" \
  "$povml" s.pov +W160 +H120 -D +O"$disk/old.png"
kept "old.png"
expect "PPM (+FP)" 5 "$disk/old.ppm: error: cannot write the image: No space left on device; the old file is kept" \
  "$povml" s.pov +W160 +H120 -D +FP +O"$disk/old.ppm"
kept "old.ppm"
expect "a new file" 5 "$disk/new.png: error: cannot write the image: No space left on device; nothing was written" \
  "$povml" s.pov +W160 +H120 -D +O"$disk/new.png"
[ -e "$disk/new.png" ] && fail "new.png was left"
expect "an animation" 5 "$disk/frame1.png: error: cannot write the image: No space left on device; the old file is kept" \
  "$povml" s.pov +W160 +H120 -D +KFI1 +KFF2 +O"$disk/frame.png"
kept "frame1.png"
[ -e "$disk/frame2.png" ] && fail "frame2.png was written"

expect "the render processes' results" 5 "povml: cannot write the render processes' results in $disk: No space left on device; no image was written" \
  env TMPDIR="$disk" "$povml" s.pov +W160 +H120 +WT2 -D +Oold.png
cmp -s old.png.before old.png 2>/dev/null || [ ! -e old.png ] || fail "old.png was written"

"$povml" s.pov +W160 +H120 -D +ER64 +Otop.png 2>/dev/null && "$povml" s.pov +W160 +H120 -D +SR65 +Obottom.png 2>/dev/null \
  || fail "the parts to merge were not written"
expect "povml merge" 5 "povml merge: error: cannot write $disk/old.png: No space left on device; the old file is kept" \
  "$povml" merge "$disk/old.png" top.png bottom.png
kept "old.png"

printf '#version 3.7;\n#fopen F "%s/out.txt" write\n#for (I, 1, 100000)\n  #write (F, "a line\\n")\n#end\n' "$disk" > w.pov
expect "#write" 1 "w.pov:4:3: error: cannot write \"$disk/out.txt\": No space left on device" \
  "$povml" w.pov --allow-write "$disk" -D -F

if [ "$failures" -eq 0 ]; then echo "test/full_disk: $cases cases passed on a full tmpfs"; else exit 1; fi

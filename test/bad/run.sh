#!/bin/sh
# run.sh SCENE [SWITCH…]: render SCENE with povml as a user would, within 10 seconds and 1 GiB of
# address space; print what povml says (without the render statistics), its exit status and
# whether an image was written.
scene=$1
shift
image=${scene%.pov}.png
rm -f "$image"
(ulimit -v 1048576 && exec timeout 10 povml "$scene" +W16 +H12 -D "$@") 2>messages.txt >/dev/null
status=$?
# the statistics begin with a line of dashes; "Wrote …" ends them
sed '/^------/,$d' messages.txt
rm -f messages.txt
if [ -f "$image" ]; then echo "[exit $status, image written]"; else echo "[exit $status, no image]"; fi

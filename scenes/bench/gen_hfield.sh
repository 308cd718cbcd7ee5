#!/usr/bin/env bash
# gen_hfield.sh OUT.png: the 1024×1024 16-bit grey height map of scenes/bench/hfield.pov, a sum of
# smooth waves (ImageMagick's -fx; a few seconds). Run from anywhere.
set -euo pipefail
out=${1:-$(dirname "$0")/generated/hfield_1024.png}
mkdir -p "$(dirname "$out")"
convert -size 1024x1024 xc: -fx \
  "0.45 + 0.2*sin(i/61)*cos(j/47) + 0.12*sin((i+2*j)/23) + 0.08*cos((3*i-j)/11) + 0.04*sin(i*j/9000)" \
  -colorspace Gray -depth 16 "$out"

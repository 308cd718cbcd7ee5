#!/usr/bin/env bash
# make test-slurm: the README's Slurm recipe on a one-node Slurm started here (start.sh): an
# animation's frames as a job array and a still's four 32-row bands as another, merged with
# povml merge; each compared with the one-process render. Exit status 1 on any difference.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$(dirname "$here")")
povml=$root/_build/default/bin/main.exe
imgdiff=$root/_build/default/test/tools/imgdiff.exe
[ "$(id -u)" = 0 ] || { echo "test-slurm: the one-node Slurm runs its daemons as root; run as root" >&2; exit 1; }
SLURM_CONF=$(bash "$here/start.sh")
export SLURM_CONF
trap 'bash "$here/stop.sh"' EXIT
work=$(mktemp -d /tmp/povml-slurm-test.XXXXXX)
cd "$work"
cp "$here/a.pov" a.pov
mkdir one split
"$povml" a.pov +W64 +H48 +A0.3 -D +KFF6 +KI-1 +KF1 +Oone/ 2>/dev/null
start=$(date +%s.%N)
sbatch --wait --array=1-6 -o /dev/null --wrap \
  "$povml a.pov +W64 +H48 +A0.3 -D +KFF6 +KI-1 +KF1 +SF\$SLURM_ARRAY_TASK_ID +EF\$SLURM_ARRAY_TASK_ID +Osplit/" >/dev/null
frames_s=$(echo "$(date +%s.%N) - $start" | bc)
bad=0
for f in one/*.png; do
  n=$(basename "$f")
  r=$("$imgdiff" "$f" "split/$n" 2>/dev/null || true)
  case $r in "differing 0/"*) ;; *) echo "frame $n: $r"; bad=1 ;; esac
done
echo "frames: $(ls split | wc -l) of $(ls one | wc -l) rendered as a Slurm job array in $frames_s s, each identical: $([ $bad = 0 ] && echo yes || echo NO)"
"$povml" a.pov +W48 +H128 +A0.3 -D +K0.4 +Ofull.png 2>/dev/null
start=$(date +%s.%N)
sbatch --wait --array=0-3 -o /dev/null --wrap \
  "$povml a.pov +W48 +H128 +A0.3 -D +K0.4 +SR\$((SLURM_ARRAY_TASK_ID * 32 + 1)) +ER\$((SLURM_ARRAY_TASK_ID * 32 + 32)) +Oband\$SLURM_ARRAY_TASK_ID.png" >/dev/null
bands_s=$(echo "$(date +%s.%N) - $start" | bc)
"$povml" merge merged.png band0.png band1.png band2.png band3.png
r=$("$imgdiff" full.png merged.png 2>/dev/null || true)
echo "still: 4 bands as a Slurm job array in $bands_s s, merged: $r"
case $r in "differing 0/"*) ;; *) bad=1 ;; esac
cd /
rm -rf "$work"
exit $bad

#!/usr/bin/env bash
# make test-ssh: the README's GNU parallel recipe across machines (--sshlogin) with a second
# machine made on this one: an sshd on 127.0.0.1 only, with keys and configuration of its own,
# for an account of its own (povml-node: its own home, povml in ~/bin), beside this machine (':').
# The scene goes out with --basefile and the images come back with --return, as they would
# between machines that share no directory; an animation's frames and a still's four 32-row
# bands, merged, are compared with the one-process render. Exit status 1 on any difference, or
# when the second machine ran no job. Run as root (it adds the account and starts the sshd);
# needs Debian's openssh-server and rsync.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(dirname "$(dirname "$here")")
povml=$root/_build/default/bin/main.exe
imgdiff=$root/_build/default/test/tools/imgdiff.exe
port=${SSH_TEST_PORT:-22222}
user=povml-node
[ "$(id -u)" = 0 ] || { echo "test-ssh: it adds an account and starts an sshd; run as root" >&2; exit 1; }
work=$(mktemp -d /tmp/povml-ssh-test.XXXXXX)
trap '[ -f "$work/sshd.pid" ] && kill "$(cat "$work/sshd.pid")" 2>/dev/null; rm -rf "$work"' EXIT

# the second machine: an account that logs in by key only, with povml on its PATH
id "$user" >/dev/null 2>&1 || useradd -m -s /bin/bash "$user"
usermod -p '*' "$user"
home=$(getent passwd "$user" | cut -d: -f6)
ssh-keygen -q -t ed25519 -N '' -f "$work/host_key"
ssh-keygen -q -t ed25519 -N '' -f "$work/client_key"
install -d -o "$user" -m 700 "$home/.ssh"
install -d -o "$user" -m 755 "$home/bin"
install -o "$user" -m 600 "$work/client_key.pub" "$home/.ssh/authorized_keys"
install -o "$user" -m 755 "$povml" "$home/bin/povml"
echo "PATH=$home/bin:/usr/local/bin:/usr/bin:/bin" > "$home/.ssh/environment"
chown "$user" "$home/.ssh/environment"
cat > "$work/sshd_config" <<CONF
Port $port
ListenAddress 127.0.0.1
HostKey $work/host_key
PidFile $work/sshd.pid
AuthorizedKeysFile .ssh/authorized_keys
PasswordAuthentication no
KbdInteractiveAuthentication no
UsePAM no
PermitUserEnvironment yes
CONF
mkdir -p /run/sshd
/usr/sbin/sshd -f "$work/sshd_config"
cat > "$work/ssh_config" <<CONF
Host node1
  HostName 127.0.0.1
  Port $port
  User $user
  IdentityFile $work/client_key
  IdentitiesOnly yes
  BatchMode yes
  StrictHostKeyChecking no
  UserKnownHostsFile $work/known_hosts
CONF
ssh="ssh -F $work/ssh_config"
for _ in 1 2 3 4 5 6 7 8 9 10; do $ssh node1 true 2>/dev/null && break; sleep 0.5; done
[ "$($ssh node1 'command -v povml')" = "$home/bin/povml" ] || { echo "test-ssh: povml is not on node1's PATH" >&2; exit 1; }

# this machine: povml on the PATH too, the work in a directory node1 does not see
mkdir "$work/bin" "$work/job"
ln -s "$povml" "$work/bin/povml"
export PATH=$work/bin:$PATH
cd "$work/job"
cp "$root/test/slurm/a.pov" a.pov
mkdir one
povml a.pov +W64 +H48 +A0.3 -D +KFF6 +KI-1 +KF1 +Oone/ 2>/dev/null
bad=0
start=$(date +%s.%N)
parallel --ssh "$ssh" -S 1/node1,1/: --joblog frames.log --basefile a.pov --return 'a{}.png' --cleanup \
  povml a.pov +W64 +H48 +A0.3 -D +KFF6 +KI-1 +KF1 +SF{} +EF{} ::: 1 2 3 4 5 6 2>/dev/null
frames_s=$(echo "$(date +%s.%N) - $start" | bc)
for f in one/*.png; do
  n=$(basename "$f")
  r=$("$imgdiff" "$f" "$n" 2>/dev/null || true)
  case $r in "differing 0/"*) ;; *) echo "frame $n: $r"; bad=1 ;; esac
done
remote=$(awk -F'\t' 'NR > 1 && $2 == "node1"' frames.log | wc -l)
echo "frames: $(ls a?.png | wc -l) of 6 rendered under GNU parallel on node1 and here ($remote on node1) in $frames_s s, each identical: $([ $bad = 0 ] && echo yes || echo NO)"
[ "$remote" -gt 0 ] || { echo "node1 ran no frame"; bad=1; }
povml a.pov +W48 +H128 +A0.3 -D +K0.4 +Ofull.png 2>/dev/null
start=$(date +%s.%N)
parallel --ssh "$ssh" -S 1/node1,1/: --joblog bands.log --basefile a.pov --return 'band{1}.png' --cleanup --colsep ' ' \
  povml a.pov +W48 +H128 +A0.3 -D +K0.4 +SR{1} +ER{2} +Oband{1}.png ::: '1 32' '33 64' '65 96' '97 128' 2>/dev/null
bands_s=$(echo "$(date +%s.%N) - $start" | bc)
povml merge merged.png band1.png band33.png band65.png band97.png
r=$("$imgdiff" full.png merged.png 2>/dev/null || true)
remote=$(awk -F'\t' 'NR > 1 && $2 == "node1"' bands.log | wc -l)
echo "still: 4 bands under GNU parallel on node1 and here ($remote on node1) in $bands_s s, merged: $r"
case $r in "differing 0/"*) ;; *) bad=1 ;; esac
[ "$remote" -gt 0 ] || { echo "node1 ran no band"; bad=1; }
# nothing left behind on node1 (--cleanup)
left=$($ssh node1 'ls *.pov *.png 2>/dev/null | wc -l')
[ "$left" = 0 ] || { echo "node1 kept $left files"; bad=1; }
cd /
exit $bad

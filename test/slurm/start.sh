#!/usr/bin/env bash
# Start a one-node Slurm on this machine, loopback only, for make test-slurm: munged with the
# key the munge package made, then slurmctld and slurmd from a private configuration under DIR
# (default /tmp/povml-slurm). Prints the SLURM_CONF to export. Run as root (the daemons run as root).
set -euo pipefail
dir=${1:-/tmp/povml-slurm}
mkdir -p "$dir/state" "$dir/spool" "$dir/log"
host=$(hostname -s)
cpus=$(nproc)
mem=$(awk '/MemTotal/ { print int($2 / 1024 / 2) }' /proc/meminfo)
cat > "$dir/slurm.conf" <<CONF
ClusterName=povml
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldPort=6817
SlurmdPort=6818
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
# munge: the package's key; its socket directory
mkdir -p /run/munge
if ! pgrep -x munged >/dev/null; then
  /usr/sbin/munged --force 2>/dev/null
fi
pkill -x slurmctld 2>/dev/null || true
pkill -x slurmd 2>/dev/null || true
sleep 1
/usr/sbin/slurmctld -f "$SLURM_CONF"
# slurmd complains about the PMIx library it cannot load (no MPI here) and carries on
/usr/sbin/slurmd -f "$SLURM_CONF" 2>/dev/null
for _ in $(seq 30); do
  if sinfo -h -o %T 2>/dev/null | grep -q -E '^(idle|mixed|allocated)'; then echo "$SLURM_CONF"; exit 0; fi
  sleep 1
done
echo "start.sh: the node did not become idle; see $dir/log" >&2
sinfo >&2 || true
exit 1

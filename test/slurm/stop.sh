#!/usr/bin/env bash
# Stop the one-node Slurm that start.sh started (munged stays: other tools may use it).
pkill -x slurmd 2>/dev/null || true
pkill -x slurmctld 2>/dev/null || true
exit 0

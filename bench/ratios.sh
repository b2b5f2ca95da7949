#!/bin/sh
# The benchmark bar: floors, cagd and the peers on one thread and on all threads, and the
# B-spline/NURBS batches against the Bézier batch, all in one run (bench/benches/ratios.rs);
# prints the tables with the threads, the load average before and after and this command,
# and exits non-zero when a target is missed. Figures taken with a load average above about
# 0.5 are not worth much: other work takes the cores and the memory bandwidth.
#
# Usage (from anywhere): bash bench/ratios.sh [--quick]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cargo bench --quiet -p cagd-bench --bench ratios --no-run 2>/dev/null
echo "# command: bash bench/ratios.sh $*"
echo "# machine: $(nproc) cores, $(lscpu | grep 'Model name' | sed 's/.*: *//'), $(uname -sr)"
echo "# date: $(date -u '+%Y-%m-%d %H:%M UTC'); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
status=0
cargo bench --quiet -p cagd-bench --bench ratios -- "$@" || status=$?
echo
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
exit "$status"

#!/usr/bin/env bash
# Speed of the Octave package cagd in one Octave session (bench_cagd.m): builds the tarball,
# installs it into a temporary prefix (as octave_pkg/ci.sh does), then times the thesis
# functions against the fixed Octave code and cagd_nrbeval against octave-nurbs' nrbeval.
#
# Usage: bash octave_pkg/bench/run.sh              (about 3 minutes: the fixed deCasteljau at
#                                                   1e6 points alone takes 1-2 minutes)
#        CAGD_BENCH_FIXED_N=100000 bash octave_pkg/bench/run.sh   (the fixed deCasteljau at 1e5
#                                                   points, its time scaled to 1e6)
#        RAYON_NUM_THREADS=1 bash octave_pkg/bench/run.sh         (the package on one thread)
#        bash octave_pkg/bench/run.sh twins   (bench_twins.m instead: the octave-nurbs twins
#                                              against octave-nurbs, the package on one thread)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
export CARGO_TARGET_DIR="${CAGD_OCTAVE_PKG_TARGET:-$root/target/octave-pkg/cargo}"
tarball="$(bash "$root/octave_pkg/build.sh" "$tmp/dist" | tail -n 1)"
bench="bench_cagd ('$root/octave_ref');"
if [ "${1:-}" = twins ]; then
    export RAYON_NUM_THREADS=1
    bench="bench_twins ();"
fi
setup="pkg prefix '$tmp/packages' '$tmp/packages'; pkg local_list '$tmp/octave_packages';"
octave --no-gui --no-window-system --quiet --norc \
    --eval "$setup pkg install -local '$tarball'; addpath ('$here'); $bench" 2>&1 \
    | grep -v 'ignoring const execution_exception& while preparing to exit\|doc_cache_create\|^warning: called from\|^    ' || true

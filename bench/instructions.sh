#!/bin/sh
# Instructions per point of cagd's batch kernels on one thread, counted by callgrind (they do
# not depend on the machine's load): for each case, two runs of the `kernels` binary with 1 and
# 3 calls; the difference divided by 2 calls and by the points of one call (10⁶: a 1000 × 1000
# grid or 10⁶ curve points).
#
# Usage (from anywhere): bench/instructions.sh [CASE...]   (default: all cases)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cargo build --release --quiet -p cagd-bench --bin kernels
bin="$root/target/release/kernels"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cases=${*:-$("$bin" list | sed 's/^cases: //')}
count() {
  RAYON_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file="$tmp/out" "$bin" "$1" "$2" \
    2>&1 | sed -n 's/.*Collected : *//p'
}
printf '| %-16s | %14s |\n' case "instr / point"
printf '|%s|%s|\n' ------------------ ----------------
for c in $cases; do
  one=$(count "$c" 1)
  three=$(count "$c" 3)
  printf '| %-16s | %14.2f |\n' "$c" "$(echo "($three - $one) / 2 / 1000000" | bc -l)"
done

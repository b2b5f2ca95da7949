#!/bin/sh
# Exact arithmetic at a student's scale, through the `cagd` binary (release build): a
# degree-20 Bernstein basis and Bézier curve, a 21 × 21 Coons grid (the thesis's Primer 4.3), a
# Gordon surface of a 5 × 5 curve network on a 21 × 21 grid, an interpolating spline through
# 20 points, each with `--exact`. Prints each command's best wall-clock and CPU time over
# RUNS runs (default 10), in milliseconds; the target is 50 ms. CPU time (perf's task-clock,
# or user + system from GNU time) is less disturbed by other work on the machine than
# wall-clock time; the load average is printed before and after.
#
# Usage (from anywhere): bench/exact_students.sh [RUNS]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
runs=${1:-10}
cargo build --release --quiet -p cagd-cli
bin="$root/target/release/cagd"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A degree-20 curve: 21 control points (i, 7i mod 11, 3i mod 5).
ctrl=$(awk 'BEGIN { for (r = 0; r < 3; r++) { for (i = 0; i <= 20; i++) printf "%d ", (r == 0 ? i : (r == 1 ? (7 * i) % 11 : (3 * i) % 5)); printf (r < 2 ? "; " : "") } }')
# 20 points of a spiral-like polyline (i, (5i mod 9) - 4).
spline=$(awk 'BEGIN { for (r = 0; r < 2; r++) { for (i = 0; i < 20; i++) printf "%d ", (r == 0 ? i : (5 * i) % 9 - 4); printf (r < 1 ? "; " : "") } }')
# The 5 × 5 network of x(u, v) = (u, v, uv + u² − v²) at 0, 1/4, 1/2, 3/4, 1.
gordon=""
for a in 0 0.25 0.5 0.75 1; do
  gordon="$gordon --v-curve [u;$a;$a*u+u^2-$a^2] --u-curve [$a;v;$a*v+$a^2-v^2]"
done

echo "# command: bash bench/exact_students.sh $runs"
echo "# machine: $(nproc) cores, $(lscpu | grep 'Model name' | sed 's/.*: *//'); load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| case | command | wall (ms) | CPU (ms) |"
echo "|---|---|---|---|"
# CPU time from perf's task-clock (microseconds) where perf runs, else from GNU time (10 ms).
if perf stat -x, -e task-clock true > /dev/null 2>&1; then
  cpu_of() { perf stat -x, -e task-clock -o "$tmp/p" "$@" > /dev/null && awk -F, '/task-clock/ { printf "%.1f", $1 }' "$tmp/p"; }
else
  cpu_of() { /usr/bin/time -f '%U %S' -o "$tmp/p" "$@" > /dev/null && awk '{ printf "%.1f", ($1 + $2) * 1000 }' "$tmp/p"; }
fi
measure() {
  name=$1
  shift
  best_wall=""
  best_cpu=""
  i=0
  while [ "$i" -lt "$runs" ]; do
    cpu=$(cpu_of "$bin" "$@")
    start=$(date +%s%N)
    "$bin" "$@" > /dev/null
    wall=$(( ($(date +%s%N) - start) / 100000 ))
    wall=$(awk -v w="$wall" 'BEGIN { printf "%.1f", w / 10 }')
    best_wall=$(awk -v a="$best_wall" -v b="$wall" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }')
    best_cpu=$(awk -v a="$best_cpu" -v b="$cpu" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }')
    i=$((i + 1))
  done
  shown=$(echo "cagd $*" | cut -c1-90)
  echo "| $name | \`$shown\` | $best_wall | $best_cpu |"
}
measure "Bernstein basis, degree 20, 101 samples" bernstein --degree 20 --n 101 --exact
measure "Bézier curve, degree 20, 101 samples" decasteljau "[$ctrl]" --n 101 --exact
measure "Coons patch (Primer 4.3), 21 × 21 grid" coons --c1 "[u;0;u-u^2]" --c2 "[u;1;u]" --d1 "[0;v^2;v-v^2]" --d2 "[1;v;v]" --n 21 --exact
# shellcheck disable=SC2086
measure "Gordon surface, 5 × 5 network, 21 × 21 grid" gordon $gordon --n 21 --exact
measure "interpolating spline through 20 points" spline "[$spline]" --exact
echo
echo "# load average after: $(cut -d' ' -f1-3 /proc/loadavg)"

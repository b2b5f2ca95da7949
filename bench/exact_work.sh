#!/usr/bin/env bash
# Compares the up-front work estimates of `--exact` commands (what --max-work limits) with
# their run time in a release build: the figures behind `cagd::limits::exact_op_cost`.
# Usage: bash bench/exact_work.sh   (from the repository root; needs python3)
# Every estimate of a command (expressions first, then the construction) is found by
# raising --max-work to each refused estimate in turn; the largest is printed.
set -euo pipefail
cargo build --release --quiet
B=target/release/cagd
digits() { python3 -c "import random; random.seed(1); print('[' + ' '.join(str(random.randint(0, 9)) for _ in range($1)) + ']')"; }
P60=$(digits 60)
W60=$(python3 -c "print('[' + ' '.join(str(1 + i % 3) for i in range(60)) + ']')")
R300=$(digits 300)
R1000=$(digits 1000)
net() { python3 -c "
import random; random.seed(2)
rows = [' '.join('%d %d %d' % (i, j, random.randint(0, 9)) for j in range($1)) for i in range($1)]
print('[' + '; '.join(rows) + ']')"; }
N40=$(net 40)
N80=$(net 80)
estimate() {
  local mw=1 best=0 r
  while true; do
    r=$({ "$B" "$@" --max-work "$mw" 2>&1 >/dev/null || true; } | grep -o 'operations[^:]*: [0-9]*' | grep -o '[0-9]*$' || true)
    if [ -z "$r" ]; then
      echo "$best"; return
    fi
    [ "$r" -gt "$best" ] && best=$r
    mw=$r
  done
}
run() {
  local est t0 t1
  est=$(estimate "$@")
  t0=$(date +%s%N)
  "$B" "$@" --max-work 1000000000000000 >/dev/null
  t1=$(date +%s%N)
  python3 - "$est" "$t0" "$t1" "$*" <<'PY'
import sys
est, t0, t1, cmd = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
ns = t1 - t0
print(f"| {cmd[:72]:72} | {est:>15,} | {ns/1e9:8.3f} | {est/ns:6.1f} |")
PY
}
echo "| command | estimate | seconds | estimate / ns |"
echo "|---|---|---|---|"
run bernstein --degree 40 --exact
run bernstein --degree 95 --exact
run bernstein --degree 30 --exact --n 1000
run decasteljau "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'" --n 100000 --exact
run decasteljau "$P60" --n 301 --exact
run derivative "$P60" --t 0:0.005:1 --exact
run bezier-patch "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]" --n 100 --exact
run bezier-patch "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]" --n 300 --exact
run lagrange --nodes 0:0.05:1 --n 101 --exact
run lagrange --nodes 0:0.01:1 --n 1001 --exact
run hermite --p0 "[0;0]" --p1 "[1;0]" --t0 "[1;1]" --t1 "[1;-1]" --n 100000 --exact
run bspline "$P60" --degree 10 --n 10001 --exact
run nurbs "$P60" --weights "$W60" --degree 10 --n 1001 --exact
run nurbs "$P60" --weights "$W60" --degree 10 --n 10001 --exact
run spline '[ ; 0:2222]' --exact
run spline "$R300" --exact
run spline "$R1000" --exact
run spline "$R1000" --exact --end closed
run curve "[u^50; u^49]" --n 100000 --exact
run curve "[u^20; u^19]" --n 1000000 --exact
run curve "[u; u^2; u-u^2]" --n 1000000 --exact
run surface "[u; v; u.*v]" --n 1000 --exact
run coons --c1 "[u;0;u-u^2]" --c2 "[u;1;u]" --d1 "[0;v^2;v-v^2]" --d2 "[1;v;v]" --n 300 --exact
run coons --c1 "[0 0 0; 1 0 1]'" --c2 "[0 1 0; 1 1 1]'" --d1 "[0 0 0; 0 1 0]'" --d2 "[1 0 1; 1 1 1]'" --n 300 --exact
run coons-bicubic --c1 "[u;0;0]" --c2 "[u;1;0]" --d1 "[0;v;0]" --d2 "[1;v;0]" --c1v "[0;1;0]" --c2v "[0;1;0]" --d1u "[1;0;0]" --d2u "[1;0;0]" --n 200 --exact
run gordon --v-curve "[u;0;u-u^2]" --v-curve "[u;0.5;0.5+u-u^2]" --v-curve "[u;1;1+u-u^2]" --u-curve "[0;v;v]" --u-curve "[0.5;v;0.25+v]" --u-curve "[1;v;v]" --n 200 --exact
run discrete-coons "$N40" --mask=-0.25,0.5 --exact
run discrete-coons "$N80" --mask=-0.25,0.5 --exact

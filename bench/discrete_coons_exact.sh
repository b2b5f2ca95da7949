#!/usr/bin/env bash
# Exact discrete Coons nets by a mask: the command line's up-front estimate against the CPU time
# of the whole command in a release build, for nets of n × n ones (`ones(n, 3n)`, packed as
# ploskevB takes them) and n = 10 … 40. The Laplace mask (α = 0, β = 1/4) builds numbers of about
# 3 bits per unknown in its elimination; the Coons mask (α = −1/4, β = 1/2) keeps them small.
# The figures behind `cagd::coons::Mask::solve_cost` (table in docs/PERFORMANCE.md).
# Usage: bash bench/discrete_coons_exact.sh [N ...]   (from the repository root)
set -euo pipefail
cargo build --release --quiet -p cagd-cli
B=target/release/cagd
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(10 12 15 18 20 22 25 28 30 35 40)
echo "| mask | n | estimate | CPU seconds | estimate / ns |"
echo "|---|---|---|---|---|"
for mask in 0,0.25 -0.25,0.5; do
  for n in "${sizes[@]}"; do
    net="ones($n,$((3 * n)))"
    est=$({ "$B" discrete-coons "$net" --mask="$mask" --exact --max-work 1 2>&1 >/dev/null || true; } \
      | grep -o 'operations: [0-9]*' | grep -o '[0-9]*$')
    t=$({ /usr/bin/time -f "%U %S" "$B" discrete-coons "$net" --mask="$mask" --exact \
      --max-work 1000000000000000000 > /dev/null; } 2>&1 | tail -1)
    python3 - "$mask" "$n" "$est" "$t" <<'PY'
import sys
mask, n, est, t = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4].split()
s = float(t[0]) + float(t[1])
print(f"| {mask} | {n} | {est:,} | {s:.2f} | {est / max(s, 1e-3) / 1e9:.2f} |")
PY
  done
done

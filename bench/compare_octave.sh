#!/bin/sh
# Runs the same cases in GNU Octave (the fixed thesis functions and octave-nurbs nrbeval) and in
# cagd (cagd-bench's `timings` binary), one after the other in one run, and prints a table of
# the best times and the ratios Octave / cagd, then cagd's own figures and the accuracy study.
#
# Usage (from anywhere): bench/compare_octave.sh
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "# machine: $(nproc) cores, $(lscpu | grep 'Model name' | sed 's/.*: *//'), $(uname -sr)"
echo "# date: $(date -u '+%Y-%m-%d %H:%M UTC'); load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "# $(octave --version | head -1); octave-nurbs $(octave --no-gui --quiet --eval 'p = pkg("list", "nurbs"); disp(p{1}.version)' 2>/dev/null)"

cargo build --release --quiet -p cagd-bench --bin timings
octave --no-gui --quiet bench/octave/timings.m > "$tmp/octave.tsv"
"$root/target/release/timings" > "$tmp/cagd.tsv"
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo

awk -F'\t' '
  FNR == NR { if ($0 !~ /^#/) cagd[$1] = $2; next }
  {
    if (!header++) {
      printf "| %-26s | %-10s | %12s | %12s | %10s |\n", "case", "Octave", "Octave (s)", "cagd (s)", "ratio"
      printf "|%s|%s|%s|%s|%s|\n", "----------------------------", "------------", "--------------", "--------------", "------------"
    }
    c = cagd[$1]
    printf "| %-26s | %-10s | %12.4g | %12.4g | %9.0fx |\n", $1, $2, $3, c, (c > 0 ? $3 / c : 0)
  }
' "$tmp/cagd.tsv" "$tmp/octave.tsv"

echo
echo "cagd alone (seconds, best of several runs):"
awk -F'\t' '$0 !~ /^#/ { printf "  %-44s %.4g\n", $1, $2 } $0 ~ /^#/ { print }' "$tmp/cagd.tsv"

#!/bin/sh
# Runs the same cases in GNU Octave (the fixed thesis functions and octave-nurbs nrbeval) and in
# cagd (cagd-bench's `timings` binary), one after the other in one run, and prints a table of
# the best times and the ratios Octave / cagd, then cagd's own figures and the accuracy study.
# Threads are stated: Octave runs these functions on one thread; cagd runs once on one thread
# (RAYON_NUM_THREADS=1, the ratio that compares like with like) and once on all threads.
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
threads=$(nproc)
RAYON_NUM_THREADS=1 "$root/target/release/timings" --no-accuracy > "$tmp/cagd1.tsv"
RAYON_NUM_THREADS=$threads "$root/target/release/timings" > "$tmp/cagd.tsv"
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo

awk -F'\t' -v n="$threads" '
  FILENAME == ARGV[1] { if ($0 !~ /^#/) one[$1] = $2; next }
  FILENAME == ARGV[2] { if ($0 !~ /^#/) all[$1] = $2; next }
  {
    if (!header++) {
      printf "| %-26s | %-10s | %12s | %14s | %9s | %14s | %9s |\n", "case", "Octave", "Octave (s)", "cagd 1 thr (s)", "ratio", "cagd " n " thr (s)", "ratio"
      printf "|%s|%s|%s|%s|%s|%s|%s|\n", "----------------------------", "------------", "--------------", "----------------", "-----------", "----------------", "-----------"
    }
    c = one[$1]; a = all[$1]
    printf "| %-26s | %-10s | %12.4g | %14.4g | %8.0fx | %14.4g | %8.0fx |\n", $1, $2, $3, c, (c > 0 ? $3 / c : 0), a, (a > 0 ? $3 / a : 0)
  }
' "$tmp/cagd1.tsv" "$tmp/cagd.tsv" "$tmp/octave.tsv"
echo
echo "cagd alone (seconds, best of several runs; 1 thread, then $threads threads):"
awk -F'\t' 'FNR == NR { if ($0 !~ /^#/) one[$1] = $2; next }
  $0 !~ /^#/ { printf "  %-44s %.4g  %.4g\n", $1, one[$1], $2 } $0 ~ /^#/ { print }' "$tmp/cagd1.tsv" "$tmp/cagd.tsv"

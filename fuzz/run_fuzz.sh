#!/bin/sh
# Runs one fuzz target (built by `RUSTC_BOOTSTRAP=1 cargo fuzz build`) for 10^7 executions or
# 30 minutes, whichever comes first, at the lowest CPU priority.
# Usage: fuzz/run_fuzz.sh TARGET   (from the repository root)
set -e
t="$1"
cd "$(dirname "$0")"
d="$(pwd)"
mkdir -p "corpus/$t" "artifacts/$t" logs
# Absolute paths: the cli target changes into a scratch folder.
exec nice -n 19 "$d/target/x86_64-unknown-linux-gnu/release/$t" "$d/corpus/$t" "$d/seeds/$t" \
  -runs=10000000 -max_total_time=1800 -timeout=30 -rss_limit_mb=2048 -max_len=4096 \
  -artifact_prefix="$d/artifacts/$t/" -print_final_stats=1 > "logs/$t.log" 2>&1

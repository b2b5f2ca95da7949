#!/bin/sh
# Runs one fuzz target (built by `RUSTC_BOOTSTRAP=1 cargo fuzz build`) for 10^7 executions or
# 30 minutes, whichever comes first, at the lowest CPU priority.
# Usage: fuzz/run_fuzz.sh TARGET   (from the repository root)
set -e
t="$1"
cd "$(dirname "$0")"
mkdir -p "corpus/$t" "artifacts/$t" logs
exec nice -n 19 "target/x86_64-unknown-linux-gnu/release/$t" "corpus/$t" "seeds/$t" \
  -runs=10000000 -max_total_time=1800 -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
  -artifact_prefix="artifacts/$t/" -print_final_stats=1 > "logs/$t.log" 2>&1

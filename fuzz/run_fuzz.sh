#!/bin/sh
# Runs one fuzz target (built by `RUSTC_BOOTSTRAP=1 cargo fuzz build`) for 10^7 executions or
# SECONDS (default 1800: 30 minutes), whichever comes first, at the lowest CPU priority
# (CAGD_FUZZ_NICE sets another), from
# CORPUS (default fuzz/corpus/TARGET) and seeds/TARGET, logging to LOG (default
# fuzz/logs/TARGET.log); a failing input is saved under fuzz/artifacts/TARGET/. The one place
# that sets the options of a run: fuzz/smoke.sh runs every target through it for 20 s.
# Usage: fuzz/run_fuzz.sh TARGET [SECONDS [CORPUS [LOG]]]
set -e
t="$1"
seconds="${2:-1800}"
cd "$(dirname "$0")"
d="$(pwd)"
corpus="${3:-$d/corpus/$t}"
log="${4:-$d/logs/$t.log}"
mkdir -p "$corpus" "artifacts/$t" "$(dirname "$log")"
# Absolute paths: the cli target changes into a scratch folder.
# allocator_may_return_null: a fallible reservation (`try_reserve`, which the library uses to
# answer `TooLarge` for sizes it cannot hold) gets null, as from the system allocator, instead of
# AddressSanitizer's abort on a size above its maximum. An infallible allocation that fails
# still aborts, and is still a finding.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}allocator_may_return_null=1"
# 30 s per input; the literal target evaluates each input up to four times in exact
# arithmetic (a matrix, a parameter list, a curve and a surface), each evaluation allowed about
# a second of release work at the default limits (measured: `[1.7918485:1206315]*3`, an exact
# range of 1.2 million elements, is refused after 1.0-1.1 s; all four take 56 s instrumented,
# and the largest range the meter admits, about 2 million such elements, about 1.6 s each):
# 180 s there. A super-linear input still exceeds it.
timeout=30
if [ "$t" = literal ]; then
    timeout=180
fi
# Lowest CPU priority by default; CAGD_FUZZ_NICE=0 gives a long run its fair share of one core
# on a machine busy with other work (at 19 it got 2 % of a core there).
exec nice -n "${CAGD_FUZZ_NICE:-19}" "$d/target/x86_64-unknown-linux-gnu/release/$t" "$corpus" "$d/seeds/$t" \
  -runs=10000000 -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
  -max_len=4096 -artifact_prefix="$d/artifacts/$t/" -print_final_stats=1 > "$log" 2>&1

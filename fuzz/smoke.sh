#!/usr/bin/env bash
# A short fuzzing run for CI: builds the five targets (cargo-fuzz, installed if missing) and
# runs each from its seeds for SECONDS_PER_TARGET seconds (default 20) at the default limits,
# into a throw-away corpus. Any crash, panic, timeout (30 s per input, 180 s for literal, as in
# fuzz/run_fuzz.sh) or out-of-memory input fails it, with the input saved under
# fuzz/artifacts/smoke/. The long runs are fuzz/run_fuzz.sh (10^7 runs or 30 minutes per
# target; results in fuzz/README.md).
# Usage: bash fuzz/smoke.sh   (from anywhere)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
seconds="${SECONDS_PER_TARGET:-20}"
targets=(text_format literal script cli library)

if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "-- cargo install cargo-fuzz"
    cargo install --quiet --locked cargo-fuzz --version 0.13.2
fi
# Stable rustc accepts the flags cargo-fuzz passes with RUSTC_BOOTSTRAP=1.
RUSTC_BOOTSTRAP=1 cargo fuzz build

d="$(pwd)"
# As fuzz/run_fuzz.sh: a fallible reservation of an impossible size gets null, not an abort.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}allocator_may_return_null=1"
mkdir -p artifacts/smoke
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for t in "${targets[@]}"; do
    mkdir -p "$scratch/$t"
    # Per input as in fuzz/run_fuzz.sh: 30 s, 180 s for literal (four exact evaluations).
    timeout=30
    if [ "$t" = literal ]; then
        timeout=180
    fi
    echo "-- $t: ${seconds} s from seeds/$t"
    if ! "$d/target/x86_64-unknown-linux-gnu/release/$t" "$scratch/$t" "$d/seeds/$t" \
            -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 -max_len=4096 \
            -artifact_prefix="$d/artifacts/smoke/$t-" -print_final_stats=1 \
            > "$scratch/$t.log" 2>&1; then
        tail -n 40 "$scratch/$t.log"
        echo "fuzz smoke: $t found an input that fails (saved under fuzz/artifacts/smoke/)" >&2
        exit 1
    fi
    grep -E "^stat::number_of_executed_units|^Done" "$scratch/$t.log" || true
done
echo "fuzz smoke: OK"

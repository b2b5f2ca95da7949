#!/usr/bin/env bash
# A short fuzzing run for CI: first checks that the hostile calls (the `library` target's and
# the property test's) name every public function of the core (fuzz/api_coverage.sh: rustdoc's
# JSON of the core into target/api-coverage, a few seconds once built; it fails on a function
# left out), then builds the five targets (cargo-fuzz, installed if missing) and
# runs each through fuzz/run_fuzz.sh (the same options as the long runs: default limits, 30 s
# per input, 180 s for literal) for SECONDS_PER_TARGET seconds (default 20) from its seeds,
# into a throw-away corpus. Any crash, panic, timeout or out-of-memory input fails it, with the
# input saved under fuzz/artifacts/TARGET/. The long runs' results are in fuzz/README.md.
# Usage: bash fuzz/smoke.sh   (from anywhere)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
seconds="${SECONDS_PER_TARGET:-20}"
targets=(text_format literal script cli library)

echo "-- every public function of the core in the hostile calls (fuzz/api_coverage.sh)"
if ! (cd .. && bash fuzz/api_coverage.sh); then
    echo "fuzz smoke: a public function of the core is not called by crates/cagd-test-support/src/hostile_calls (or a name there is not a public function)" >&2
    exit 1
fi

if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "-- cargo install cargo-fuzz"
    cargo install --quiet --locked cargo-fuzz --version 0.13.2
fi
# Stable rustc accepts the flags cargo-fuzz passes with RUSTC_BOOTSTRAP=1.
RUSTC_BOOTSTRAP=1 cargo fuzz build

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
for t in "${targets[@]}"; do
    echo "-- $t: ${seconds} s from seeds/$t"
    if ! ./run_fuzz.sh "$t" "$seconds" "$scratch/$t" "$scratch/$t.log"; then
        tail -n 40 "$scratch/$t.log"
        echo "fuzz smoke: $t found an input that fails (saved under fuzz/artifacts/$t/)" >&2
        exit 1
    fi
    grep -E "^stat::number_of_executed_units|^Done" "$scratch/$t.log" || true
done
echo "fuzz smoke: OK"

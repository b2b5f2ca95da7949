#!/usr/bin/env bash
# The number of the core's public functions the hostile calls reach, and the list of those
# they do not (fuzz/README.md). Needs python3; rustdoc's JSON output is unstable, so it runs
# with RUSTC_BOOTSTRAP=1 into its own target folder.
# Usage: bash fuzz/api_coverage.sh   (from the repository root)
set -euo pipefail
target=${CARGO_TARGET_DIR:-target}/api-coverage
RUSTC_BOOTSTRAP=1 RUSTDOCFLAGS="-Z unstable-options --output-format json" \
  cargo doc -p cagd --no-deps --quiet --target-dir "$target"
python3 fuzz/api_coverage.py "$target/doc/cagd.json" crates/cagd-test-support/src/hostile_calls

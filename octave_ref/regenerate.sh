#!/usr/bin/env bash
# Regenerate the Octave reference files: runs every octave_ref/cases/*.m in ONE Octave process
# (fixed/ on the path, CAGD_REF_OUT=OUTDIR) and lists the files written.
#
# Usage: bash octave_ref/regenerate.sh [OUTDIR]      (default: octave_ref/expected)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
outdir="${1:-$here/expected}"
mkdir -p "$outdir"
outdir="$(cd "$outdir" && pwd)"

if ! command -v octave >/dev/null 2>&1; then
    echo "regenerate.sh: octave not found (apt-get install octave)" >&2
    exit 2
fi

log="$(mktemp)"
trap 'rm -f "$log"' EXIT
# Octave 7 may print "error: ignoring const execution_exception& while preparing to exit" at
# exit, and its exit status is then unreliable: success is the OK line printed by run_cases.
status=0
octave --no-gui --no-window-system --quiet --norc \
    --eval "addpath('$here'); run_cases('$here', '$outdir');" >"$log" 2>&1 || status=$?
grep -v 'ignoring const execution_exception& while preparing to exit' "$log" || true
if ! grep -q '^run_cases: OK' "$log"; then
    echo "regenerate.sh: FAILED (octave exit status $status)" >&2
    exit 1
fi

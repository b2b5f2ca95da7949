#!/usr/bin/env bash
# Check the committed Octave references: regenerate every case into a temporary directory with
# live Octave and compare with octave_ref/expected/ number by number (compare.py: 4 ULPs or 1e-14
# relative; the "# Created by Octave" line is ignored; a file on one side only fails).
#
# Usage: bash octave_ref/check.sh          exit status 0 = identical within round-off
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
bash "$here/regenerate.sh" "$tmp"
if python3 "$here/compare.py" "$here/expected" "$tmp"; then
    echo "check.sh: octave_ref/expected matches live Octave"
else
    echo "check.sh: FAILED: octave_ref/expected differs from what live Octave writes now" >&2
    echo "  (if a case changed on purpose, run: bash octave_ref/regenerate.sh, and commit)" >&2
    exit 1
fi

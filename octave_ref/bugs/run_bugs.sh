#!/usr/bin/env bash
# Run every bug script of octave_ref/bugs/ against the ORIGINAL thesis code and store what GNU
# Octave writes, stdout and stderr merged in the order written, as OUTDIR/<script>.txt.
#
# Usage: bash octave_ref/bugs/run_bugs.sh [OUTDIR]     (default: octave_ref/bugs/captured)
#        bash octave_ref/bugs/run_bugs.sh --check      (run into a temporary directory and
#                                                        compare with captured/; exit 1 on any
#                                                        difference)
#
# Each script runs in an Octave process of its own (octave --no-gui --no-window-system --quiet
# --norc <script>.m) with octave_ref/bugs/ as the working directory, so an error ends only that
# script, and Octave prints it exactly as a user would see it. Volatile lines are removed:
#   - "error: ignoring const execution_exception& while preparing to exit" (printed by Octave 7
#     at exit or not, depending on the run);
# and the absolute path of octave_ref/ is replaced by "<octave_ref>" (none of today's outputs
# contains it). Nothing else is changed. bug_setup.m and shim/ are helpers, not bug scripts.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ref="$(cd "$here/.." && pwd)"

if ! command -v octave >/dev/null 2>&1; then
    echo "run_bugs.sh: octave not found (apt-get install octave)" >&2
    exit 2
fi

check=0
if [ "${1:-}" = "--check" ]; then
    check=1
    outdir="$(mktemp -d)"
    trap 'rm -rf "$outdir"' EXIT
else
    outdir="${1:-$here/captured}"
    mkdir -p "$outdir"
    outdir="$(cd "$outdir" && pwd)"
fi

count=0
for script in "$here"/*.m; do
    name="$(basename "$script" .m)"
    if [ "$name" = "bug_setup" ]; then
        continue
    fi
    (cd "$here" && octave --no-gui --no-window-system --quiet --norc "$name.m" 2>&1 || true) |
        grep -v '^error: ignoring const execution_exception& while preparing to exit$' |
        sed "s|$ref|<octave_ref>|g" >"$outdir/$name.txt" || true
    count=$((count + 1))
done

if [ "$check" -eq 0 ]; then
    echo "run_bugs.sh: wrote $count file(s) to $outdir"
    exit 0
fi
status=0
for f in "$outdir"/*.txt; do
    name="$(basename "$f")"
    if ! diff -u "$here/captured/$name" "$f"; then
        status=1
    fi
done
for f in "$here"/captured/*.txt; do
    if [ ! -e "$outdir/$(basename "$f")" ]; then
        echo "captured/$(basename "$f") has no bug script" >&2
        status=1
    fi
done
if [ "$status" -eq 0 ]; then
    echo "run_bugs.sh: all $count bug script(s) behave as captured"
else
    echo "run_bugs.sh: FAILED: an original behaves differently from octave_ref/bugs/captured/" >&2
fi
exit "$status"

#!/usr/bin/env bash
# Ctrl-C in live Octave: long calls of the package's functions stop on SIGINT, as Octave's own
# builtins do, and the session goes on.
#
# One Octave process reads its commands from a pipe (as a terminal session reads them). The
# limits are raised (cagd_limits ("max_work", 1e15), ...) so that each call below would run for
# minutes; each is started, SIGINT is sent to Octave half a second after it began, and then:
#   - the rest of its command line must not run (it prints NOT INTERRUPTED otherwise);
#   - the next command must run (AFTER), within HANG seconds of the signal (a generous bound,
#     only to catch a hang: the time it took is printed, not judged);
# and at the end the session computes the thesis's Primer 2.4 correctly.
#
# Usage: bash octave_pkg/tests/interrupt.sh "SETUP"
#   SETUP: Octave commands that make the installed package loadable (ci.sh's pkg prefix).
# Prints one line per call and "interrupt: OK"; exits non-zero on a failure.
set -euo pipefail
setup="${1:-}"
HANG=20

dir="$(mktemp -d)"
pid=""
cleanup() {
    exec 3>&- 2>/dev/null || true
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
        kill -TERM "$pid" 2>/dev/null || true
    fi
    rm -rf "$dir"
}
trap cleanup EXIT
mkfifo "$dir/in"
# In the temporary directory, so that nothing Octave may write stays behind.
(cd "$dir" && exec octave --no-gui --no-window-system --quiet --norc < "$dir/in" > "$dir/log" 2>&1) &
pid=$!
exec 3> "$dir/in"

say() { printf '%s\n' "$1" >&3; }
# Waits until the log has a line matching $1 (at most $2 seconds); prints that line.
wait_for() {
    local deadline=$((SECONDS + $2))
    while [ $SECONDS -le "$deadline" ]; do
        if grep -q -- "$1" "$dir/log"; then
            grep -- "$1" "$dir/log" | head -n 1
            return 0
        fi
        if ! kill -0 "$pid" 2>/dev/null; then
            echo "interrupt: Octave exited" >&2
            cat "$dir/log" >&2
            return 1
        fi
        sleep 0.02
    done
    echo "interrupt: no '$1' within $2 s" >&2
    cat "$dir/log" >&2
    return 1
}

say "crash_dumps_octave_core (false); $setup pkg load cagd; pkg load nurbs;"
say "cagd_limits ('max_work', 1e15); cagd_limits ('max_samples', 1e8); cagd_limits ('max_grid_points', 1e8);"
# The data: a degree-1000 curve, a degree-1000 NURBS surface (a Bézier patch as octave-nurbs
# writes it), 1001 Lagrange nodes, a million parameters.
say "P = ones (2, 1001); t = linspace (0, 1, 1e6); k = [zeros(1, 1001), ones(1, 1001)];"
say "C = zeros (4, 1001, 1001); C(1, :, :) = rand (1001, 1001); C(4, :, :) = 1; srf = nrbmak (C, {k, k});"
say "g = linspace (0, 1, 1000); x = linspace (0, 1, 1001); tt = rand (2, 1e6);"
say "disp ('READY'); fflush (stdout);"
wait_for '^READY' 120 > /dev/null

cases=(
    "cagd_bezier (P, t)"
    "cagd_nrbeval (srf, {g, g})"
    "cagd_nrbeval (srf, tt)"
    "cagd_bspeval (1000, P, k, t)"
    "deCasteljau (P, 1e6)"
    "Lagrange (x, 3, rand (1, 1e7))"
)
failed=0
for k in "${!cases[@]}"; do
    call="${cases[$k]}"
    say "printf ('STARTED $k\n'); fflush (stdout); X = $call; printf ('NOT INTERRUPTED $k\n'); fflush (stdout);"
    say "printf ('AFTER $k %.6f\n', time ()); fflush (stdout);"
    wait_for "^STARTED $k\$" 60 > /dev/null
    sleep 0.5
    sent="$(date +%s.%N)"
    kill -INT "$pid"
    after="$(wait_for "^AFTER $k " "$HANG")" || { failed=1; break; }
    took="$(awk -v a="${after##* }" -v s="$sent" 'BEGIN { printf "%.3f", a - s }')"
    if grep -q "^NOT INTERRUPTED $k\$" "$dir/log"; then
        echo "  $call: ran to its end before the signal (not a long call?)" >&2
        failed=1
    else
        echo "  $call: stopped by SIGINT, the next command ran $took s after the signal"
    fi
done

say "P = [0 0 8 4; 0 2 2 0; 0 2 0 0]; ok = isequal (deCasteljau (P, 3)(:, 2), [3.5; 1.5; 0.75]) && ! exist ('X', 'var');"
say "printf ('ALIVE %d\n', ok); fflush (stdout); exit"
alive="$(wait_for '^ALIVE ' 60)" || failed=1
if [ "$alive" != "ALIVE 1" ]; then
    echo "interrupt: the session is not correct afterwards ($alive)" >&2
    failed=1
fi
if [ "$failed" -ne 0 ]; then
    echo "interrupt: FAILED" >&2
    exit 1
fi
echo "interrupt: OK"

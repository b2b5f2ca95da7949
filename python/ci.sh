#!/usr/bin/env bash
# The Python package's CI (called by .ci/run): build and install it with the pinned install
# line (`pip install ./python`) into a fresh virtual environment, then
#   1. clippy on the extension crate;
#   2. its pytest suite (python/tests: the thesis functions against octave_ref/expected, random
#      cases against scipy, geomdl and dhermes/bezier, the sources' worked examples, bad input);
#   3. scipy's own TestBSpline with scipy.interpolate.BSpline replaced by cagd.BSpline (the
#      test file of the installed scipy, run in place): at least 30 must pass and every failure
#      must be one listed in python/SCIPY_SUITE.md;
#   4. the notebook's code cells (python/examples/run_notebook.py).
# Environment: PYTHON (default python3), CAGD_PY_VENV (default: a new temporary directory).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
start=$SECONDS

python="${PYTHON:-python3}"
venv="${CAGD_PY_VENV:-$(mktemp -d)/venv}"
if ! "$python" -m venv "$venv" 2>/dev/null; then
    echo "== python3 -m venv failed: installing python3-venv"
    sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update && $sudo apt-get install -y python3-venv
    "$python" -m venv "$venv"
fi
py="$venv/bin/python"
"$py" -m pip install --quiet --upgrade pip

echo "== clippy: the extension crate (cagd-python)"
cargo clippy -p cagd-python --all-targets -- -D warnings

echo "== pip install ./python (maturin builds the abi3 wheel)"
"$py" -m pip install --quiet ./python
"$py" -m pip install --quiet pytest scipy geomdl bezier
"$py" -c "import cagd, numpy, scipy; print('cagd', cagd.__version__, '| numpy', numpy.__version__, '| scipy', scipy.__version__)"

echo "== pytest python/tests"
# Run from outside python/ so that `import cagd` is the installed package.
(cd "$root/python/tests" && "$py" -m pytest -q -p no:cacheprovider .)

echo "== scipy's TestBSpline with cagd.BSpline in place of scipy.interpolate.BSpline"
report="$(mktemp -d)/scipy-suite.xml"
(cd "$root/python/tests/scipy_suite" && PYTHONPATH="$PWD" "$py" -m pytest -q -p no:cacheprovider \
    -p cagd_as_scipy_bspline --pyargs scipy.interpolate.tests.test_bsplines::TestBSpline \
    --junitxml="$report" > "$report.log" 2>&1) || true
"$py" "$root/python/tests/scipy_suite/check.py" "$report" "$root/python/SCIPY_SUITE.md"

echo "== the notebook (python/examples/cagd_tour.ipynb): every code cell"
(cd "$root/python/examples" && "$py" run_notebook.py cagd_tour.ipynb)

echo "== python/ci.sh: $((SECONDS - start)) s"

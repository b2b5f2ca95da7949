#!/usr/bin/env bash
# The Python package's CI (called by .ci/run): in a fresh virtual environment, install the
# pinned peers and tools (python/ci-requirements.txt), build the wheel as `pip install ./python`
# builds it (maturin), check that it is an abi3 wheel and install it, then
#   1. clippy on the extension crate;
#   2. mypy's stubtest: the stubs (cagd/*.pyi) match the installed package;
#   3. its pytest suite (python/tests: the thesis functions against octave_ref/expected, random
#      cases against scipy, geomdl and dhermes/bezier, the sources' worked examples, bad input,
#      every docstring example); a peer library missing fails it (CI is set);
#   4. scipy's own TestBSpline with scipy.interpolate.BSpline replaced by cagd.BSpline (the
#      test file of the installed scipy, run in place): as many must pass as
#      python/SCIPY_SUITE.md says, and every failure must be one listed there;
#   5. the notebook's code cells (python/examples/run_notebook.py).
# Environment: PYTHON (default python3), CAGD_PY_VENV (default: a new temporary directory).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$PWD"
start=$SECONDS
# The tests' peers (scipy, geomdl, bezier) are required, not skipped, in CI (tests/conftest.py).
export CI="${CI:-true}"

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

# .ci/run's workspace clippy already checks this crate (it is a workspace member) and says so
# with CAGD_WORKSPACE_CLIPPY=done; run alone, this script checks it itself.
if [ "${CAGD_WORKSPACE_CLIPPY:-}" = done ]; then
    echo "== clippy: the extension crate was checked by .ci/run's workspace clippy"
else
    echo "== clippy: the extension crate (cagd-python)"
    cargo clippy -p cagd-python --all-targets -- -D warnings
fi

echo "== the pinned peers and tools (python/ci-requirements.txt)"
"$py" -m pip install --quiet -r python/ci-requirements.txt

echo "== the wheel of ./python (maturin), an abi3 wheel, installed"
dist="$(mktemp -d)"
"$py" -m pip wheel --quiet --no-deps ./python -w "$dist"
wheel="$(ls "$dist"/cagd-*.whl)"
echo "$(basename "$wheel")"
case "$(basename "$wheel")" in
    *-cp39-abi3-*.whl) ;;
    *) echo "python/ci.sh: $(basename "$wheel") is not an abi3 wheel for CPython >= 3.9" >&2; exit 1 ;;
esac
"$py" -m pip install --quiet --force-reinstall --no-deps "$wheel"
"$py" -c "import cagd, numpy, scipy, geomdl, bezier, pytest; print('cagd', cagd.__version__, '| numpy', numpy.__version__, '| scipy', scipy.__version__, '| geomdl', geomdl.__version__, '| bezier', bezier.__version__, '| pytest', pytest.__version__)"

echo "== stubtest: the stubs match the installed package"
# From an empty directory: `cagd` is the installed package, mypy's cache stays out of the tree.
(cd "$(mktemp -d)" && "$py" -m mypy.stubtest cagd --allowlist "$root/python/stubtest-allowlist.txt")

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

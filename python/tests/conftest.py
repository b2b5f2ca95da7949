"""Shared helpers: the Octave reference files of the repository and the comparison rule of
octave_ref/compare.py (4 ULPs, or 1e-14 relative to the scale of the array)."""

import importlib
import os
import pathlib

import numpy as np
import pytest

import cagd

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXPECTED = ROOT / "octave_ref" / "expected"


@pytest.fixture(scope="session")
def expected():
    """``expected(case)``: the variables GNU Octave saved for ``octave_ref/cases/<case>.m``."""
    cache = {}

    def load(case):
        if case not in cache:
            cache[case] = cagd.octave.load(EXPECTED / f"{case}.txt")
        return cache[case]

    return load


def in_ci():
    """Whether this is a CI run (``CI`` set, as .ci/run and python/ci.sh set it)."""
    return os.environ.get("CI", "").lower() not in ("", "0", "false", "no")


def peer(module):
    """The peer library ``module`` (scipy, geomdl, dhermes/bezier): in CI it must be there (a
    missing peer fails the run: python/ci.sh installs every one, pinned); elsewhere the tests
    that need it are skipped."""
    if in_ci():
        return importlib.import_module(module)
    return pytest.importorskip(module)


def assert_close(name, ours, octave):
    """Within 4 ULPs or 1e-14 relative to the largest magnitude of the Octave array."""
    ours = np.asarray(ours, dtype=float)
    octave = np.asarray(octave, dtype=float)
    assert ours.shape == octave.shape, f"{name}: shape {ours.shape} != {octave.shape}"
    scale = np.max(np.abs(octave)) if octave.size else 0.0
    tol = np.maximum(4 * np.spacing(np.abs(octave)), 1e-14 * scale)
    err = np.abs(ours - octave)
    assert np.all(err <= tol), f"{name}: worst error {err.max():.3e} (allowed {tol.max():.3e})"

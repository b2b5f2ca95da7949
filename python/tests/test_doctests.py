"""Every example of the package's docstrings (``>>>``) runs and prints what it says: the module
docs, every class and its methods, the eight thesis functions of ``cagd.octave``, the
functions and ``cagd.BSpline``. Every public class and every thesis function has examples.

The examples run with ``cagd``, ``np`` (numpy) and ``Fraction`` in scope; ``...`` in an
expected output matches anything (``doctest.ELLIPSIS``)."""

import doctest
import inspect
from fractions import Fraction

import numpy as np
import pytest

import cagd
import cagd.octave

THESIS_FUNCTIONS = [
    "deCasteljau",
    "ploskevB",
    "bilinearna",
    "tenzor",
    "krpaCoons",
    "vrednostCoons",
    "krpaGordon",
    "Lagrange",
]


def _collect():
    """The doctests of the package, by name (``module=False``: the extension's classes and
    functions are found although the module they report is the extension's)."""
    finder = doctest.DocTestFinder(exclude_empty=True)
    tests = {}
    for obj, name in [(cagd, "cagd"), (cagd.octave, "cagd.octave")]:
        globs = {"cagd": cagd, "np": np, "Fraction": Fraction}
        for test in finder.find(obj, name, module=False, globs=globs):
            if test.examples:
                tests.setdefault(test.name, test)
    return tests


TESTS = _collect()


@pytest.fixture(autouse=True)
def _default_limits():
    yield
    cagd.set_limit()


@pytest.mark.parametrize("name", sorted(TESTS))
def test_docstring_examples_run(name):
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    test = TESTS[name]
    out = []
    runner.run(test, out=out.append, clear_globs=False)
    assert runner.failures == 0, "".join(out)


def _has_examples(name):
    return any(t == name or t.endswith("." + name) for t in TESTS)


@pytest.mark.parametrize(
    "name", [n for n in cagd.__all__ if inspect.isclass(getattr(cagd, n))]
)
def test_every_class_has_examples(name):
    assert _has_examples(f"cagd.{name}"), f"cagd.{name} has no >>> example in its docstring"


@pytest.mark.parametrize("name", THESIS_FUNCTIONS)
def test_every_thesis_function_has_examples(name):
    assert _has_examples(f"cagd.octave.{name}"), f"cagd.octave.{name} has no >>> example"


def test_the_examples_are_found():
    # The finder reaches the extension's classes, their methods and the thesis functions: a
    # change that hid them would leave the parametrised test with nothing to run.
    assert "cagd.BezierPatch" in TESTS
    assert "cagd.octave.krpaGordon" in TESTS
    assert "cagd.BSpline" in TESTS
    assert len(TESTS) >= 25

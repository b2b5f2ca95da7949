"""pytest plugin: scipy.interpolate.BSpline replaced by cagd.BSpline before scipy's own test
module is imported, so that its ``TestBSpline`` exercises cagd (python/ci.sh runs it with
``-p cagd_as_scipy_bspline`` on the test file of the installed scipy)."""

import scipy.interpolate

import cagd

_original = scipy.interpolate.BSpline
scipy.interpolate.BSpline = cagd.BSpline

try:  # scipy ≥ 1.15 marks its tests by the array-API capabilities of the class under test
    from scipy._lib._array_api import xp_capabilities_table

    if _original in xp_capabilities_table:
        xp_capabilities_table[cagd.BSpline] = xp_capabilities_table[_original]
except ImportError:
    pass

"""``cagd.BSpline``: a drop-in for evaluating ``scipy.interpolate.BSpline``.

The same constructor, attributes and methods (``t``, ``c``, ``k``, ``extrapolate``, ``axis``,
``tck``, ``__call__``, ``derivative``, ``antiderivative``, ``integrate``, ``basis_element``,
``design_matrix``, ``insert_knot``, ``construct_fast``), computed by the Rust core: this file
only arranges scipy's array layout (the interpolation axis, trailing dimensions, complex
coefficients as pairs of reals) around the core's calls.
"""

import operator

import numpy as np

from . import _cagd


def _error(argument, message):
    """A ``cagd.CagdError`` for a Python value the core never sees (kind ``Conversion``)."""
    error = _cagd.CagdError(f"{argument}: {message}")
    error.kind, error.argument = "Conversion", argument
    return error


def _floats(x, argument):
    """``x`` as a contiguous float64 array (``CagdError`` for what is not real numbers)."""
    try:
        a = np.asarray(x)
        if a.dtype.kind == "c":
            raise TypeError("complex numbers are not supported")
        return np.ascontiguousarray(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise _error(argument, f"expected real numbers ({e})") from None


def _mode(extrapolate):
    return "periodic" if isinstance(extrapolate, str) and extrapolate == "periodic" else bool(extrapolate)


def _normalize_axis(axis, ndim):
    """``axis`` in ``[0, ndim)``; numpy's ``AxisError`` (a ``ValueError``) outside ``[-ndim, ndim)``."""
    axis = operator.index(axis)
    if not -ndim <= axis < ndim:
        error = getattr(getattr(np, "exceptions", np), "AxisError")
        raise error(axis, ndim)
    return axis % ndim


class BSpline:
    r"""A spline of degree ``k`` in the B-spline basis over the knots ``t``:

    .. math:: S(x) = \sum_{j=0}^{n-1} c_j B_{j,k;t}(x), \qquad n = \mathrm{len}(t) - k - 1,

    on the base interval ``[t[k], t[n]]`` (outside it: the end pieces continued,
    ``extrapolate=True``; NaN, ``False``; or the base interval repeated, ``'periodic'``).

    ``c`` has shape ``(n, ...)`` (or the interpolation axis ``axis``); ``S(x)`` has shape
    ``x.shape + c.shape[1:]``. Bad input raises ``cagd.CagdError`` (a ``ValueError``).

    >>> import numpy as np, cagd
    >>> s = cagd.BSpline([0, 0, 0, 1, 2, 3, 3, 3], [1, 3, 2, -1, 4], 2)
    >>> round(float(s.integrate(0.5, 2.5)), 12)      # 37/12
    3.083333333333
    >>> s(np.array([0.0, 3.0])).tolist()
    [1.0, 4.0]
    """

    def __init__(self, t, c, k, extrapolate=True, axis=0):
        self.k = operator.index(k)
        if self.k < 0:
            raise _error("k", "the degree must be non-negative")
        self._t = _floats(t, "t")
        c = np.asarray(c)
        self.extrapolate = "periodic" if _mode(extrapolate) == "periodic" else bool(extrapolate)
        if c.ndim < 1:
            raise _error("c", "coefficients must be at least 1-dimensional")
        self.axis = _normalize_axis(axis, c.ndim)
        if self.axis != 0:
            c = np.moveaxis(c, self.axis, 0)
        if c.dtype.kind not in "fc":
            c = c.astype(np.float64)
        self._c = np.ascontiguousarray(c)
        if self._t.ndim != 1:
            raise _error("t", "the knot vector must be one-dimensional")
        _cagd.bspline_check(self._t, self._pairs(), self.k)

    @classmethod
    def construct_fast(cls, t, c, k, extrapolate=True, axis=0):
        """A spline from arrays already in shape (checked all the same)."""
        return cls(t, c, k, extrapolate, axis)

    @property
    def t(self):
        return self._t

    @t.setter
    def t(self, t):
        self._t = np.asarray(t)

    @property
    def c(self):
        return self._c

    @c.setter
    def c(self, c):
        self._c = np.asarray(c)

    @property
    def tck(self):
        """``(t, c, k)``."""
        return self.t, self.c, self.k

    def _pairs(self):
        """The coefficients as a 2-D float array ``(n, d)``; complex ones as pairs of reals."""
        c = np.ascontiguousarray(self._c)
        if c.dtype.kind == "c":
            c = c.view(np.float64) if c.ndim > 1 else c.view(np.float64).reshape(c.shape[0], 2)
        return np.ascontiguousarray(c.reshape(c.shape[0], -1), dtype=np.float64)

    def _values(self, flat, shape):
        """Values computed as pairs of reals back in the coefficients' dtype and shape."""
        if self._c.dtype.kind == "c":
            flat = np.ascontiguousarray(flat).view(np.complex128)
        return flat.reshape(shape)

    def _from_tc(self, t, c, k, extrapolate):
        tail = self._c.shape[1:]
        if self._c.dtype.kind == "c":
            c = np.ascontiguousarray(c).view(np.complex128)
        c = c.reshape((c.shape[0],) + tail)
        if self.axis != 0:
            c = np.moveaxis(c, 0, self.axis)
        return type(self)(t, c, k, extrapolate, self.axis)

    def __call__(self, x, nu=0, extrapolate=None):
        """The spline (or its derivative of order ``nu``) at ``x``.

        Shape ``x.shape + c.shape[1:]`` (the interpolation axis replaced by ``x``'s axes).
        """
        if extrapolate is None:
            extrapolate = self.extrapolate
        x = np.asarray(x)
        x_shape, x_ndim = x.shape, x.ndim
        flat = _floats(x.ravel(), "x")
        nu = operator.index(nu)
        if nu < 0:
            raise _error("nu", "the derivative order must be non-negative")
        out = _cagd.bspline_eval(self._t, self._pairs(), self.k, flat, nu, _mode(extrapolate))
        out = self._values(out, x_shape + self._c.shape[1:])
        if self.axis != 0:
            axes = list(range(out.ndim))
            axes = axes[x_ndim:x_ndim + self.axis] + axes[:x_ndim] + axes[x_ndim + self.axis:]
            out = out.transpose(axes)
        return out

    def derivative(self, nu=1):
        r"""The derivative of order ``nu`` as a spline of degree ``k - nu``:
        :math:`c'_j = k (c_{j+1} - c_j)/(t_{j+k+1} - t_{j+1})`, applied ``nu`` times."""
        t, c = _cagd.bspline_derivative(self._t, self._pairs(), self.k, operator.index(nu))
        return self._from_tc(t, c, self.k - nu, self.extrapolate)

    def antiderivative(self, nu=1):
        r"""The antiderivative of order ``nu``, degree ``k + nu``: once,
        :math:`d_0 = 0,\ d_i = \sum_{j<i} c_j (t_{j+k+1} - t_j)/(k+1)` over the knots with
        the first and the last repeated once more."""
        t, c = _cagd.bspline_antiderivative(self._t, self._pairs(), self.k, operator.index(nu))
        extrapolate = False if self.extrapolate == "periodic" else self.extrapolate
        return self._from_tc(t, c, self.k + nu, extrapolate)

    def integrate(self, a, b, extrapolate=None):
        r""":math:`\int_a^b S(x)\,dx` (shape ``c.shape[1:]``); outside the base interval as
        ``extrapolate`` says (``False``: only the part inside counts)."""
        if extrapolate is None:
            extrapolate = self.extrapolate
        out = _cagd.bspline_integrate(
            self._t, self._pairs(), self.k, float(a), float(b), _mode(extrapolate)
        )
        # The interpolation axis is gone: the remaining axes keep their order.
        return np.asarray(self._values(out, self._c.shape[1:]))

    def insert_knot(self, x, m=1):
        """The same spline with the knot ``x`` inserted ``m`` times (Boehm)."""
        t, c = _cagd.bspline_insert_knot(
            self._t, self._pairs(), self.k, float(x), operator.index(m)
        )
        return self._from_tc(t, c, self.k, self.extrapolate)

    @classmethod
    def basis_element(cls, t, extrapolate=True):
        """The single B-spline ``B(x | t[0], ..., t[k+1])`` of degree ``k = len(t) - 2``."""
        t2, c2, k = _cagd.bspline_basis_element(_floats(t, "t").ravel())
        return cls(t2, c2.ravel(), k, extrapolate)

    @classmethod
    def design_matrix(cls, x, t, k, extrapolate=False):
        """The design matrix ``A[r, j] = B_j(x[r])`` as a ``scipy.sparse.csr_array``."""
        from scipy.sparse import csr_array

        x = _floats(x, "x").ravel()
        k = operator.index(k)
        if k < 0:
            raise _error("k", "the degree must be non-negative")
        data, first, n = _cagd.bspline_design_matrix(x, _floats(t, "t"), k, _mode(extrapolate))
        width = k + 1
        index = np.int32 if x.size * width < np.iinfo(np.int32).max else np.int64
        indices = (first.astype(index)[:, None] + np.arange(width, dtype=index)).ravel()
        indptr = np.arange(0, (x.size + 1) * width, width, dtype=index)
        return csr_array((data.ravel(), indices, indptr), shape=(x.size, n))

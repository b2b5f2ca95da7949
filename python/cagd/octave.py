"""The eight functions of the thesis (I. Čavdek, *Bézierove in Gordon-Coons krpe*, Koper 2014),
fixed, with the arguments, array layouts and outputs of ``octave_ref/fixed/``.

A script ported from Octave changes ``deCasteljau(B, N)`` into
``cagd.octave.deCasteljau(B, N)`` and nothing else: control points are **columns**
(``d × (n+1)``), packed nets ``(m+1) × 3(n+1)`` with ``B[i, 3j:3j+3] = b_ij``, surfaces
``N × N × 3``, and several outputs come back as a tuple (``R, P = krpaCoons(...)``).
Samples are ``t = linspace(0, 1, N)`` as Octave computes it, so the numbers agree with the
fixed Octave code to its last bits.

Exact arithmetic: ``object`` arrays of ``fractions.Fraction`` (or ints), or ``Fraction``
parameters, give exact ``Fraction`` results (samples ``t = k/(N-1)`` exactly).

>>> import numpy as np
>>> from cagd.octave import deCasteljau
>>> B = np.array([[0, 0, 8, 4], [0, 2, 2, 0], [0, 2, 0, 0]])   # Primer 2.4, points as columns
>>> deCasteljau(B, 3)[:, 1]                                     # b(1/2)
array([3.5 , 1.5 , 0.75])

``load(path)`` reads an Octave text file (``save -text``) into a dict of arrays;
``save(path, T=T, P=P)`` writes one that Octave's ``load`` reads, every bit kept.
"""

from ._cagd import octave as _octave

deCasteljau = _octave.deCasteljau
ploskevB = _octave.ploskevB
bilinearna = _octave.bilinearna
tenzor = _octave.tenzor
krpaCoons = _octave.krpaCoons
vrednostCoons = _octave.vrednostCoons
krpaGordon = _octave.krpaGordon
Lagrange = _octave.Lagrange
load = _octave.load
save = _octave.save

__all__ = [
    "deCasteljau",
    "ploskevB",
    "bilinearna",
    "tenzor",
    "krpaCoons",
    "vrednostCoons",
    "krpaGordon",
    "Lagrange",
    "load",
    "save",
]

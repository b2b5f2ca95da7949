//! Bernstein polynomials.

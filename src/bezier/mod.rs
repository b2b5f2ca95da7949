//! Bézier curves and patches.

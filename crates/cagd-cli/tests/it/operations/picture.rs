//! Pictures' polylines: sampled finely enough that chords are short and close to the curve,
//! each axis counted against its own side, bounded, and kept as they are when refused.

use cagd_ops::picture::{
    picture_line, samples_for, MAX_CHORD_PIXELS, MAX_PICTURE_SAMPLES, MAX_SAG_PIXELS,
};
use nalgebra::DMatrix;

/// The curve (t, t³ − t) at `ts`.
fn cubic(ts: &[f64]) -> DMatrix<f64> {
    DMatrix::from_fn(2, ts.len(), |r, k| {
        let t = ts[k];
        if r == 0 {
            t
        } else {
            t * t * t - t
        }
    })
}

#[test]
fn chords_become_short_and_close_to_the_curve() {
    let line = picture_line((&-1.0, &1.0), 11, false, |ts| Ok(cubic(ts)), |_| true).unwrap();
    let n = line.ncols();
    assert!(n > 11 && n < MAX_PICTURE_SAMPLES && n % 2 == 1, "{n}");
    // The extent is 2 (t over [−1, 1]; t³ − t within ±0.39): 400 pixels a unit.
    let px = 400.0;
    let longest = (1..n)
        .map(|k| (line.column(k) - line.column(k - 1)).norm())
        .fold(0.0, f64::max);
    assert!(longest * px <= MAX_CHORD_PIXELS, "{}", longest * px);
    // The curve between samples: at the middle of each step, off the chord by at most
    // the sag allowed.
    let ts = cagd::linspace(-1.0, 1.0, n);
    for k in 1..n {
        let mid = cubic(&[(ts[k - 1] + ts[k]) / 2.0]);
        let (a, b) = (line.column(k - 1), line.column(k));
        let (ab, am) = (b - a, mid.column(0) - a);
        let off = (&am - &ab * (am.dot(&ab) / ab.norm_squared())).norm();
        assert!(off * px <= MAX_SAG_PIXELS, "step {k}: {}", off * px);
    }
}

#[test]
fn a_graph_counts_each_axis_against_its_own_side() {
    // (0, 0), (1, 1/2), (4, 1). As geometry 200 pixels a unit (the extent 4): chords of
    // 223.6 and 608.3 pixels, the middle point 48.5 pixels off the chord of its
    // neighbours. 608.3 / 6 = 101.4 times as many steps: 203.8, so 204, and 205 samples
    // (odd). As a graph x has 200 and y 800 pixels a unit: chords of 447.2 and 721.1
    // pixels, 120.2 times as many steps, 241 and 243 samples.
    let line = DMatrix::from_column_slice(2, 3, &[0.0, 0.0, 1.0, 0.5, 4.0, 1.0]);
    assert_eq!(samples_for(&line, false), 205);
    assert_eq!(samples_for(&line, true), 243);
}

#[test]
fn a_straight_line_needs_short_chords_only() {
    // 11 samples of a segment of 800 pixels: chords of 80 pixels, no sag. 80 / 6 = 13.3
    // times as many steps: 133.3, so 134, and 135 samples.
    let line = DMatrix::from_fn(2, 11, |r, k| k as f64 * [1.0, 0.0][r]);
    assert_eq!(samples_for(&line, false), 135);
    // A line already fine stays as it is.
    let fine = DMatrix::from_fn(2, 201, |r, k| k as f64 * [1.0, 0.0][r]);
    assert_eq!(samples_for(&fine, false), 201);
}

#[test]
fn bounded_and_kept_when_refused() {
    // A spike among a thousand points on a line asks for more than the bound.
    let long = DMatrix::from_fn(2, 1000, |r, k| {
        if r == 1 && k == 500 {
            1.0
        } else {
            k as f64 * 1e-3 * (1 - r) as f64
        }
    });
    assert_eq!(samples_for(&long, false), MAX_PICTURE_SAMPLES);
    // A point, two points, or a non-finite value: the samples as they are.
    assert_eq!(samples_for(&DMatrix::zeros(2, 5), false), 5);
    assert_eq!(
        samples_for(&DMatrix::from_column_slice(2, 2, &[0., 0., 1., 1.]), false),
        2
    );
    let mut bad = cubic(&cagd::linspace(-1.0, 1.0, 5));
    bad[(1, 2)] = f64::NAN;
    assert_eq!(samples_for(&bad, false), 5);
    // Work refused: the first polyline.
    let line = picture_line((&-1.0, &1.0), 11, false, |ts| Ok(cubic(ts)), |_| false).unwrap();
    assert_eq!(line.ncols(), 11);
}

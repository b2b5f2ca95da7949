//! Pictures drawn where the answer is, to a fraction of a pixel: a curve's polyline lies on the
//! exact curve mapped to pixels (no staircase of whole pixels), its chords are a few pixels
//! long and close to the curve (no corners), and the values of a basis are marked where they
//! are. The exact curves and values are worked out by hand (a parabola, the unit circle, the
//! Bernstein polynomials); the mapping to pixels is read off the picture's own control points
//! or axis ticks.

use super::slips::{binary, canvas_per_pixel, circles, svg_texts};

/// The polylines of an SVG drawn `width` pixels wide, in pixels of the picture.
fn polylines(svg: &str, width: f64) -> Vec<Vec<(f64, f64)>> {
    let scale = canvas_per_pixel(svg);
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter(|n| {
            n.attribute("stroke-width")
                .and_then(|w| w.parse::<f64>().ok())
                == Some(width * scale)
        })
        .map(|n| {
            n.attribute("points")
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (
                        x.parse::<f64>().unwrap() / scale,
                        y.parse::<f64>().unwrap() / scale,
                    )
                })
                .collect()
        })
        .collect()
}

/// The one curve of a picture: its polyline 2 pixels wide (the legend's sample of it has two
/// points).
fn the_curve(svg: &str) -> Vec<(f64, f64)> {
    let mut lines: Vec<_> = polylines(svg, 2.0)
        .into_iter()
        .filter(|l| l.len() > 2)
        .collect();
    assert_eq!(lines.len(), 1, "one curve");
    lines.pop().unwrap()
}

/// The control points of a picture: its red rings of radius 5 pixels, in drawing order.
fn control_points(svg: &str) -> Vec<(f64, f64)> {
    circles(svg)
        .into_iter()
        .filter(|c| c.2 == 5.0 && c.3.contains("fill=\"none\""))
        .map(|c| (c.0, c.1))
        .collect()
}

/// The line `pixel = a + b · value` through `(value, pixel)` pairs, by least squares.
fn fit(pairs: &[(f64, f64)]) -> Axis {
    let n = pairs.len() as f64;
    let (mv, mp) = (
        pairs.iter().map(|p| p.0).sum::<f64>() / n,
        pairs.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let b = pairs.iter().map(|p| (p.0 - mv) * (p.1 - mp)).sum::<f64>()
        / pairs.iter().map(|p| (p.0 - mv).powi(2)).sum::<f64>();
    (mp - b * mv, b)
}

/// A map of data to pixels along one axis: `pixel = a + b · value`.
type Axis = (f64, f64);

/// The parabola of `decasteljau [0 1 2; 0 2 0]`: x = 2t, y = 4t(1 − t), so y = 2x − x²; its
/// polyline in pixels and the map of data to pixels (x = ax + bx·x, y = ay + by·y) from the
/// control points' rings (0, 0), (1, 2), (2, 0).
fn parabola() -> (Vec<(f64, f64)>, Axis, Axis) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.svg");
    binary(&[
        "decasteljau",
        "[0 1 2; 0 2 0]",
        "--plot",
        path.to_str().unwrap(),
    ]);
    let svg = std::fs::read_to_string(&path).unwrap();
    let control = control_points(&svg);
    assert_eq!(control.len(), 3, "{control:?}");
    let data = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)];
    let xs: Vec<(f64, f64)> = data.iter().zip(&control).map(|(d, c)| (d.0, c.0)).collect();
    let ys: Vec<(f64, f64)> = data.iter().zip(&control).map(|(d, c)| (d.1, c.1)).collect();
    (the_curve(&svg), fit(&xs), fit(&ys))
}

/// The distance in pixels from the pixel `(px, py)` to the parabola y = 2x − x² drawn by the
/// map `(ax, bx)`, `(ay, by)`: |F| / |∇F| of F = y − 2x + x² in pixels (first order, exact
/// to far below a pixel this close to the curve).
fn off_parabola((px, py): (f64, f64), (ax, bx): Axis, (ay, by): Axis) -> f64 {
    let (x, y) = ((px - ax) / bx, (py - ay) / by);
    let f = y - 2.0 * x + x * x;
    let (fx, fy) = ((-2.0 + 2.0 * x) / bx, 1.0 / by);
    f.abs() / fx.hypot(fy)
}

#[test]
fn a_curve_is_drawn_to_a_tenth_of_a_pixel() {
    // Plotters places points on whole units of its canvas; on a canvas of the picture's own
    // size the parabola's points strayed up to half a pixel (a staircase). On the finer
    // canvas every point lies within a tenth of a pixel of the parabola.
    let (line, x, y) = parabola();
    assert!(line.len() > 50, "{} points", line.len());
    let worst = line
        .iter()
        .map(|&p| off_parabola(p, x, y))
        .fold(0.0, f64::max);
    assert!(worst <= 0.1, "a point {worst} pixels off the parabola");
    // Not whole pixels: most points fall between them.
    let whole = line
        .iter()
        .filter(|p| p.0.fract() == 0.0 && p.1.fract() == 0.0)
        .count();
    assert!(
        whole * 4 < line.len(),
        "{whole} of {} on whole pixels",
        line.len()
    );
}

#[test]
fn a_curves_chords_are_short_and_close_to_it() {
    // The chords of a curve's polyline are at most 6 pixels long (101 samples made chords of
    // 11 pixels here) and their middles stray from the curve by a tenth of a pixel at most:
    // no corners.
    let (line, x, y) = parabola();
    for w in line.windows(2) {
        let (p, q) = (w[0], w[1]);
        let chord = (q.0 - p.0).hypot(q.1 - p.1);
        assert!(chord <= 6.0, "a chord of {chord} pixels from {p:?}");
        let middle = ((p.0 + q.0) / 2.0, (p.1 + q.1) / 2.0);
        let off = off_parabola(middle, x, y);
        assert!(
            off <= 0.1,
            "a chord's middle {off} pixels off the parabola at {p:?}"
        );
    }
    // From end to end: b(0) = (0, 0) and b(1) = (2, 0).
    let (first, last) = (line[0], line[line.len() - 1]);
    assert!((first.0 - x.0).abs() <= 0.1 && (first.1 - y.0).abs() <= 0.1);
    assert!((last.0 - (x.0 + 2.0 * x.1)).abs() <= 0.1 && (last.1 - y.0).abs() <= 0.1);
}

#[test]
fn the_circle_is_round_to_a_tenth_of_a_pixel() {
    // `cagd circle`: the unit circle, its control points (1,0), (1,1), (0,1), (−1,1),
    // (−1,0), (−1,−1), (0,−1), (1,−1), (1,0) (nrbcirc). Every point of the polyline and every
    // chord's middle lies within a tenth of a pixel of the circle through them mapped to
    // pixels.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("c.svg");
    binary(&["circle", "--plot", path.to_str().unwrap()]);
    let svg = std::fs::read_to_string(&path).unwrap();
    let control = control_points(&svg);
    let data = [
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
        (-1.0, 1.0),
        (-1.0, 0.0),
        (-1.0, -1.0),
        (0.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
    ];
    assert_eq!(control.len(), data.len(), "{control:?}");
    let xs: Vec<(f64, f64)> = data.iter().zip(&control).map(|(d, c)| (d.0, c.0)).collect();
    let ys: Vec<(f64, f64)> = data.iter().zip(&control).map(|(d, c)| (d.1, c.1)).collect();
    let ((ax, bx), (ay, by)) = (fit(&xs), fit(&ys));
    // Equal scales: a unit is as many pixels across as up (y grows downwards).
    assert!((bx + by).abs() < 1e-3 * bx.abs(), "{bx} {by}");
    let off = |(px, py): (f64, f64)| ((px - ax).hypot(py - ay) - bx.abs()).abs();
    let line = the_curve(&svg);
    let worst = line.iter().map(|&p| off(p)).fold(0.0, f64::max);
    assert!(worst <= 0.1, "a point {worst} pixels off the circle");
    for w in line.windows(2) {
        let middle = ((w[0].0 + w[1].0) / 2.0, (w[0].1 + w[1].1) / 2.0);
        assert!(
            off(middle) <= 0.1,
            "a chord's middle {} pixels off",
            off(middle)
        );
    }
}

#[test]
fn the_bernstein_plot_marks_each_value_where_it_is() {
    // B_i^3(t) = C(3, i) t^i (1 − t)^(3−i): at t = 1/4 (27, 27, 9, 1)/64, at t = 1/2
    // (1, 3, 3, 1)/8. Each value is marked at (t, B_i^3(t)), as bspline-basis marks its own.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("b.svg");
    binary(&[
        "bernstein",
        "--degree",
        "3",
        "--t",
        "[1/4 1/2]",
        "--plot",
        path.to_str().unwrap(),
    ]);
    let svg = std::fs::read_to_string(&path).unwrap();
    // The map of (t, value) to pixels from the tick labels: the numbers in a row under the
    // chart are t at their x, those in a column left of it values at their y.
    let numbers: Vec<(f64, f64, f64)> = svg_texts(&svg)
        .into_iter()
        .filter_map(|(x, y, t)| t.parse::<f64>().ok().map(|v| (x, y, v)))
        .collect();
    let most = |key: &dyn Fn(&(f64, f64, f64)) -> f64| {
        let keys: Vec<f64> = numbers.iter().map(key).collect();
        *keys
            .iter()
            .max_by_key(|k| keys.iter().filter(|j| j == k).count())
            .unwrap()
    };
    let (column, row) = (most(&|n| n.0), most(&|n| n.1));
    let t_ticks: Vec<(f64, f64)> = numbers
        .iter()
        .filter(|n| n.1 == row)
        .map(|n| (n.2, n.0))
        .collect();
    let value_ticks: Vec<(f64, f64)> = numbers
        .iter()
        .filter(|n| n.0 == column)
        .map(|n| (n.2, n.1))
        .collect();
    assert!(t_ticks.len() >= 3 && value_ticks.len() >= 3);
    let ((at, bt), (av, bv)) = (fit(&t_ticks), fit(&value_ticks));
    let expected: Vec<(f64, f64)> = [
        (0.25, [27.0, 27.0, 9.0, 1.0], 64.0),
        (0.5, [1.0, 3.0, 3.0, 1.0], 8.0),
    ]
    .iter()
    .flat_map(|&(t, b, d)| b.map(|b| (t, b / d)))
    .collect();
    // The markers: black discs of radius 6 (the legend's is 5).
    let markers: Vec<_> = circles(&svg).into_iter().filter(|c| c.2 == 6.0).collect();
    assert_eq!(markers.len(), expected.len(), "{markers:?}");
    for (m, (t, b)) in markers.iter().zip(&expected) {
        let (px, py) = (at + bt * t, av + bv * b);
        assert!(
            (m.0 - px).abs() <= 0.2 && (m.1 - py).abs() <= 0.2,
            "marker at ({}, {}), B({t}) = {b} at ({px}, {py})",
            m.0,
            m.1
        );
    }
    // Labelled with their parameters, and named in the legend.
    let texts: Vec<String> = svg_texts(&svg).into_iter().map(|t| t.2).collect();
    assert_eq!(
        texts.iter().filter(|t| *t == "t = 0.25").count(),
        4,
        "{texts:?}"
    );
    assert_eq!(
        texts.iter().filter(|t| *t == "t = 0.5").count(),
        4,
        "{texts:?}"
    );
    assert!(texts.iter().any(|t| t == "values at t"), "{texts:?}");
}

#[test]
fn the_svg_keeps_the_pictures_size_and_the_png_its_pixels() {
    // The picture is drawn on a finer canvas: the SVG says so in its viewBox, its width and
    // height are the picture's; the PNG has the picture's pixels.
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("s.svg");
    let png = dir.path().join("s.png");
    for path in [&svg, &png] {
        binary(&[
            "decasteljau",
            "[0 1 2; 0 2 0]",
            "--plot",
            path.to_str().unwrap(),
        ]);
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let root = doc.root_element();
    assert_eq!(
        (root.attribute("width"), root.attribute("height")),
        (Some("900"), Some("700"))
    );
    assert_eq!(root.attribute("viewBox"), Some("0 0 18000 14000"));
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(&png).unwrap()));
    let info = decoder.read_info().unwrap();
    assert_eq!((info.info().width, info.info().height), (900, 700));
}

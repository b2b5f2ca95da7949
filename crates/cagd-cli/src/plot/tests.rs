//! The figures drawn, read back as SVG and PNG.

use super::*;
use cagd::grid::PointGrid;
use nalgebra::DMatrix;
use plotters::prelude::{RGBColor, WHITE};
use plotters::style::IntoFont;
use std::path::Path;

fn helix() -> DMatrix<f64> {
    DMatrix::from_fn(3, 40, |k, j| {
        let t = j as f64 / 39.0 * 6.0;
        [t.cos(), t.sin(), t / 6.0][k]
    })
}

fn saddle(n: usize) -> PointGrid<f64> {
    PointGrid::from_shape_fn((n, n, 3), |(i, j, k)| {
        let (u, v) = (i as f64 / (n - 1) as f64, j as f64 / (n - 1) as f64);
        [u, v, (u - 0.5) * (v - 0.5)][k]
    })
}

fn count(doc: &roxmltree::Document, tag: &str) -> usize {
    doc.descendants().filter(|n| n.has_tag_name(tag)).count()
}

#[test]
fn svg_is_well_formed_with_title_legend_and_layers() {
    let control =
        DMatrix::from_column_slice(3, 4, &[0., 0., 0., 0., 2., 2., 8., 2., 0., 4., 0., 0.]);
    let svg = Figure::new("Bézier curve")
        .curve(helix(), Colour::Blue, "curve")
        .control_polygon(control, "control polygon")
        .render(ImageKind::Svg)
        .unwrap();
    let text = String::from_utf8(svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let texts: Vec<&str> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(str::trim)
        .collect();
    for expected in ["Bézier curve", "curve", "control polygon", "x", "y", "z"] {
        assert!(
            texts.contains(&expected),
            "missing text {expected:?} in {texts:?}"
        );
    }
    // Four control points drawn as circles (plus one in the legend).
    assert_eq!(count(&doc, "circle"), 5);
}

#[test]
fn surface_svg_has_one_polygon_per_cell() {
    let n = 6;
    let svg = Figure::new("surf")
        .surface(saddle(n), "")
        .render(ImageKind::Svg)
        .unwrap();
    let text = String::from_utf8(svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    // (n−1)² filled cells, plus the three back panels of the axes box.
    assert_eq!(count(&doc, "polygon"), (n - 1) * (n - 1) + 3);
}

#[test]
fn png_decodes_with_the_requested_size_and_colours() {
    let bytes = Figure::new("surf")
        .surface(saddle(8), "patch")
        .net(saddle(3), Colour::Red, "net")
        .with_size(640, 480)
        .render(ImageKind::Png)
        .unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.width, info.height), (640, 480));
    assert_eq!(info.color_type, png::ColorType::Rgb);
    let pixels = &buf[..info.buffer_size()];
    let has = |c: RGBColor| pixels.chunks(3).any(|p| p == [c.0, c.1, c.2]);
    assert!(has(WHITE), "background");
    assert!(has(render::rgb(Colour::Red)), "the red net is visible");
    let viridis_like = pixels
        .chunks(3)
        .filter(|p| p[2] as i32 > p[0] as i32 + 30 && p[1] > 40)
        .count();
    assert!(viridis_like > 1000, "the surface is filled");
}

#[test]
fn planar_layers_make_a_2d_chart() {
    let square = DMatrix::from_column_slice(2, 5, &[0., 0., 1., 0., 1., 1., 0., 1., 0., 0.]);
    let svg = Figure::new("plane")
        .curve(square, Colour::Blue, "square")
        .render(ImageKind::Svg)
        .unwrap();
    let text = String::from_utf8(svg).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    assert_eq!(count(&doc, "polygon"), 0, "no 3-D axis panels");
}

#[test]
fn bad_figures_are_errors() {
    assert_eq!(
        Figure::new("").render(ImageKind::Svg),
        Err(PlotError::Empty)
    );
    let four_d = DMatrix::zeros(4, 3);
    assert!(matches!(
        Figure::new("")
            .curve(four_d, Colour::Blue, "c")
            .render(ImageKind::Png),
        Err(PlotError::Shape { .. })
    ));
    let mut bad = helix();
    bad[(2, 7)] = f64::NAN;
    assert!(matches!(
        Figure::new("")
            .curve(bad, Colour::Blue, "c")
            .render(ImageKind::Svg),
        Err(PlotError::NonFinite { index: 23, .. })
    ));
    assert!(matches!(
        Figure::new("")
            .curve(helix(), Colour::Blue, "c")
            .with_size(50, 50)
            .render(ImageKind::Svg),
        Err(PlotError::Size { .. })
    ));
    assert!(matches!(
        ImageKind::from_path(Path::new("a.jpg")),
        Err(PlotError::UnknownExtension { .. })
    ));
    assert_eq!(ImageKind::from_path(Path::new("A.PNG")), Ok(ImageKind::Png));
}

#[test]
fn marked_points_too_far_to_draw_are_left_out_and_the_legend_says_so() {
    // decasteljau --t "[0.5 1e308]" --plot: the point at 1e308 is printed, not drawn.
    let line = DMatrix::from_column_slice(2, 2, &[0., 0., 1., 1.]);
    let at = DMatrix::from_column_slice(2, 2, &[0.5, 0.5, 1e308, 1e308]);
    let svg = Figure::new("Bézier curve")
        .curve(line.clone(), Colour::Blue, "curve")
        .points(
            at,
            vec!["t = 1/2".into(), "t = 1e308".into()],
            "points at t",
        )
        .render(ImageKind::Svg)
        .unwrap();
    let text = String::from_utf8(svg).unwrap();
    assert!(text.contains("t = 1/2"), "{text}");
    assert!(!text.contains("t = 1e308"));
    assert!(text.contains("points at t (1 beyond ±1e100, not drawn)"));
    // The curve itself out of range is still refused.
    let far = DMatrix::from_column_slice(2, 2, &[0., 0., 1e308, 1.]);
    let e = Figure::new("far")
        .curve(far, Colour::Blue, "curve")
        .render(ImageKind::Svg)
        .unwrap_err();
    assert!(matches!(e, PlotError::OutOfRange { .. }), "{e}");
}

/// Every advance of the table is the embedded font's, at the pictures' sizes; words of the
/// pictures in the three languages are within their kerning of the font's measure.
#[test]
fn the_table_is_the_embedded_fonts() {
    super::render::register_font_for_tests();
    let exact = ("sans-serif", text_size::HEIGHT_UNITS).into_font();
    for c in ' '..='~' {
        assert_eq!(
            exact.box_size(&c.to_string()).unwrap(),
            text_size::from_table(text_size::HEIGHT_UNITS, &c.to_string()),
            "{c:?}"
        );
    }
    for c in "áčďéěíňóřšťúůýžÁČĎÉĚÍŇÓŘŠŤÚŮÝŽ−×".chars() {
        let (w, _) = exact.box_size(&c.to_string()).unwrap();
        assert_eq!(
            w,
            text_size::from_table(text_size::HEIGHT_UNITS, &c.to_string()).0,
            "{c:?}"
        );
    }
    for size in [14.0, 15.0, 16.0, 18.0] {
        let font = ("sans-serif", size * 20.0).into_font();
        for text in [
            "x(t)",
            "-0.5",
            "1.25",
            "b(1/2)",
            "Bézier curve",
            "Bézierova krivulja",
            "Beziérova křivka",
            "control polygon",
            "u = 0.2, v = 0.5",
        ] {
            let (w, h) = font.box_size(text).unwrap();
            let (tw, th) = text_size::from_table(size * 20.0, text);
            assert_eq!(th, h, "{text}");
            assert!(
                (f64::from(tw) - f64::from(w)).abs() <= 0.02 * f64::from(w) + 1.0,
                "{text}: {tw} against {w}"
            );
        }
    }
}

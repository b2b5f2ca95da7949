//! The size of a line of text in a picture, as plotters needs it to place labels.
//!
//! Natively plotters measures with the embedded DejaVu Sans (ab_glyph): the width is the sum of
//! the glyphs' advances (with kerning) at a scale where the font's height, ascent − descent
//! = 2384 font units, is the text's size; the height is the size / 1.24. Compiled to
//! WebAssembly, plotters would measure with the page's DOM instead (a `<span>` appended to the
//! document and its `offsetWidth` read): a forced layout of the page for every label, and no
//! DOM at all in a worker. There the same widths come from DejaVu Sans' advances below, so that
//! the page places labels as the program does, the same in a worker as on the page's main
//! thread. Every text of a picture is measured here (the legend too, drawn by the picture code
//! rather than by plotters), so the WebAssembly never asks the DOM.

use plotters::style::FontDesc;

/// DejaVu Sans' advance widths (font units, 2048 to the em) of the printable ASCII characters,
/// `' '` to `'~'`; checked against the embedded font by the tests.
const ADVANCES: [u16; 95] = [
    651, 821, 942, 1716, 1303, 1946, 1597, 563, 799, 799, 1024, 1716, 651, 739, 651, 690, 1303,
    1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 1303, 690, 690, 1716, 1716, 1716, 1087, 2048,
    1401, 1405, 1430, 1577, 1294, 1178, 1587, 1540, 604, 604, 1343, 1141, 1767, 1532, 1612, 1235,
    1612, 1423, 1300, 1251, 1499, 1401, 2025, 1403, 1251, 1403, 799, 690, 799, 1716, 1024, 1024,
    1255, 1300, 1126, 1300, 1260, 721, 1300, 1298, 569, 569, 1186, 569, 1995, 1298, 1253, 1300,
    1300, 842, 1067, 803, 1298, 1212, 1675, 1212, 1212, 1075, 1303, 690, 1303, 1716,
];

/// DejaVu Sans' height, ascent − descent, in font units: the scale of a text's size.
pub(super) const HEIGHT_UNITS: f64 = 2384.0;

/// The advance of `c` in font units: the table's for ASCII, the base letter's for the accented
/// letters of the course's languages (DejaVu Sans gives them the same advance), the plus sign's
/// for − × ±, the digits' for anything else.
fn advance(c: char) -> u16 {
    let base = match c {
        'á' | 'à' | 'ä' | 'â' => 'a',
        'č' | 'ć' | 'ç' => 'c',
        'ď' => 'd',
        'é' | 'è' | 'ě' | 'ë' | 'ê' => 'e',
        'í' | 'ì' | 'ï' => 'i',
        'ň' | 'ñ' => 'n',
        'ó' | 'ò' | 'ö' | 'ô' => 'o',
        'ř' => 'r',
        'š' => 's',
        'ť' => 't',
        'ú' | 'ù' | 'ů' | 'ü' => 'u',
        'ý' => 'y',
        'ž' => 'z',
        'Á' | 'Ä' => 'A',
        'Č' | 'Ć' => 'C',
        'Ď' => 'D',
        'É' | 'Ě' => 'E',
        'Í' => 'I',
        'Ň' => 'N',
        'Ó' | 'Ö' => 'O',
        'Ř' => 'R',
        'Š' => 'S',
        'Ť' => 'T',
        'Ú' | 'Ů' | 'Ü' => 'U',
        'Ý' => 'Y',
        'Ž' => 'Z',
        '−' | '×' | '±' => '+',
        '·' => '.',
        c if (' '..='~').contains(&c) => c,
        _ => '0',
    };
    ADVANCES[base as usize - ' ' as usize]
}

/// The width and height of `text` at `size` (plotters' units), without kerning.
// Natively only its tests call it (the embedded font measures there).
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub(super) fn from_table(size: f64, text: &str) -> (u32, u32) {
    let units: u32 = text.chars().map(|c| u32::from(advance(c))).sum();
    let width = f64::from(units) * size / HEIGHT_UNITS;
    (width as u32, (size / 1.24) as u32)
}

/// The width and height of `text` in `font`: measured with the embedded font natively, from
/// its advances in WebAssembly.
pub(super) fn text_size(
    font: &FontDesc<'_>,
    text: &str,
) -> Result<(u32, u32), plotters::style::FontError> {
    #[cfg(target_arch = "wasm32")]
    {
        Ok(from_table(font.get_size(), text))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        font.box_size(text)
    }
}

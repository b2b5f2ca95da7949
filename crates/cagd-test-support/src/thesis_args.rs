//! Command-line arguments of the thesis's worked examples, shared by the command-line tests.

/// Primer 2.4's control points b0..b3 as columns.
pub const PRIMER_2_4: &str = "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'";

/// The 3×3 control net of the Bézier patch example, packed as ploskevB takes it.
pub const NET_3X3: &str = "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]";

/// Primer 4.3's boundary curves of the Coons patch.
pub const PRIMER_4_3: [&str; 8] = [
    "--c1",
    "[u;0;u-u^2]",
    "--c2",
    "[u;1;u]",
    "--d1",
    "[0;v^2;v-v^2]",
    "--d2",
    "[1;v;v]",
];

/// Appendix D's curve network of the Gordon surface.
pub const GORDON_D: [&str; 12] = [
    "--v-curve",
    "[u;0;u-u^2]",
    "--v-curve",
    "[u;0.5;0.5+u-u^2]",
    "--v-curve",
    "[u;1;1+u-u^2]",
    "--u-curve",
    "[0;v;v]",
    "--u-curve",
    "[0.5;v;0.25+v]",
    "--u-curve",
    "[1;v;v]",
];

/// The boundary of the unit square in the plane z = 0.
pub const FLAT_SQUARE: [&str; 8] = [
    "--c1", "[u;0;0]", "--c2", "[u;1;0]", "--d1", "[0;v;0]", "--d2", "[1;v;0]",
];

/// The cross-boundary derivatives of the flat unit square.
pub const FLAT_SQUARE_CROSS: [&str; 8] = [
    "--c1v", "[0;1;0]", "--c2v", "[0;1;0]", "--d1u", "[1;0;0]", "--d2u", "[1;0;0]",
];

/// `head` followed by `tail`.
pub fn with<'a>(head: &[&'a str], tail: &[&'a str]) -> Vec<&'a str> {
    head.iter().chain(tail).copied().collect()
}

//! The whole command line, in-process, at the default limits: a subcommand chosen by the first
//! byte, then arguments split from the rest of the input at NUL bytes. Options come from a
//! vocabulary (so that the fuzzer reaches the constructions rather than clap's parser) or are
//! taken verbatim.
//!
//! `cagd_cli::run` stages files in memory and never writes; the target runs in an empty
//! folder and drops arguments that would read standard input or absolute/parent paths, so
//! nothing outside the folder is read either.
#![no_main]

use libfuzzer_sys::fuzz_target;

/// Every subcommand that computes from its arguments (not `thesis`, which takes none, nor
/// `serve`). New ones are appended, so that the seeds' first bytes keep their meaning.
const SUBCOMMANDS: &[&str] = &[
    "decasteljau",
    "bezier-patch",
    "coons",
    "coons-bicubic",
    "discrete-coons",
    "gordon",
    "lagrange",
    "bernstein",
    "derivative",
    "spline",
    "hermite",
    "bspline",
    "nurbs",
    "curve",
    "surface",
    "script",
    "convert",
    "elevate",
    "subdivide",
    "insert-knot",
    "bspline-basis",
    "continuity",
    "integrate",
    "ruled",
    "ferguson",
    "bspline-surface",
    "nurbs-surface",
    "circle",
    "arc",
    "course",
    "curvature",
];

/// Every option of the subcommands above, except the limits (`--max-…`, which the target
/// keeps at their defaults) and the folders of `course` and `serve`.
const OPTIONS: &[&str] = &[
    "--t",
    "--u",
    "--v",
    "--n",
    "--steps",
    "--exact",
    "--rows",
    "--format",
    "--c1",
    "--c2",
    "--d1",
    "--d2",
    "--c1v",
    "--c2v",
    "--d1u",
    "--d2u",
    "--twist",
    "--twists",
    "--mask",
    "--u-curve",
    "--v-curve",
    "--u-nodes",
    "--v-nodes",
    "--nodes",
    "--points",
    "--degree",
    "--i",
    "--order",
    "--end",
    "--start-tangent",
    "--end-tangent",
    "--p0",
    "--p1",
    "--t0",
    "--t1",
    "--knots",
    "--weights",
    "-o",
    "--plot",
    "--mesh",
    "--script",
    "--bernstein",
    "--blend",
    "--by",
    "--center",
    "--coefficients",
    "--digits",
    "--du",
    "--dv",
    "--first",
    "--second",
    "--free-point",
    "--from",
    "--to",
    "--insert",
    "--interval",
    "--k",
    "--linear",
    "--list",
    "--params",
    "--radius",
    "--samples",
    "--start",
    "--uknots",
    "--vknots",
    "--x",
    "--y",
    "--z",
    "--columns",
    "-r",
    "--lang",
];

/// Typical values, and values at the edges: near the range of doubles, subnormal, deep
/// nesting, non-finite.
const VALUES: &[&str] = &[
    "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'",
    "[u;0;u-u^2]",
    "[u;1;u]",
    "[0;v^2;v-v^2]",
    "[1;v;v]",
    "0.5",
    "0:0.25:1",
    "3",
    "json",
    "octave",
    "csv",
    "out.svg",
    "out.png",
    "out.stl",
    "out.obj",
    "out.txt",
    "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]",
    "clamped",
    "natural",
    "gregory",
    "[0 0 0 1 2 3 3 3]",
    "[0 0 0 0.5 1 1 1]",
    "[1 2 1]",
    "hermite",
    "bezier",
    "bspline",
    "monomial",
    "[0 0; 1 2; 3 2; 4 0]",
    "[1 -1]",
    "pi/2",
    "2",
    "1e308",
    "-1.7e308",
    "5e-324",
    "[1e308 -1e308; 0 1]",
    "[0 1e-310 1]",
    "((((((((((((((((1))))))))))))))))",
    "NaN",
    "-Inf",
];

fn init() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let dir = std::env::temp_dir().join(format!("cagd-fuzz-cli-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("scratch folder");
        std::env::set_current_dir(&dir).expect("enter scratch folder");
        // The vocabulary is kept in its own order (the seeds' first bytes index it), so check
        // here that it has every subcommand the command line has: a new one must be added.
        for sub in cagd_cli::subcommands() {
            assert!(
                SUBCOMMANDS.contains(&sub.as_str()) || sub == "thesis" || sub == "serve",
                "the cli fuzz target does not know the subcommand {sub}: append it to SUBCOMMANDS"
            );
        }
        // The default limits, as a user gets them: none from the environment, and `--max-…`
        // arguments are dropped below.
        for (_, var, _) in cagd_cli::limits::SETTINGS {
            std::env::remove_var(var);
        }
    });
}

fuzz_target!(|data: &[u8]| {
    init();
    let Some((&choice, rest)) = data.split_first() else {
        return;
    };
    let mut args = vec![
        "cagd".to_string(),
        SUBCOMMANDS[choice as usize % SUBCOMMANDS.len()].to_string(),
    ];
    for piece in rest.split(|&b| b == 0) {
        let arg = match piece {
            // One control byte 0x03..=0x1F, or 0x02 then any byte: an option; 0x01 then any
            // byte: a value.
            [b] if (3..0x20).contains(b) => OPTIONS[*b as usize % OPTIONS.len()].to_string(),
            [2, b] => OPTIONS[*b as usize % OPTIONS.len()].to_string(),
            [1, b] => VALUES[*b as usize % VALUES.len()].to_string(),
            _ => match std::str::from_utf8(piece) {
                Ok(s) => s.to_string(),
                Err(_) => return,
            },
        };
        let reads_outside = arg == "-"
            || arg.starts_with("--max-")
            || arg.starts_with('/')
            || arg.contains("..")
            || arg.starts_with('~')
            || arg.contains("/dev")
            || arg.contains("/proc");
        if reads_outside || args.len() > 40 {
            return;
        }
        args.push(arg);
    }
    let _ = cagd_cli::run(&args);
});

//! Appendix D's packed network has one reading: `cagd gordon --script` and
//! `cagd_octave::compat::krpa_gordon` unpack it through the same `PackedNetwork`, so the same
//! data give the same Gordon surface — also when a node is not a sample parameter (the thesis's
//! own data: nodes `[0 0.5 1]`, `N = 10`), where the crossing is added to the curve.

use cagd_octave::compat::krpa_gordon;
use cagd_octave::literal::Env;
use cagd_octave::script::run;
use nalgebra::DMatrix;
use ndarray::Array2;

/// The `(i, j, x, y, z)` rows of `cagd gordon --script FILE --format csv`, run in process.
fn cli_grid(script: &str) -> Vec<(usize, usize, [f64; 3])> {
    let path = cagd_test_support::data_file(script);
    let path = path.to_str().unwrap();
    let out = cagd_cli::run(["cagd", "gordon", "--script", path, "--format", "csv"])
        .unwrap_or_else(|e| panic!("cagd gordon --script {script}: {e}"));
    let result = out.stdout.split("# result\n").nth(1).expect("a result");
    result
        .lines()
        .take_while(|l| !l.is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            let num = |k: usize| f[k].parse::<f64>().unwrap();
            (
                f[0].parse().unwrap(),
                f[1].parse().unwrap(),
                [num(2), num(3), num(4)],
            )
        })
        .collect()
}

fn array(m: &DMatrix<f64>) -> Array2<f64> {
    Array2::from_shape_fn((m.nrows(), m.ncols()), |(i, j)| m[(i, j)])
}

/// The same script read by the Octave layer and given to `krpa_gordon` with `N` samples.
fn twin_grid(script: &str, n: usize) -> ndarray::Array3<f64> {
    let text = std::fs::read_to_string(cagd_test_support::data_file(script)).unwrap();
    let s = run::<f64>(&text, Env::new()).unwrap();
    let m = |name: &str| array(s.value(name).unwrap());
    let x = m("x");
    krpa_gordon(
        m("g_u").view(),
        m("g_v").view(),
        m("g_uv").view(),
        x.view(),
        x.view(),
        n,
    )
    .unwrap()
    .p
}

fn same_surface(script: &str, n: usize) {
    let cli = cli_grid(script);
    let twin = twin_grid(script, n);
    assert_eq!(
        cli.len(),
        n * n,
        "{script}: the default grid is the N × N samples"
    );
    let t = cagd::linspace(0.0, 1.0, n);
    for (i, j, p) in cli {
        for (c, value) in p.iter().enumerate() {
            let other = twin[[i - 1, j - 1, c]];
            assert_eq!(
                value.to_bits(),
                other.to_bits(),
                "{script} ({i},{j},{c}): cagd gordon {value:e}, krpa_gordon {other:e}"
            );
        }
        // Both are the surface the network lies on, (u, v, v + u − u²), on the samples.
        let (u, v) = (t[i - 1], t[j - 1]);
        let want = [u, v, v + u - u * u];
        for c in 0..3 {
            assert!((p[c] - want[c]).abs() < 1e-14, "{script} ({i},{j},{c})");
        }
    }
}

#[test]
fn nodes_among_the_samples_give_the_same_surface() {
    // N = 11: 0, 0.5 and 1 are all in linspace(0, 1, 11).
    same_surface("appendix_d_odd.m", 11);
}

#[test]
fn nodes_off_the_samples_give_the_same_surface() {
    // N = 10: 0.5 is not in linspace(0, 1, 10); both add the crossings at 0.5.
    same_surface("appendix_d.m", 10);
}

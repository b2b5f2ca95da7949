//! Thesis data scripts: any text runs to a script or a typed error, in f64 and exactly; every
//! parameter expression it defines can be sampled.
#![no_main]

use cagd::octave::literal::Env;
use cagd::octave::script::{run, Binding};
use libfuzzer_sys::fuzz_target;

/// Fuzzing runs with smaller limits than the defaults (10⁴ elements instead of 4·10⁶): the
/// instrumented build is 10–50 times slower, and at the default sizes linear work (an exact
/// range of a million elements) would pass the 10-second timeout without being a bug. The
/// limits themselves are what is exercised.
fn small_limits() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        cagd::limits::Limits {
            max_elements: 10_000,
            max_iterations: 10_000,
            max_samples: 1_000,
            max_grid_points: 10_000,
            max_work: 5_000_000,
            max_system_entries: 100_000,
            ..cagd::limits::Limits::default()
        }
        .set_current();
    });
}

use num_rational::BigRational;

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut env = Env::<f64>::new();
    env.bind_scalar("N", 4.0);
    if let Ok(script) = run::<f64>(text, env) {
        for name in script.names() {
            if let Some(Binding::Function(f)) = script.get(name) {
                let mut env = script.env().clone();
                let _ = f.sample_curve(&mut env, "u", &[0.0, 1.0]);
                let _ = f.sample_surface(&mut env, &[0.5], &[0.5]);
            }
        }
        let _ = script.resolve("c1");
    }
    let mut exact = Env::<BigRational>::new();
    exact.bind_scalar("N", BigRational::from_integer(4.into()));
    let _ = run::<BigRational>(text, exact);
});

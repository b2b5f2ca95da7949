//! Thesis data scripts: any text runs to a script or a typed error, in f64 and exactly; every
//! parameter expression it defines can be sampled.
#![no_main]

mod common;
use common::fuzz_limits;

use cagd_octave::literal::Env;
use cagd_octave::script::{run, Binding};
use libfuzzer_sys::fuzz_target;

use num_rational::BigRational;

fuzz_target!(|data: &[u8]| {
    let limits = fuzz_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut env = Env::<f64>::with_limits(limits);
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
    let mut exact = Env::<BigRational>::with_limits(limits);
    exact.bind_scalar("N", BigRational::from_integer(4.into()));
    let _ = run::<BigRational>(text, exact);
});

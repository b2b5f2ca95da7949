//! The web page's WebAssembly (`web/`, built by `bash web/build.sh`).
//!
//! Two kinds of export, both computing with the same library code as the `cagd` program:
//! - [`run`]: a whole command line through [`cagd_cli::run`], answering what the program
//!   would print and the files it would write (pictures as SVG), staged in memory;
//! - the interactive views' constructions ([`bezier_view`], [`coons_view`], [`bspline_view`],
//!   [`nurbs_view`]): the operation layer's requests on the views' small inputs, cheap enough to
//!   repeat on every frame of a drag, their messages naming each argument by its role's key
//!   (the page shows it under the label of the view's field);
//! - what the page builds itself from ([`schema`]: every subcommand's arguments, for the forms,
//!   with their Slovenian and Czech labels; [`step_tables`]: the labels of the steps in
//!   English, Slovenian and Czech; both read once by `web/build.sh` into `pkg/tables.json`,
//!   which the page fetches while the .wasm compiles) and [`message_in`]: a message in
//!   Slovenian or Czech.
//!
//! Everything is plain Rust that also builds natively (`cargo test -p cagd-web` checks the
//! answers); `#[wasm_bindgen]` turns the functions into JavaScript exports when the target is
//! `wasm32-unknown-unknown`. Answers are JSON text (or `Float64Array`s for grids), errors the
//! command line's one-line message `cagd: error: ARG: PROBLEM; expected FORM`.

mod command;
mod coons_view;
pub mod messages;
mod ops;
mod tables;
mod views;

pub use command::{file_bytes, run};
pub use coons_view::coons_view;
pub use messages::message_in;
pub use tables::{schema, step_tables};
pub use views::{bezier_view, bspline_view, nurbs_view};

/// Installs the panic hook: a fault is reported to the page (`globalThis.cagdPanic`) as the
/// program reports it, `cagd: internal error: …; this is a bug in cagd`, before the
/// WebAssembly traps.
#[cfg(target_arch = "wasm32")]
#[wasm_bindgen::prelude::wasm_bindgen(start)]
pub fn start() {
    use wasm_bindgen::prelude::wasm_bindgen;

    #[wasm_bindgen]
    extern "C" {
        #[wasm_bindgen(js_namespace = globalThis, js_name = cagdPanic)]
        fn report_panic(message: &str);
    }

    std::panic::set_hook(Box::new(|info| {
        report_panic(&cagd_cli::faults::fault_line(info));
    }));
}

//! `cagd script`: runs a thesis-style Octave data script and prints the variables it defines.
//! No construction: the script is the Octave layer's (`cagd_octave::script`), its work
//! bounded by its own budget; this file lays its variables out.

use cagd_octave::literal::LiteralScalar;
use cagd_octave::script::{Binding, Script};
use clap::Args;

use super::common::finish;
use super::cx::Cx;
use super::run::{Names, Run};
use crate::args::{OutputArgs, ScriptArgs};
use crate::{CliError, ErrorKind, Outcome, PendingWrites, Report, Value};

/// Run a thesis-style Octave data script and print the variables it defines.
#[derive(Debug, Args)]
#[command(after_help = "\
Scripts may contain assignments, indexed assignments x(i) = ..., for loops, comments and
continuations. Right-hand sides that use u, v or t without defining them are kept as curves
in that parameter (appendix C: c1 = [u;0;u-u^2]).

Examples:
  cagd script data.m --n 10
  cagd script data.m --format json")]
pub struct ScriptCommand {
    /// The Octave data script, or - for standard input.
    #[arg(value_name = "FILE")]
    pub file: String,
    /// Bind N (used by the thesis scripts, e.g. u = linspace(0,1,N)) before running.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub n: Option<usize>,
    #[command(flatten)]
    pub output: OutputArgs,
}

impl Run for ScriptCommand {
    fn exact(&self) -> bool {
        self.output.exact
    }

    fn run<T: LiteralScalar>(&self, cx: &mut Cx) -> Result<Outcome, CliError> {
        let args = ScriptArgs {
            script: Some(self.file.clone()),
        };
        let loaded = cx.script::<T>(&args, self.n)?.ok_or_else(|| {
            CliError::new("FILE", "no script", "a script file", ErrorKind::Internal)
        })?;
        let warnings = loaded
            .warnings()
            .into_iter()
            .map(|w| (self.file.clone(), w))
            .collect();
        finish(
            &variables(&loaded),
            &self.output,
            PendingWrites::new(),
            warnings,
            &Names {
                input: "FILE",
                special: &[],
            },
        )
    }
}

/// The script's variables in order: values as matrices, curves as their text.
fn variables<T: LiteralScalar>(loaded: &Script<T>) -> Report<T> {
    let mut report = Report::new();
    for name in loaded.names() {
        match loaded.get(name) {
            Some(Binding::Value(m)) => {
                report.push(name, Value::Matrix(m.clone()));
            }
            Some(Binding::Function(f)) => {
                let params = f.parameters(loaded.env());
                report.push(
                    name,
                    Value::Text(format!(
                        "{}    (expression in {})",
                        f.source(),
                        params.join(", ")
                    )),
                );
            }
            None => {}
        }
    }
    report
}

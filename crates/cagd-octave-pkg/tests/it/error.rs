//! Errors: their Octave identifiers, the library's own words, and the limits by name.

use cagd::limits::Limit;
use cagd_octave_pkg::error::limit_by_name;
use cagd_octave_pkg::{Kind, PkgError};

#[test]
fn identifiers_and_library_messages() {
    let e: PkgError = cagd::Error::DerivativeOrder {
        order: 4,
        degree: 3,
    }
    .into();
    assert_eq!(e.identifier(), "cagd:value");
    assert_eq!(e.message, "derivative order 4 exceeds the degree 3");
    let e: PkgError = cagd::Error::TooLarge {
        what: "N",
        requested: 20,
        limit: 10,
        which: Limit::Samples,
    }
    .into();
    assert_eq!(e.identifier(), "cagd:limit");
    assert!(
        e.message.contains("cagd_limits (\"max_samples\", VALUE)"),
        "{e}"
    );
    let names: std::collections::HashSet<_> = Kind::ALL.iter().map(|k| k.name()).collect();
    assert_eq!(names.len(), Kind::ALL.len());
    assert_eq!(limit_by_name("max_degree"), Some(Limit::Degree));
    assert_eq!(limit_by_name("degree"), None);
}

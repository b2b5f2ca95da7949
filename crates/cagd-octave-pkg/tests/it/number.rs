//! Exact inputs are read as a person typed them: a double as the shortest decimal that gives
//! it back.

use cagd_octave_pkg::number::Number;
use num_rational::BigRational;
use num_traits::FromPrimitive;

#[test]
fn decimals_are_read_as_typed() {
    assert_eq!(
        BigRational::from_input(0.2),
        BigRational::new(1.into(), 5.into())
    );
    assert_eq!(
        BigRational::from_input(-3.25e-7),
        BigRational::new((-325).into(), 1_000_000_000.into())
    );
    let big = BigRational::from_input(1e300);
    assert_eq!(big, BigRational::from_u8(10).unwrap().pow(300));
    assert_ne!(big, BigRational::from_f64(1e300).unwrap());
    assert_eq!(
        BigRational::from_input(0.0),
        BigRational::from_u8(0).unwrap()
    );
}

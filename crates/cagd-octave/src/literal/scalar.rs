//! The numbers a literal evaluates to: [`LiteralScalar`] (`f64` with Octave's semantics, or
//! exact `BigRational`), and the element-wise [`Function`]s.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use cagd::scalar::{rational_from_decimal, Scalar};

use super::range;

/// A function applied element-wise.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Function {
    /// `sin`
    Sin,
    /// `cos`
    Cos,
    /// `tan`
    Tan,
    /// `sqrt`
    Sqrt,
    /// `exp`
    Exp,
    /// `log` (natural)
    Log,
    /// `abs`
    Abs,
}

impl Function {
    /// The function of that Octave name.
    pub fn from_name(name: &str) -> Option<Function> {
        Some(match name {
            "sin" => Function::Sin,
            "cos" => Function::Cos,
            "tan" => Function::Tan,
            "sqrt" => Function::Sqrt,
            "exp" => Function::Exp,
            "log" => Function::Log,
            "abs" => Function::Abs,
            _ => return None,
        })
    }

    /// The Octave name.
    pub fn name(self) -> &'static str {
        match self {
            Function::Sin => "sin",
            Function::Cos => "cos",
            Function::Tan => "tan",
            Function::Sqrt => "sqrt",
            Function::Exp => "exp",
            Function::Log => "log",
            Function::Abs => "abs",
        }
    }
}

/// Why a power has no value in the scalar type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PowerError {
    /// No exact rational value (non-integer exponent).
    NotRational,
    /// Zero to a negative power.
    DivisionByZero,
    /// The exact result would be unreasonably large.
    TooLarge,
}

/// A number type the evaluator works in: `f64` (as Octave) or [`BigRational`] (exact).
pub trait LiteralScalar: Scalar {
    /// Whether an exact number has grown too large to compute with in reasonable time
    /// (numerator and denominator together longer than [`MAX_EXACT_BITS`]); never for `f64`.
    fn is_oversized(&self) -> bool {
        false
    }

    /// The length of the number in 64-bit words (numerator and denominator together, at least
    /// 1; always 1 for `f64`). An exact operation on operands of `a` and `b` words is
    /// charged `32 (a + b)²` element operations against an evaluation's work limit — the
    /// binary gcd that reduces every exact result is quadratic in the length (found by fuzzing: a short expression on
    /// 1000-bit rationals over a range of a few hundred elements took a third of a second
    /// while charged as a few thousand operations).
    fn words(&self) -> u128 {
        1
    }

    /// The value of a decimal literal (`text` as lexed; `nearest` its nearest double).
    /// `None` if it is not finite in this type.
    fn from_literal(text: &str, nearest: f64) -> Option<Self>;

    /// `f(x)`, or `None` where the value is not representable (any transcendental function
    /// in exact arithmetic). Non-finite `f64` results are returned and rejected by the caller.
    fn apply(f: Function, x: &Self) -> Option<Self>;

    /// `pi` or `e`; `None` in exact arithmetic.
    fn constant(name: &str) -> Option<Self>;

    /// `base ^ exponent` for scalars, as Octave's `xpow(double, double)` (`std::pow`).
    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError>;

    /// `base .^ exponent` for one element of a non-scalar array. Octave's `elem_xpow`
    /// computes `x.^2` as `x*x`, `x.^3` as `x*x*x` and `x.^-1` as `1/x`, which may differ in
    /// the last bit from `pow`; the default is [`LiteralScalar::pow`].
    fn pow_in_array(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Self::pow(base, exponent)
    }

    /// `a / b`, or `None` for an exact division by zero (`f64` returns ±∞ or NaN, rejected by
    /// the caller).
    fn checked_div(a: &Self, b: &Self) -> Option<Self>;

    /// The value as a non-negative integer count or index, if it is one.
    fn to_count(&self) -> Option<usize>;

    /// `linspace(a, b, n)`: Octave's doubles ([`cagd::linspace()`]) for `f64`; exact
    /// `a + i(b−a)/(n−1)` for rationals.
    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self>;

    /// The range `base:increment:limit` (Octave's elements for `f64`, exact for rationals);
    /// `Err(count)` if it would have more than `max` elements.
    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128>;
}

impl LiteralScalar for f64 {
    fn from_literal(_text: &str, nearest: f64) -> Option<Self> {
        nearest.is_finite().then_some(nearest)
    }

    fn apply(f: Function, x: &Self) -> Option<Self> {
        Some(match f {
            Function::Sin => x.sin(),
            Function::Cos => x.cos(),
            Function::Tan => x.tan(),
            Function::Sqrt => x.sqrt(),
            Function::Exp => x.exp(),
            Function::Log => x.ln(),
            Function::Abs => x.abs(),
        })
    }

    fn constant(name: &str) -> Option<Self> {
        match name {
            "pi" => Some(std::f64::consts::PI),
            "e" => Some(std::f64::consts::E),
            _ => None,
        }
    }

    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Ok(base.powf(*exponent))
    }

    fn pow_in_array(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        Ok(match *exponent {
            2.0 => base * base,
            3.0 => base * base * base,
            -1.0 => 1.0 / base,
            _ => base.powf(*exponent),
        })
    }

    fn checked_div(a: &Self, b: &Self) -> Option<Self> {
        Some(a / b)
    }

    fn to_count(&self) -> Option<usize> {
        (*self >= 0.0 && self.fract() == 0.0 && *self < 9.0e15).then_some(*self as usize)
    }

    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self> {
        cagd::linspace(*a, *b, n)
    }

    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128> {
        range::octave_range(*base, *increment, *limit, max)
            .map_err(|range::RangeError::TooLarge(n)| n)
    }
}

/// Largest size, in bits, of an exact number's numerator plus denominator (about 1 200
/// decimal digits): exact literals and results beyond it are refused
/// ([`LiteralError::NumberOutOfRange`](super::LiteralError::NumberOutOfRange), [`LiteralError::TooLarge`](super::LiteralError::TooLarge)), since every operation on
/// them costs a gcd quadratic in their size (found by fuzzing: `24.445^46913` took minutes,
/// a range stepping by `1e-5828 - 2` took seconds per thousand elements).
pub const MAX_EXACT_BITS: u64 = 1 << 12;

impl LiteralScalar for BigRational {
    fn is_oversized(&self) -> bool {
        self.numer().bits() + self.denom().bits() > MAX_EXACT_BITS
    }

    fn words(&self) -> u128 {
        self.bits().div_ceil(64).max(1)
    }

    fn from_literal(text: &str, _nearest: f64) -> Option<Self> {
        rational_from_decimal(text).filter(|x| !x.is_oversized())
    }

    fn apply(f: Function, x: &Self) -> Option<Self> {
        match f {
            Function::Abs => Some(x.abs()),
            _ => None,
        }
    }

    fn constant(_name: &str) -> Option<Self> {
        None
    }

    fn pow(base: &Self, exponent: &Self) -> Result<Self, PowerError> {
        if !exponent.is_integer() {
            return Err(PowerError::NotRational);
        }
        let n = exponent.to_integer();
        if base.is_zero() {
            return match n.sign() {
                num_bigint::Sign::Minus => Err(PowerError::DivisionByZero),
                num_bigint::Sign::NoSign => Ok(BigRational::one()),
                num_bigint::Sign::Plus => Ok(BigRational::zero()),
            };
        }
        if base.abs().is_one() {
            let odd = n.bit(0);
            return Ok(if base.is_negative() && odd {
                -BigRational::one()
            } else {
                BigRational::one()
            });
        }
        let bits = base.numer().bits() + base.denom().bits();
        let magnitude = n.magnitude().to_u64().unwrap_or(u64::MAX);
        if magnitude.saturating_mul(bits) > MAX_EXACT_BITS {
            return Err(PowerError::TooLarge);
        }
        // Numerator and denominator are coprime, so are their powers: no gcd needed (a gcd
        // at every squaring made large powers quadratic).
        let e = magnitude as u32;
        let p = BigRational::new_raw(
            num_traits::pow(base.numer().clone(), e as usize),
            num_traits::pow(base.denom().clone(), e as usize),
        );
        Ok(if n.is_negative() { p.recip() } else { p })
    }

    fn checked_div(a: &Self, b: &Self) -> Option<Self> {
        (!b.is_zero()).then(|| a / b)
    }

    fn to_count(&self) -> Option<usize> {
        if self.is_integer() && !self.is_negative() {
            self.to_integer().to_usize()
        } else {
            None
        }
    }

    fn linspace(a: &Self, b: &Self, n: usize) -> Vec<Self> {
        match n {
            0 => Vec::new(),
            1 => vec![b.clone()],
            _ => {
                let step = (b - a) / BigRational::from_integer(BigInt::from(n - 1));
                let mut out: Vec<Self> = (0..n)
                    .map(|i| a + &step * BigRational::from_integer(BigInt::from(i)))
                    .collect();
                out[n - 1] = b.clone();
                out
            }
        }
    }

    fn range(base: &Self, increment: &Self, limit: &Self, max: usize) -> Result<Vec<Self>, u128> {
        range::exact_range(base, increment, limit, max).map_err(|range::RangeError::TooLarge(n)| n)
    }
}

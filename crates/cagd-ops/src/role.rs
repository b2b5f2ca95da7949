//! The roles an argument plays in a construction: the operation layer's name for it, which
//! each front end maps to its own (`--knots` on the command line, `U` in Octave, the field
//! "knots" on the page, the keyword `knots` in Python).

/// What an argument is to a construction.
///
/// Messages are worded once, about the role ([`crate::OpError::role`]); a front end prefixes
/// its own name for the argument that carried the role.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Role {
    /// Control points of a curve (`d × (n+1)`, one point per column).
    Control,
    /// A control net of a patch.
    Net,
    /// A degree `p`.
    Degree,
    /// A B-spline order `k = p + 1`.
    Order,
    /// A knot vector.
    Knots,
    /// The knot vector of a surface along `u`.
    UKnots,
    /// The knot vector of a surface along `v`.
    VKnots,
    /// NURBS weights.
    Weights,
    /// The parameter interval `[a, b]` of a curve.
    Interval,
    /// Curve parameters `t`.
    T,
    /// Surface parameters `u`.
    U,
    /// Surface parameters `v`.
    V,
    /// The grid `u × v` as a whole (its size, the work of evaluating on it).
    Grid,
    /// A number of equally spaced samples (the thesis's `N`).
    Samples,
    /// The order of a derivative (of a curve, or `∂/∂u` of a patch).
    DerivativeOrder,
    /// The order of a patch derivative in `v`.
    DerivativeV,
    /// Interpolation nodes.
    Nodes,
    /// Data points (interpolated values, a spline's points).
    Points,
    /// The end conditions of a spline.
    Ends,
    /// Boundary curve `x(u, 0)`.
    C1,
    /// Boundary curve `x(u, 1)`.
    C2,
    /// Boundary curve `x(0, v)`.
    D1,
    /// Boundary curve `x(1, v)`.
    D2,
    /// The four boundary curves together (where they meet).
    Boundary,
    /// Cross-boundary derivative `x_v(u, 0)`.
    C1v,
    /// Cross-boundary derivative `x_v(u, 1)`.
    C2v,
    /// Cross-boundary derivative `x_u(0, v)`.
    D1u,
    /// Cross-boundary derivative `x_u(1, v)`.
    D2u,
    /// The twist choice of a bicubic Coons patch.
    Twist,
    /// Given corner twists.
    Twists,
    /// Blending functions.
    Blend,
    /// A discrete Coons mask `(α, β)`.
    Mask,
    /// The curves `g(u_i, v)` of a Gordon network (in `v`).
    UCurves,
    /// The curves `g(u, v_j)` of a Gordon network (in `u`).
    VCurves,
    /// The nodes `u_i` of a Gordon network.
    UNodes,
    /// The nodes `v_j` of a Gordon network.
    VNodes,
    /// A Gordon network as a whole (where its curves cross, the work of setting it up).
    Network,
    /// The four cross-boundary derivatives of a bicubic Coons patch together (where they meet
    /// the boundary's tangents).
    Cross,
    /// Tangents `∂x/∂u` at the corners of a patch.
    Du,
    /// Tangents `∂x/∂v` at the corners of a patch.
    Dv,
    /// The steps asked for (the parts of a construction).
    Steps,
    /// The first curve (or point) of a pair.
    First,
    /// The second curve (or point) of a pair.
    Second,
    /// Hermite data: the start point.
    P0,
    /// Hermite data: the end point.
    P1,
    /// Hermite data: the start tangent.
    T0,
    /// Hermite data: the end tangent.
    T1,
    /// Hermite data together (`p0`, `p1`, `t0`, `t1`: where they must agree).
    Hermite,
    /// A representation converted from.
    From,
    /// A representation converted to.
    To,
    /// A number of degree elevations.
    By,
    /// A knot to insert, or a parameter to split at.
    At,
    /// A radius.
    Radius,
    /// A centre.
    Center,
    /// Start and end angles.
    Angles,
    /// A tolerance.
    Tolerance,
    /// An index into a family (`i` of the Bernstein polynomial `B_i^n`).
    Index,
    /// A B-spline curve as a whole: its control points, degree and knots together (whose
    /// counts must fit).
    Spline,
    /// A factor (`k` of `x'(1) = k · ¹x'(0)`).
    Factor,
    /// The joint of two curves (both together).
    Joint,
    /// The result (a value that overflows, say).
    Result,
}

/// Defines [`Role::key`] from one line per role (`Role => "key"`): a role without its key does
/// not compile, as with a `match` written out.
macro_rules! keys {
    ($($role:ident => $key:literal,)*) => {
        impl Role {
            /// The role's key, as the page and Python name the argument (`"knots"`, `"c1v"`).
            ///
            /// ```
            /// assert_eq!(cagd_ops::Role::Knots.key(), "knots");
            /// assert_eq!(cagd_ops::Role::UCurves.key(), "u_curves");
            /// ```
            pub fn key(self) -> &'static str {
                match self {
                    $(Role::$role => $key,)*
                }
            }
        }
    };
}

keys! {
    Control => "control",
    Net => "net",
    Degree => "degree",
    Order => "order",
    Knots => "knots",
    UKnots => "u_knots",
    VKnots => "v_knots",
    Weights => "weights",
    Interval => "interval",
    T => "t",
    U => "u",
    V => "v",
    Grid => "grid",
    Samples => "n",
    DerivativeOrder => "derivative",
    DerivativeV => "dv",
    Nodes => "nodes",
    Points => "points",
    Ends => "ends",
    C1 => "c1",
    C2 => "c2",
    D1 => "d1",
    D2 => "d2",
    Boundary => "boundary",
    C1v => "c1v",
    C2v => "c2v",
    D1u => "d1u",
    D2u => "d2u",
    Twist => "twist",
    Twists => "twists",
    Blend => "blend",
    Mask => "mask",
    UCurves => "u_curves",
    VCurves => "v_curves",
    UNodes => "u_nodes",
    VNodes => "v_nodes",
    Network => "network",
    Cross => "cross",
    Du => "tangents_u",
    Dv => "tangents_v",
    Steps => "steps",
    First => "first",
    Second => "second",
    P0 => "p0",
    P1 => "p1",
    T0 => "t0",
    T1 => "t1",
    Hermite => "hermite",
    From => "from",
    To => "to",
    By => "by",
    At => "at",
    Radius => "radius",
    Center => "center",
    Angles => "angles",
    Tolerance => "tolerance",
    Index => "i",
    Spline => "spline",
    Factor => "k",
    Joint => "joint",
    Result => "result",
}

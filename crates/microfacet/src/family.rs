//! [`AnyNdf`]: one value that holds any NDF of the family, selected by name at run time
//! (command line, JSON, sweeps). Static dispatch through a `match`; no trait objects.

use crate::error::ParamError;
use crate::ndf::{Ndf, ShapeInvariant};
use crate::{Beckmann, DoubleGgx, Exponential, Ggx, Gtr};
use std::fmt;
use std::str::FromStr;

/// The NDFs of the family, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NdfKind {
    Beckmann,
    Ggx,
    Gtr,
    DoubleGgx,
    Exponential,
}

impl NdfKind {
    /// Every kind, in the order of the source pages (Beckmann first: the base).
    pub const ALL: [NdfKind; 5] = [
        NdfKind::Beckmann,
        NdfKind::Ggx,
        NdfKind::Gtr,
        NdfKind::DoubleGgx,
        NdfKind::Exponential,
    ];

    /// The lower-case name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            NdfKind::Beckmann => "beckmann",
            NdfKind::Ggx => "ggx",
            NdfKind::Gtr => "gtr",
            NdfKind::DoubleGgx => "double_ggx",
            NdfKind::Exponential => "exponential",
        }
    }
}

impl fmt::Display for NdfKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown NDF name.
#[derive(Clone, Debug, PartialEq)]
pub struct UnknownNdf(pub String);

impl fmt::Display for UnknownNdf {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // At most 60 characters of the name are echoed (a 1 MB name is not).
        let name = match self.0.char_indices().nth(60) {
            Some((i, _)) => format!("{}…", &self.0[..i]),
            None => self.0.clone(),
        };
        write!(
            f,
            "unknown ndf '{name}' (expected one of beckmann, ggx, gtr, double_ggx, exponential)"
        )
    }
}

impl std::error::Error for UnknownNdf {}

impl FromStr for NdfKind {
    type Err = UnknownNdf;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        NdfKind::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| UnknownNdf(s.to_string()))
    }
}

/// Any NDF of the family.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AnyNdf {
    Beckmann(Beckmann),
    Ggx(Ggx),
    Gtr(Gtr),
    DoubleGgx(DoubleGgx),
    Exponential(Exponential),
}

impl AnyNdf {
    /// Builds `kind` with roughness α; γ is required by (and only used for) GTR.
    pub fn new(kind: NdfKind, alpha: f64, gamma: Option<f64>) -> Result<Self, ParamError> {
        Ok(match kind {
            NdfKind::Beckmann => AnyNdf::Beckmann(Beckmann::new(alpha)?),
            NdfKind::Ggx => AnyNdf::Ggx(Ggx::new(alpha)?),
            NdfKind::Gtr => AnyNdf::Gtr(Gtr::new(alpha, gamma.unwrap_or(f64::NAN))?),
            NdfKind::DoubleGgx => AnyNdf::DoubleGgx(DoubleGgx::new(alpha)?),
            NdfKind::Exponential => AnyNdf::Exponential(Exponential::new(alpha)?),
        })
    }

    /// Which NDF this is.
    pub fn kind(&self) -> NdfKind {
        match self {
            AnyNdf::Beckmann(_) => NdfKind::Beckmann,
            AnyNdf::Ggx(_) => NdfKind::Ggx,
            AnyNdf::Gtr(_) => NdfKind::Gtr,
            AnyNdf::DoubleGgx(_) => NdfKind::DoubleGgx,
            AnyNdf::Exponential(_) => NdfKind::Exponential,
        }
    }

    /// γ for GTR, `None` otherwise.
    pub fn gamma(&self) -> Option<f64> {
        match self {
            AnyNdf::Gtr(g) => Some(g.gamma()),
            _ => None,
        }
    }

    /// The shape-invariant profile f(x), or `None` for GTR (not shape invariant for γ ≠ 2).
    pub fn f(&self, x: f64) -> Option<f64> {
        match self {
            AnyNdf::Beckmann(n) => Some(n.f(x)),
            AnyNdf::Ggx(n) => Some(n.f(x)),
            AnyNdf::Gtr(_) => None,
            AnyNdf::DoubleGgx(n) => Some(n.f(x)),
            AnyNdf::Exponential(n) => Some(n.f(x)),
        }
    }

    fn inner(&self) -> &dyn Ndf {
        match self {
            AnyNdf::Beckmann(n) => n,
            AnyNdf::Ggx(n) => n,
            AnyNdf::Gtr(n) => n,
            AnyNdf::DoubleGgx(n) => n,
            AnyNdf::Exponential(n) => n,
        }
    }
}

impl Ndf for AnyNdf {
    fn name(&self) -> &'static str {
        self.inner().name()
    }
    fn alpha(&self) -> f64 {
        self.inner().alpha()
    }
    fn d_pos(&self, u: f64) -> f64 {
        self.inner().d_pos(u)
    }
    fn p22(&self, p: f64, q: f64) -> f64 {
        self.inner().p22(p, q)
    }
    fn p2(&self, p: f64) -> f64 {
        self.inner().p2(p)
    }
    fn lambda_pos(&self, u: f64) -> f64 {
        self.inner().lambda_pos(u)
    }
    fn sigma_neg(&self, u: f64) -> f64 {
        self.inner().sigma_neg(u)
    }
    fn sigma_zero(&self) -> f64 {
        self.inner().sigma_zero()
    }
}

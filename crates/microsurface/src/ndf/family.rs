//! [`AnyNdf`]: one value that holds any NDF of the family, selected by name at run time
//! (command line, JSON, sweeps). Static dispatch through a `match`; no trait objects.

use crate::error::ParamError;
use crate::ndf::{Ndf, ShapeInvariant};
use crate::{Beckmann, DoubleGgx, Exponential, Ggx, Gtr};
use crate::{BesselK, Ei, Erfc, GenExponential, StudentT, K0};
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
    StudentT,
    Ei,
    Erfc,
    K0,
    BesselK,
    GenExponential,
}

impl NdfKind {
    /// Every kind: [`NdfKind::CLASSIC`] then [`NdfKind::FAMILY`].
    pub const ALL: [NdfKind; 11] = [
        NdfKind::Beckmann,
        NdfKind::Ggx,
        NdfKind::Gtr,
        NdfKind::DoubleGgx,
        NdfKind::Exponential,
        NdfKind::StudentT,
        NdfKind::Ei,
        NdfKind::Erfc,
        NdfKind::K0,
        NdfKind::BesselK,
        NdfKind::GenExponential,
    ];

    /// The five NDFs of the source pages (d'Eon's NDF pages and Burley's appendix), with
    /// shipped compensation tables and report sections, in the order of the pages (Beckmann
    /// first: the base).
    pub const CLASSIC: [NdfKind; 5] = [
        NdfKind::Beckmann,
        NdfKind::Ggx,
        NdfKind::Gtr,
        NdfKind::DoubleGgx,
        NdfKind::Exponential,
    ];

    /// The rest of the book's family: the Beckmann mixtures (fast through
    /// [`crate::Microfacet::with_shape`]) and the generalised exponential (exact only).
    pub const FAMILY: [NdfKind; 6] = [
        NdfKind::StudentT,
        NdfKind::Ei,
        NdfKind::Erfc,
        NdfKind::K0,
        NdfKind::BesselK,
        NdfKind::GenExponential,
    ];

    /// The name of the kind's shape parameter (`gamma`, or `a` for Bessel-K), if it has one.
    pub fn shape_name(self) -> Option<&'static str> {
        match self {
            NdfKind::Gtr | NdfKind::StudentT | NdfKind::GenExponential => Some("gamma"),
            NdfKind::BesselK => Some("a"),
            _ => None,
        }
    }

    /// The lower-case name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            NdfKind::Beckmann => "beckmann",
            NdfKind::Ggx => "ggx",
            NdfKind::Gtr => "gtr",
            NdfKind::DoubleGgx => "double_ggx",
            NdfKind::Exponential => "exponential",
            NdfKind::StudentT => "student_t",
            NdfKind::Ei => "ei",
            NdfKind::Erfc => "erfc",
            NdfKind::K0 => "k0",
            NdfKind::BesselK => "bessel_k",
            NdfKind::GenExponential => "gen_exponential",
        }
    }

    /// The other names [`NdfKind::from_str`](std::str::FromStr) accepts for the kind (after
    /// lower-casing and mapping `-` and spaces to `_`): the names of the literature and of
    /// the peers' scene formats.
    pub fn aliases(self) -> &'static [&'static str] {
        match self {
            NdfKind::Beckmann => &["beckmann_spizzichino", "gaussian"],
            NdfKind::Ggx => &["trowbridge_reitz", "tr"],
            NdfKind::Gtr => &[
                "generalized_trowbridge_reitz",
                "generalised_trowbridge_reitz",
            ],
            NdfKind::DoubleGgx => &["dggx"],
            NdfKind::Exponential => &["exp"],
            NdfKind::StudentT => &["studentt", "student"],
            NdfKind::Ei => &[],
            NdfKind::Erfc => &[],
            NdfKind::K0 => &[],
            NdfKind::BesselK => &["besselk"],
            NdfKind::GenExponential => &["generalized_exponential", "generalised_exponential"],
        }
    }
}

impl fmt::Display for NdfKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The names every NDF answers to, for error messages: each kind's [`NdfKind::name`].
fn valid_names() -> String {
    NdfKind::ALL.map(NdfKind::name).join(", ")
}

/// An unknown NDF name (the message lists the valid ones).
#[derive(Clone, Debug, PartialEq)]
pub struct UnknownNdf(pub String);

/// At most 60 characters of a name are echoed in an error (a 1 MB name is not).
fn clipped(s: &str) -> String {
    match s.char_indices().nth(60) {
        Some((i, _)) => format!("{}…", &s[..i]),
        None => s.to_string(),
    }
}

impl UnknownNdf {
    /// The kind whose name or alias is nearest the unknown name, if one is near enough to be
    /// a misspelling: within an edit distance (Levenshtein, on the name as `from_str` reads
    /// it) of 1 for names up to 4 characters, 2 up to 8, 3 beyond ("beckman" → Beckmann,
    /// "studnet_t" → Student-T; "foo" → none).
    pub fn suggestion(&self) -> Option<NdfKind> {
        let key = normalised(&self.0);
        if key.is_empty() || key.len() > 64 {
            return None;
        }
        let limit = match key.chars().count() {
            0..=4 => 1,
            5..=8 => 2,
            _ => 3,
        };
        NdfKind::ALL
            .into_iter()
            .flat_map(|k| {
                std::iter::once(k.name())
                    .chain(k.aliases().iter().copied())
                    .map(move |n| (k, n))
            })
            .map(|(k, n)| (edit_distance(&key, n), k))
            .filter(|&(d, _)| d <= limit)
            .min_by_key(|&(d, _)| d)
            .map(|(_, k)| k)
    }
}

/// The Levenshtein distance between two short strings (by characters).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// A name as `from_str` compares it: trimmed, lower case, `-` and spaces read as `_`.
fn normalised(s: &str) -> String {
    s.trim()
        .chars()
        .map(|c| match c {
            '-' | ' ' => '_',
            c => c.to_ascii_lowercase(),
        })
        .collect()
}

impl fmt::Display for UnknownNdf {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.suggestion() {
            Some(k) => write!(
                f,
                "unknown ndf '{}': did you mean '{}'? (expected one of {}; case-insensitive)",
                clipped(&self.0),
                k.name(),
                valid_names()
            ),
            None => write!(
                f,
                "unknown ndf '{}' (expected one of {}; case-insensitive)",
                clipped(&self.0),
                valid_names()
            ),
        }
    }
}

impl std::error::Error for UnknownNdf {}

impl FromStr for NdfKind {
    type Err = UnknownNdf;
    /// The kind named `s`: its [`NdfKind::name`] or one of its [`NdfKind::aliases`],
    /// case-insensitive, with `-` and spaces read as `_` (`"GGX"`, `"Student-T"`,
    /// `"Trowbridge_Reitz"`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let key = normalised(s);
        NdfKind::ALL
            .into_iter()
            .find(|k| k.name() == key || k.aliases().contains(&key.as_str()))
            .ok_or_else(|| UnknownNdf(s.to_string()))
    }
}

/// An NDF chosen by name, with its shape parameter: what a scene file or a command line
/// says. Parsed from `"name"` or `"name:shape"` (`"ggx"`, `"GGX"`, `"trowbridge_reitz"`,
/// `"student_t:2.5"`, `"gtr:1.5"`, `"bessel_k:0.7"`): the name as [`NdfKind`]'s
/// `from_str` reads it, the shape a number, required by the kinds that have one
/// ([`NdfKind::shape_name`]) and refused by the others. The shape's range is checked where
/// the material is built ([`crate::AnyMicrofacet::new`], [`AnyNdf::new`]).
///
/// ```
/// use microsurface::{NdfKind, NdfSpec};
/// let spec: NdfSpec = "Student-T:2.5".parse()?;
/// assert_eq!((spec.kind, spec.shape), (NdfKind::StudentT, Some(2.5)));
/// assert_eq!(spec.to_string(), "student_t:2.5");
/// assert!("gtr".parse::<NdfSpec>().is_err()); // GTR needs its γ
/// # Ok::<(), microsurface::SpecError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NdfSpec {
    /// Which NDF.
    pub kind: NdfKind,
    /// Its shape parameter (γ of GTR, Student-T and the generalised exponential, a of
    /// Bessel-K); `None` for the kinds without one.
    pub shape: Option<f64>,
}

impl NdfSpec {
    /// The spec of `kind` with `shape`: `Err` where the kind needs a shape and has none, or
    /// has none and is given one.
    pub fn new(kind: NdfKind, shape: Option<f64>) -> Result<NdfSpec, SpecError> {
        match (kind.shape_name(), shape) {
            (Some(name), None) => Err(SpecError::MissingShape { kind, name }),
            (None, Some(_)) => Err(SpecError::UnexpectedShape(kind)),
            _ => Ok(NdfSpec { kind, shape }),
        }
    }
}

impl fmt::Display for NdfSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.shape {
            Some(s) => write!(f, "{}:{s}", self.kind),
            None => write!(f, "{}", self.kind),
        }
    }
}

impl FromStr for NdfSpec {
    type Err = SpecError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let (name, shape) = match s.split_once(':') {
            Some((name, shape)) => (name, Some(shape)),
            None => (s, None),
        };
        let kind: NdfKind = name.parse().map_err(SpecError::UnknownNdf)?;
        let shape = match shape {
            None => None,
            Some(t) => Some(
                t.trim()
                    .parse::<f64>()
                    .map_err(|_| SpecError::BadShape(clipped(t)))?,
            ),
        };
        NdfSpec::new(kind, shape)
    }
}

/// Why an NDF spec or a material chosen at run time was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum SpecError {
    /// The name is none of the NDFs' (the message lists them).
    UnknownNdf(UnknownNdf),
    /// The text after `:` is not a number.
    BadShape(String),
    /// The kind has a shape parameter (`name`) and none was given.
    MissingShape { kind: NdfKind, name: &'static str },
    /// The kind has no shape parameter and one was given.
    UnexpectedShape(NdfKind),
    /// A parameter outside its range.
    Param(ParamError),
}

impl fmt::Display for SpecError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpecError::UnknownNdf(e) => e.fmt(f),
            SpecError::BadShape(t) => write!(
                f,
                "the shape parameter after ':' must be a number, got '{t}' (e.g. student_t:2.5)"
            ),
            SpecError::MissingShape { kind, name } => write!(
                f,
                "ndf {kind} needs its shape parameter {name} (e.g. {kind}:{})",
                if *kind == NdfKind::BesselK {
                    "0.7"
                } else {
                    "2.5"
                }
            ),
            SpecError::UnexpectedShape(kind) => {
                write!(f, "ndf {kind} has no shape parameter")
            }
            SpecError::Param(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for SpecError {}

impl From<ParamError> for SpecError {
    fn from(e: ParamError) -> Self {
        SpecError::Param(e)
    }
}

impl From<UnknownNdf> for SpecError {
    fn from(e: UnknownNdf) -> Self {
        SpecError::UnknownNdf(e)
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
    StudentT(StudentT),
    Ei(Ei),
    Erfc(Erfc),
    K0(K0),
    BesselK(BesselK),
    GenExponential(GenExponential),
}

impl AnyNdf {
    /// Builds `kind` with roughness α and, for the kinds that have one
    /// ([`NdfKind::shape_name`]), its shape parameter: γ for GTR, Student-T and the generalised
    /// exponential, a for Bessel-K (required by those, ignored by the others).
    pub fn new(kind: NdfKind, alpha: f64, shape: Option<f64>) -> Result<Self, ParamError> {
        let shape = shape.unwrap_or(f64::NAN);
        Ok(match kind {
            NdfKind::Beckmann => AnyNdf::Beckmann(Beckmann::new(alpha)?),
            NdfKind::Ggx => AnyNdf::Ggx(Ggx::new(alpha)?),
            NdfKind::Gtr => AnyNdf::Gtr(Gtr::new(alpha, shape)?),
            NdfKind::DoubleGgx => AnyNdf::DoubleGgx(DoubleGgx::new(alpha)?),
            NdfKind::Exponential => AnyNdf::Exponential(Exponential::new(alpha)?),
            NdfKind::StudentT => AnyNdf::StudentT(StudentT::new(alpha, shape)?),
            NdfKind::Ei => AnyNdf::Ei(Ei::new(alpha)?),
            NdfKind::Erfc => AnyNdf::Erfc(Erfc::new(alpha)?),
            NdfKind::K0 => AnyNdf::K0(K0::new(alpha)?),
            NdfKind::BesselK => AnyNdf::BesselK(BesselK::new(alpha, shape)?),
            NdfKind::GenExponential => AnyNdf::GenExponential(GenExponential::new(alpha, shape)?),
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
            AnyNdf::StudentT(_) => NdfKind::StudentT,
            AnyNdf::Ei(_) => NdfKind::Ei,
            AnyNdf::Erfc(_) => NdfKind::Erfc,
            AnyNdf::K0(_) => NdfKind::K0,
            AnyNdf::BesselK(_) => NdfKind::BesselK,
            AnyNdf::GenExponential(_) => NdfKind::GenExponential,
        }
    }

    /// Whether D is unbounded at the pole: D(1) = P22(0, 0) = +∞ (the true value) for Ei,
    /// Erfc and K0 (logarithmic: P22 ~ −ln r) and Bessel-K with a ≤ 1 (P22 ~ r^{2a−2}, or
    /// −ln r at a = 1); D·cos stays integrable, and every other value is finite.
    pub fn singular_at_pole(&self) -> bool {
        match self {
            AnyNdf::Ei(_) | AnyNdf::Erfc(_) | AnyNdf::K0(_) => true,
            AnyNdf::BesselK(n) => n.a() <= 1.0,
            _ => false,
        }
    }

    /// ln f(x) of the α = 1 profile for x ≥ 1e15 given as ln x, where x itself may overflow:
    /// Student-T's power law, f = ((γ − 1)/(x² + γ − 1))^γ/π → (γ − 1)^γ x^{−2γ}/π (relative
    /// error γ(γ − 1)/x² ≤ 1e-18 at γ ≤ 1e6); `None` for the others, whose f is 0 in f64 there
    /// (exponential tails).
    pub(crate) fn ln_f_far(&self, ln_x: f64) -> Option<f64> {
        match self {
            AnyNdf::StudentT(n) => {
                let g = n.gamma();
                Some(g * (g - 1.0).ln() - 2.0 * g * ln_x - std::f64::consts::PI.ln())
            }
            _ => None,
        }
    }

    /// D of the unit normal wm (z > 0) at roughness (αx, αy) from this α = 1 member, through
    /// the stretched slopes g = (x/(αx z), y/(αy z)): P22₁(g)/(αx αy z⁴); far in the tail, at
    /// X = |g| ≥ 1e15 (where P22₁ turns subnormal before D does, and X or z⁴ may leave the
    /// range), f(X)/(αx αy z⁴) in logarithms from ln X ([`AnyNdf::ln_f_far`]: Student-T's
    /// power law, whose next term γ(γ − 1)/X² ≤ 1e-18 there; 0 for the exponential tails).
    pub(crate) fn d_stretched(&self, wm: [f64; 3], ax: f64, ay: f64) -> f64 {
        self.d_cos_k_stretched(wm, ax, ay, 0)
    }

    /// D(m) cos^k θm as [`AnyNdf::d_stretched`] forms D: k = 1 is the D·cos density, finite
    /// where D overflows toward the horizon (Student-T at γ < 2).
    pub(crate) fn d_cos_k_stretched(&self, wm: [f64; 3], ax: f64, ay: f64, k: i32) -> f64 {
        let z = wm[2];
        let s = crate::math::vec3::hypot(wm[0] / ax, wm[1] / ay);
        if s >= 1e15 * z {
            return match self.ln_f_far(s.ln() - z.ln()) {
                Some(lf) => (lf - (ax * ay).ln() - f64::from(4 - k) * z.ln()).exp(),
                None => 0.0,
            };
        }
        let (gx, gy) = (wm[0] / (ax * z), wm[1] / (ay * z));
        let z2 = z * z;
        self.p22(gx, gy) * z.powi(k) / (ax * ay * z2 * z2)
    }

    /// Λ at x = cot θ/α given directly (not through a rounded cosine, whose rounding moves Λ
    /// by up to p·2ε/sin²θ relative where Λ ~ cot^{−p}θ): the Beckmann mixtures of the
    /// family; `None` for the others.
    pub(crate) fn lambda_x(&self, x: f64) -> Option<f64> {
        let lambda: &dyn Fn(f64) -> f64 = match self {
            AnyNdf::StudentT(n) => &|x| n.lambda_x(x),
            AnyNdf::Ei(_) => &crate::ndf::ei::lambda_x,
            AnyNdf::Erfc(_) => &crate::ndf::erfc::lambda_x,
            AnyNdf::K0(_) => &crate::K0::lambda_x,
            AnyNdf::BesselK(n) => &|x| n.lambda_x(x),
            _ => return None,
        };
        if x < 1e-20 {
            // Grazing: Λ = σ(0)/cot θ − ½ + O(cot θ) (as `Ndf::lambda` below its GRAZING
            // threshold), +∞ at 0 and where σ(0)/cot θ overflows; the members' forms would
            // lose it to x² underflowing.
            return Some(self.sigma(0.0) / (self.alpha() * x) - 0.5);
        }
        Some(lambda(x))
    }

    /// Whether the marginal slope density is unbounded at 0: P2(0) = +∞ (the true value) for
    /// Erfc (P2 ~ −ln |p|) and Bessel-K with a ≤ ½ (P2 ~ |p|^{2a−1}, or −ln |p| at a = ½).
    pub fn p2_singular_at_zero(&self) -> bool {
        match self {
            AnyNdf::Erfc(_) => true,
            AnyNdf::BesselK(n) => n.a() <= 0.5,
            _ => false,
        }
    }

    /// The shape parameter (γ for GTR, Student-T and the generalised exponential, a for
    /// Bessel-K), `None` for the kinds without one.
    pub fn shape(&self) -> Option<f64> {
        match self {
            AnyNdf::Gtr(g) => Some(g.gamma()),
            AnyNdf::StudentT(n) => Some(n.gamma()),
            AnyNdf::BesselK(n) => Some(n.a()),
            AnyNdf::GenExponential(n) => Some(n.gamma()),
            _ => None,
        }
    }

    /// The same NDF at roughness α (no range check: the α = 1 member of a validated
    /// material, or a superposition component).
    pub(crate) fn with_alpha(&self, alpha: f64) -> AnyNdf {
        let shape = self.shape();
        match self {
            AnyNdf::BesselK(n) => AnyNdf::BesselK(BesselK::raw(alpha, n.a())),
            _ => AnyNdf::new(
                self.kind(),
                alpha.clamp(crate::error::ALPHA_MIN, crate::error::ALPHA_MAX),
                shape,
            )
            .expect("a validated NDF's shape at a valid α"),
        }
    }

    /// The mixing law that writes this NDF as a superposition of Beckmann NDFs
    /// ([`crate::ndf::mixture`]), where it is one with a usable density: GGX (Gamma-1), the
    /// Exponential NDF (Gamma(3/2)), Student-T (inverse-Gamma(γ − 1)), Ei, Erfc, K0 and
    /// Bessel-K; `None` for Beckmann itself, GTR, Double GGX (a superposition of GGX) and the
    /// generalised exponential (a positive-stable law for γ < 2, none for γ > 2).
    pub fn beckmann_mixing(&self) -> Option<crate::ndf::mixture::Mixing> {
        use crate::ndf::mixture::Mixing;
        Some(match self {
            AnyNdf::Ggx(_) => Mixing::Gamma1,
            AnyNdf::Exponential(_) => Mixing::Gamma32,
            AnyNdf::StudentT(n) => Mixing::InverseGamma(n.gamma() - 1.0),
            AnyNdf::Ei(_) => Mixing::UniformSquare,
            AnyNdf::Erfc(_) => Mixing::Uniform,
            AnyNdf::K0(_) => Mixing::Gamma(1.0),
            AnyNdf::BesselK(n) => Mixing::Gamma(n.a()),
            _ => return None,
        })
    }

    /// The shape-invariant profile f(x), or `None` for GTR (not shape invariant for γ ≠ 2).
    pub fn f(&self, x: f64) -> Option<f64> {
        match self {
            AnyNdf::Beckmann(n) => Some(n.f(x)),
            AnyNdf::Ggx(n) => Some(n.f(x)),
            AnyNdf::Gtr(_) => None,
            AnyNdf::DoubleGgx(n) => Some(n.f(x)),
            AnyNdf::Exponential(n) => Some(n.f(x)),
            AnyNdf::StudentT(n) => Some(n.f(x)),
            AnyNdf::Ei(n) => Some(n.f(x)),
            AnyNdf::Erfc(n) => Some(n.f(x)),
            AnyNdf::K0(n) => Some(n.f(x)),
            AnyNdf::BesselK(n) => Some(n.f(x)),
            AnyNdf::GenExponential(n) => Some(n.f(x)),
        }
    }

    fn inner(&self) -> &dyn Ndf {
        match self {
            AnyNdf::Beckmann(n) => n,
            AnyNdf::Ggx(n) => n,
            AnyNdf::Gtr(n) => n,
            AnyNdf::DoubleGgx(n) => n,
            AnyNdf::Exponential(n) => n,
            AnyNdf::StudentT(n) => n,
            AnyNdf::Ei(n) => n,
            AnyNdf::Erfc(n) => n,
            AnyNdf::K0(n) => n,
            AnyNdf::BesselK(n) => n,
            AnyNdf::GenExponential(n) => n,
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
    fn d_cos_pos(&self, u: f64) -> f64 {
        self.inner().d_cos_pos(u)
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

//! Albedo tables over (α, μ): the directional albedo of a rough microsurface by scattering
//! order from [`crate::scattering`] (with standard errors), or single scattering by quadrature,
//! for any NDF (GTR at a fixed γ) and facet material, and their storage format.
//!
//! **Generation** ([`Grid::generate`]) is deterministic for a given seed whatever the number
//! of threads: each cell's walks run in chunks of [`CHUNK`] walks, chunk j of cell c from
//! the stream `seed_of(seed, c, j)` (in the two interleaved lanes of
//! [`crate::scattering::albedo`]: that stream and one derived from it), and the chunks' sums
//! are merged in order. With the `rayon` feature the chunks run on every core.
//!
//! **Quantities** per cell, named in the file:
//! * method `quadrature`: `e1`, the single-scattering albedo of the F = 1 conductor with the
//!   height-correlated G2 ([`crate::scattering::single_scattering_albedo`] at relative tolerance
//!   1e-7, error ≤ 1e-6; μ = 0 is the grazing limit, taken at μ = 1e-6);
//! * method `walk`: `r1 r2 r3 r4 r` (reflected energy by order 1, 2, 3, ≥ 4, and in all),
//!   `t1 t2 t3 t4 t` (transmitted; 0 for opaque facets), `e` (their sum), each followed by
//!   its standard error in `<name>_se`.
//!
//! **The binary form** (`.mfa`; all little-endian):
//!
//! | bytes | content |
//! |---|---|
//! | 8 | magic `MFALBEDO` |
//! | 4 | u32 format version, 1 |
//! | 4 | u32 length L of the header text |
//! | L | header text, UTF-8: `key=value` fields separated by `;` (`ndf`, the shape parameter by its name (`gamma` or `a`), `material`, `eta`, `k`, `rho`, `method`, `walks`, `seed`, `quantities` (comma-separated names)) |
//! | 12 | u32 counts: n_α, n_μ, n_q |
//! | 8 n_α | f64 α nodes |
//! | 8 n_μ | f64 μ nodes |
//! | 4 n_α n_μ n_q | f32 values, row-major in (α, μ, quantity) |
//!
//! f32 values carry 6e-8 relative rounding, far below the walks' Monte Carlo error and the
//! quadrature's 1e-6; the nodes are f64 so that a table's grid is reproduced exactly.

use crate::distribution::MicrofacetDistribution;
use crate::ndf::family::NdfKind;
use crate::scattering::albedo::{lane_seed, single_scattering_albedo_tol, AlbedoSums};
use crate::scattering::progress::Progress;
use crate::scattering::walk::{
    DielectricFacets, DiffuseFacets, Heights, MirrorFacets, RandomWalk, WalkRng,
};
use crate::AnyMicrofacet;

/// Walks per chunk: the unit of work (and of the random streams) of [`Grid::generate`]
/// (2¹⁶: a few ms of work, so that a cell of 10⁶ walks spreads over 16 chunks).
pub const CHUNK: u64 = 1 << 16;

/// The facets of a table's microsurface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// A conductor with F = 1 (the white furnace).
    Furnace,
    /// A conductor of complex index η + ik (one channel).
    Conductor { eta: f64, k: f64 },
    /// A dielectric interface of relative index η (μ < 0: from inside).
    Dielectric { eta: f64 },
    /// Lambertian facets of albedo ρ.
    Diffuse { rho: f64 },
}

/// How the cells are computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The single-scattering albedo by quadrature (F = 1 conductor only).
    Quadrature,
    /// The random walk with this many walks per cell, from this seed.
    Walk { walks: u64, seed: u64 },
}

/// What a table is of.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    pub ndf: NdfKind,
    /// The shape parameter of the kinds that have one ([`NdfKind::shape_name`]: γ of GTR,
    /// Student-T and the generalised exponential, a of Bessel-K; required by them, ignored
    /// by the others).
    pub gamma: Option<f64>,
    pub material: Material,
    pub method: Method,
    /// The α nodes (isotropic α).
    pub alpha: Vec<f64>,
    /// The μ = cos θo nodes (in (0, 1]; a dielectric also [−1, 0): from inside).
    pub mu: Vec<f64>,
}

/// A table: its spec, the quantities' names, and the values, row-major in (α, μ, quantity).
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    pub spec: Spec,
    pub quantities: Vec<String>,
    pub values: Vec<f32>,
}

/// Why a table could not be made or read: a bad parameter, or bytes that are not the
/// binary form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableError(pub String);

impl std::fmt::Display for TableError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for TableError {}

/// The fast f64 material of `kind` at isotropic α (the run-time door), or the
/// constructor's error as a [`TableError`].
fn material(
    kind: NdfKind,
    alpha: f64,
    shape: Option<f64>,
) -> Result<AnyMicrofacet<f64>, TableError> {
    AnyMicrofacet::new(kind, alpha, alpha, shape).map_err(|e| TableError(e.to_string()))
}

const MAGIC: &[u8; 8] = b"MFALBEDO";
const VERSION: u32 = 1;

/// The names of a walk table's quantities.
fn walk_quantities() -> Vec<String> {
    let mut q = Vec::new();
    for name in [
        "r1", "r2", "r3", "r4", "r", "t1", "t2", "t3", "t4", "t", "e",
    ] {
        q.push(name.to_string());
        q.push(format!("{name}_se"));
    }
    q
}

/// A stream's seed from the table's seed, the cell and the chunk (SplitMix64's finaliser
/// over their combination).
fn chunk_seed(seed: u64, cell: u64, chunk: u64) -> u64 {
    let mut z = seed
        .wrapping_add(cell.wrapping_mul(0x9E37_79B9_7F4A_7C15))
        .wrapping_add(chunk.wrapping_mul(0xD1B5_4A32_D192_ED03));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Spec {
    /// Checks the parameters: α > 0 finite, μ ≠ 0 in [−1, 1] (negative only for a
    /// dielectric), γ for GTR, the method's material, η, k, ρ in range, at least one node.
    pub fn validate(&self) -> Result<(), TableError> {
        let bad = |what: String| Err(TableError(what));
        if self.alpha.is_empty() || self.mu.is_empty() {
            return bad("a table needs at least one α and one μ".into());
        }
        for &a in &self.alpha {
            // (The distribution's own check follows in `material`.)
            if !(a > 0.0 && a.is_finite()) {
                return bad(format!("α must be positive and finite, got {a}"));
            }
        }
        let transmits = matches!(self.material, Material::Dielectric { .. });
        let quadrature = self.method == Method::Quadrature;
        for &m in &self.mu {
            let grazing = quadrature && m == 0.0;
            if !((m != 0.0 || grazing) && m.abs() <= 1.0) || (m < 0.0 && !transmits) {
                return bad(format!(
                    "μ must be in (0, 1] (the quadrature also 0, a dielectric's walk also [-1, 0)), got {m}"
                ));
            }
        }
        match self.material {
            Material::Furnace => {}
            Material::Conductor { eta, k } => {
                if !(eta > 0.0 && eta.is_finite() && k >= 0.0 && k.is_finite()) {
                    return bad(format!("a conductor needs η > 0 and k ≥ 0, got {eta}, {k}"));
                }
            }
            Material::Dielectric { eta } => {
                if !(eta > 0.0 && eta.is_finite()) {
                    return bad(format!("a dielectric needs η > 0, got {eta}"));
                }
            }
            Material::Diffuse { rho } => {
                if !(0.0..=1.0).contains(&rho) {
                    return bad(format!("ρ must be in [0, 1], got {rho}"));
                }
            }
        }
        if self.method == Method::Quadrature && self.material != Material::Furnace {
            return bad(
                "the quadrature is the single-scattering albedo of the F = 1 conductor".into(),
            );
        }
        for &a in &self.alpha {
            material(self.ndf, a, self.gamma)?;
        }
        Ok(())
    }

    /// The header text of the binary form (without `quantities`).
    fn header(&self) -> String {
        let mut h = format!("ndf={}", self.ndf.name());
        if let (Some(name), Some(g)) = (self.ndf.shape_name(), self.gamma) {
            h += &format!(";{name}={g:?}");
        }
        h += &match self.material {
            Material::Furnace => ";material=furnace".to_string(),
            Material::Conductor { eta, k } => format!(";material=conductor;eta={eta:?};k={k:?}"),
            Material::Dielectric { eta } => format!(";material=dielectric;eta={eta:?}"),
            Material::Diffuse { rho } => format!(";material=diffuse;rho={rho:?}"),
        };
        h += &match self.method {
            Method::Quadrature => ";method=quadrature".to_string(),
            Method::Walk { walks, seed } => format!(";method=walk;walks={walks};seed={seed}"),
        };
        h
    }
}

/// One unit of work: a cell's quadrature, or one chunk of a cell's walks.
#[derive(Clone, Copy, Debug)]
struct Task {
    cell: usize,
    chunk: u64,
    walks: u64,
}

/// What a task produced.
enum Done {
    E1(f64),
    Walks(Box<AlbedoSums>),
}

/// One task's work on the distribution `d`, from wo.
fn cell<D: MicrofacetDistribution<f64> + Clone>(
    d: &D,
    spec: &Spec,
    wo: [f64; 3],
    t: &Task,
) -> Done {
    let Method::Walk { seed, .. } = spec.method else {
        // (μ = 0: the limit, at μ = 1e-6, as compensate's tables take it.)
        let mu = wo[2].max(1e-6);
        let wo = [((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu];
        return Done::E1(single_scattering_albedo_tol(d, wo, 1e-7));
    };
    let s = RandomWalk::new(d.clone(), Heights::Uniform);
    // The chunk's walks in albedo's two interleaved lanes: the chunk's stream and one derived
    // from it (each lane's walks independent of the interleaving).
    let chunk = chunk_seed(seed, t.cell as u64, t.chunk);
    let mut rngs = [WalkRng::new(chunk), WalkRng::new(lane_seed(chunk, 1))];
    let mut lanes = [AlbedoSums::default(), AlbedoSums::default()];
    macro_rules! walks {
        ($facets:expr) => {{
            let f = $facets;
            s.walk_lanes::<1, 2, _>(&f, wo, t.walks, &mut rngs, |j, w| lanes[j].add(wo, w));
        }};
    }
    match spec.material {
        Material::Furnace => walks!(MirrorFacets(crate::bsdf::fresnel::One::<1>)),
        Material::Conductor { eta, k } => walks!(MirrorFacets(crate::bsdf::fresnel::Conductor {
            eta: [eta],
            k: [k]
        })),
        Material::Dielectric { eta } => walks!(DielectricFacets(eta)),
        Material::Diffuse { rho } => walks!(DiffuseFacets(rho)),
    }
    let [mut sums, second] = lanes;
    sums.merge(&second);
    Done::Walks(Box::new(sums))
}

impl Grid {
    /// Computes the table of `spec`, reporting `(done, total)` to `progress` after each unit
    /// of work (from any thread) and asking it before each whether to stop
    /// ([`crate::scattering::Progress`]: then `Err`, the message "cancelled"). Deterministic
    /// for a given spec: see the [module docs](self).
    pub fn generate(spec: &Spec, progress: &dyn Progress) -> Result<Grid, TableError> {
        spec.validate()?;
        let cells = spec.alpha.len() * spec.mu.len();
        let mut tasks = Vec::new();
        for cell in 0..cells {
            match spec.method {
                Method::Quadrature => tasks.push(Task {
                    cell,
                    chunk: 0,
                    walks: 0,
                }),
                Method::Walk { walks, .. } => {
                    let mut left = walks;
                    let mut chunk = 0;
                    while left > 0 {
                        let n = left.min(CHUNK);
                        tasks.push(Task {
                            cell,
                            chunk,
                            walks: n,
                        });
                        left -= n;
                        chunk += 1;
                    }
                }
            }
        }
        let total = tasks.len();
        let done = std::sync::atomic::AtomicUsize::new(0);
        let run = |t: &Task| -> Result<Done, TableError> {
            if progress.cancelled() {
                return Err(TableError("cancelled".into()));
            }
            let (ia, im) = (t.cell / spec.mu.len(), t.cell % spec.mu.len());
            let mu = spec.mu[im];
            let wo = [((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu];
            let out = cell(
                &material(spec.ndf, spec.alpha[ia], spec.gamma)?,
                spec,
                wo,
                t,
            );
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            progress.report(n, total);
            Ok(out)
        };
        #[cfg(feature = "rayon")]
        let results: Vec<Done> = {
            use rayon::prelude::*;
            tasks.par_iter().map(run).collect::<Result<_, _>>()?
        };
        #[cfg(not(feature = "rayon"))]
        let results: Vec<Done> = tasks.iter().map(run).collect::<Result<_, _>>()?;

        let quantities = match spec.method {
            Method::Quadrature => vec!["e1".to_string()],
            Method::Walk { .. } => walk_quantities(),
        };
        let mut values = Vec::with_capacity(cells * quantities.len());
        let mut merged: Vec<AlbedoSums> = vec![AlbedoSums::default(); cells];
        for (t, r) in tasks.iter().zip(&results) {
            match r {
                Done::E1(e) => values.push(*e as f32),
                Done::Walks(s) => merged[t.cell].merge(s),
            }
        }
        if let Method::Walk { .. } = spec.method {
            for m in &merged {
                let a = m.finish();
                for b in [a.reflect, a.transmit] {
                    for k in 0..4 {
                        values.push(b.orders[k] as f32);
                        values.push(b.stderr[k] as f32);
                    }
                    values.push(b.total as f32);
                    values.push(b.total_stderr as f32);
                }
                values.push(a.total.mean as f32);
                values.push(a.total.stderr as f32);
            }
        }
        Ok(Grid {
            spec: spec.clone(),
            quantities,
            values,
        })
    }

    /// The value of quantity `q` (its index in `quantities`) at α node `ia`, μ node `im`;
    /// NaN for an index outside the table.
    pub fn value(&self, ia: usize, im: usize, q: usize) -> f32 {
        let (na, nm, nq) = (
            self.spec.alpha.len(),
            self.spec.mu.len(),
            self.quantities.len(),
        );
        if ia >= na || im >= nm || q >= nq {
            return f32::NAN;
        }
        self.values
            .get((ia * nm + im) * nq + q)
            .copied()
            .unwrap_or(f32::NAN)
    }

    /// The binary form (see the [module docs](self)).
    pub fn to_bytes(&self) -> Vec<u8> {
        let header = format!(
            "{};quantities={}",
            self.spec.header(),
            self.quantities.join(",")
        );
        let mut b = Vec::new();
        b.extend_from_slice(MAGIC);
        b.extend_from_slice(&VERSION.to_le_bytes());
        b.extend_from_slice(&(header.len() as u32).to_le_bytes());
        b.extend_from_slice(header.as_bytes());
        for n in [
            self.spec.alpha.len(),
            self.spec.mu.len(),
            self.quantities.len(),
        ] {
            b.extend_from_slice(&(n as u32).to_le_bytes());
        }
        for x in self.spec.alpha.iter().chain(&self.spec.mu) {
            b.extend_from_slice(&x.to_le_bytes());
        }
        for v in &self.values {
            b.extend_from_slice(&v.to_le_bytes());
        }
        b
    }

    /// Reads the binary form.
    pub fn from_bytes(bytes: &[u8]) -> Result<Grid, TableError> {
        let err = |s: &str| TableError(s.to_string());
        let mut r = Reader(bytes);
        if r.take(8)? != MAGIC {
            return Err(err("no MFALBEDO magic"));
        }
        let version = r.u32()?;
        if version != VERSION {
            return Err(TableError(format!("format version {version}, expected 1")));
        }
        let len = r.u32()? as usize;
        let header = std::str::from_utf8(r.take(len)?).map_err(|_| err("header not UTF-8"))?;
        let field = |key: &str| -> Option<&str> {
            header
                .split(';')
                .find_map(|kv| kv.strip_prefix(key).and_then(|v| v.strip_prefix('=')))
        };
        let num = |key: &str| -> Result<f64, TableError> {
            field(key)
                .and_then(|v| v.parse().ok())
                .ok_or_else(|| TableError(format!("header field '{key}' missing or bad")))
        };
        let ndf: NdfKind = field("ndf")
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| err("header field 'ndf' missing or bad"))?;
        let gamma = ndf
            .shape_name()
            .and_then(field)
            .and_then(|v| v.parse().ok());
        let material = match field("material") {
            Some("furnace") => Material::Furnace,
            Some("conductor") => Material::Conductor {
                eta: num("eta")?,
                k: num("k")?,
            },
            Some("dielectric") => Material::Dielectric { eta: num("eta")? },
            Some("diffuse") => Material::Diffuse { rho: num("rho")? },
            _ => return Err(err("header field 'material' missing or bad")),
        };
        let method = match field("method") {
            Some("quadrature") => Method::Quadrature,
            Some("walk") => Method::Walk {
                walks: num("walks")? as u64,
                seed: field("seed")
                    .and_then(|v| v.parse().ok())
                    .ok_or_else(|| err("header field 'seed' missing or bad"))?,
            },
            _ => return Err(err("header field 'method' missing or bad")),
        };
        let quantities: Vec<String> = field("quantities")
            .ok_or_else(|| err("header field 'quantities' missing"))?
            .split(',')
            .map(str::to_string)
            .collect();
        let (na, nm, nq) = (r.u32()? as usize, r.u32()? as usize, r.u32()? as usize);
        if nq != quantities.len() {
            return Err(err("the quantity count does not match the header"));
        }
        let alpha = (0..na).map(|_| r.f64()).collect::<Result<Vec<_>, _>>()?;
        let mu = (0..nm).map(|_| r.f64()).collect::<Result<Vec<_>, _>>()?;
        let n = na
            .checked_mul(nm)
            .and_then(|x| x.checked_mul(nq))
            .ok_or_else(|| err("counts overflow"))?;
        if r.0.len() != 4 * n {
            return Err(TableError(format!(
                "{} bytes of values, expected {}",
                r.0.len(),
                4 * n
            )));
        }
        let values = (0..n).map(|_| r.f32()).collect::<Result<Vec<_>, _>>()?;
        Ok(Grid {
            spec: Spec {
                ndf,
                gamma,
                material,
                method,
                alpha,
                mu,
            },
            quantities,
            values,
        })
    }
}

/// A cursor over the binary form.
struct Reader<'a>(&'a [u8]);

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], TableError> {
        if self.0.len() < n {
            return Err(TableError("truncated".into()));
        }
        let (a, b) = self.0.split_at(n);
        self.0 = b;
        Ok(a)
    }
    fn u32(&mut self) -> Result<u32, TableError> {
        Ok(u32::from_le_bytes(
            self.take(4)?.try_into().expect("4 bytes"),
        ))
    }
    fn f64(&mut self) -> Result<f64, TableError> {
        Ok(f64::from_le_bytes(
            self.take(8)?.try_into().expect("8 bytes"),
        ))
    }
    fn f32(&mut self) -> Result<f32, TableError> {
        Ok(f32::from_le_bytes(
            self.take(4)?.try_into().expect("4 bytes"),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(method: Method, material: Material) -> Spec {
        Spec {
            ndf: NdfKind::Ggx,
            gamma: None,
            material,
            method,
            alpha: vec![0.3, 1.0],
            mu: vec![0.2, 0.9],
        }
    }

    #[test]
    fn round_trip_and_determinism() {
        let s = spec(
            Method::Walk {
                walks: 2 * CHUNK + 7,
                seed: 5,
            },
            Material::Dielectric { eta: 1.5 },
        );
        let g = Grid::generate(&s, &|_, _| {}).unwrap();
        assert_eq!(g, Grid::generate(&s, &|_, _| {}).unwrap());
        let back = Grid::from_bytes(&g.to_bytes()).unwrap();
        assert_eq!(back, g);
        // Reflection + transmission = 1 (weights 1), per cell.
        let e = g.quantities.iter().position(|q| q == "e").unwrap();
        for ia in 0..2 {
            for im in 0..2 {
                assert_eq!(g.value(ia, im, e), 1.0);
            }
        }
        let q = Grid::generate(&spec(Method::Quadrature, Material::Furnace), &|_, _| {}).unwrap();
        assert_eq!(Grid::from_bytes(&q.to_bytes()).unwrap(), q);
    }

    /// The same table on one thread as on every core (the chunks' streams and merge order
    /// do not depend on the schedule).
    #[cfg(feature = "rayon")]
    #[test]
    fn thread_count_does_not_matter() {
        let s = spec(
            Method::Walk {
                walks: 3 * CHUNK,
                seed: 9,
            },
            Material::Furnace,
        );
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap()
            .install(|| Grid::generate(&s, &|_, _| {}).unwrap());
        let all = Grid::generate(&s, &|_, _| {}).unwrap();
        assert_eq!(one, all);
    }

    #[test]
    fn bad_input_is_an_error() {
        assert!(Grid::generate(
            &spec(Method::Quadrature, Material::Diffuse { rho: 1.0 }),
            &|_, _| {}
        )
        .is_err());
        let mut s = spec(Method::Quadrature, Material::Furnace);
        s.mu = vec![-0.5];
        assert!(s.validate().is_err());
        s.mu = vec![0.5];
        s.alpha = vec![f64::NAN];
        assert!(s.validate().is_err());
        for bytes in [&b""[..], b"MFALBEDO", b"MFALBEDO\x02\0\0\0"] {
            assert!(Grid::from_bytes(bytes).is_err());
        }
        let g = Grid::generate(&spec(Method::Quadrature, Material::Furnace), &|_, _| {}).unwrap();
        let b = g.to_bytes();
        assert!(Grid::from_bytes(&b[..b.len() - 1]).is_err());
    }
}

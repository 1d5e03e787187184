//! `microsurface albedo`: the albedo of a rough microsurface by scattering order, from the
//! random walk of Heitz et al. 2016 (`microsurface::scattering`), or single scattering by quadrature.
//! JSON lines in, one line out per line, in order (errors as in `eval`).

use crate::json::field;
use crate::json::{ndf_alpha, spectrum};
use microsurface::bsdf::fresnel::{self, One};
use microsurface::bsdf::Masking;
use microsurface::scattering::{
    albedo, single_scattering_albedo, single_scattering_albedo_dielectric_level, Albedo, ByOrder,
    DielectricFacets, DiffuseFacets, Heights, MirrorFacets, RandomWalk,
};
use microsurface::{AnyMicrofacet, MicrofacetDistribution};
use serde_json::{json, Value};
use std::process::ExitCode;

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    crate::json::json_lines("albedo", args, albedo_line)
}

const FIELDS: [&str; 14] = [
    "ndf", "alpha", "gamma", "a", "material", "eta", "k", "rho", "mu", "walks", "seed", "method",
    "heights", "g2",
];

/// Walks per line at most (10¹⁰: hours; a typo's 10²⁰ is an error, not a hang).
const MAX_WALKS: f64 = 1e10;

enum Facets {
    /// A conductor: F = 1 without eta and k, else the complex Fresnel term (channel 0 of
    /// the triples: the albedo is per channel; give one channel per line).
    Mirror(Option<(f64, f64)>),
    /// Lambertian facets of albedo ρ.
    Diffuse(f64),
    /// A dielectric interface of relative index η.
    Dielectric(f64),
}

fn albedo_line(text: &str) -> Result<Value, String> {
    let v: Value = serde_json::from_str(text).map_err(|e| format!("not valid JSON: {e}"))?;
    let obj = v.as_object().ok_or("expected a JSON object")?;
    crate::json::known_fields(obj, &FIELDS)?;
    let (kind, ax, ay, shape) = ndf_alpha(obj)?;
    let d = AnyMicrofacet::<f64>::new(kind, ax, ay, shape).map_err(|e| e.to_string())?;
    let mu = field(obj, "mu")?;
    if !(mu != 0.0 && mu.abs() <= 1.0) {
        return Err(format!(
            "field 'mu' must be in (0, 1] (a dielectric also [-1, 0): from inside), got {}",
            crate::json::num(mu)
        ));
    }
    let wo = [((1.0 - mu) * (1.0 + mu)).sqrt(), 0.0, mu];
    let facets = match obj.get("material").map(|m| m.as_str()) {
        None | Some(Some("conductor")) => match (obj.contains_key("eta"), obj.contains_key("k")) {
            (false, false) => Facets::Mirror(None),
            (true, true) => {
                let (eta, k) = (spectrum(obj, "eta")?[0], spectrum(obj, "k")?[0]);
                // (As `bsdf`'s conductors: a complex index with η > 0 and k ≥ 0.)
                if !(eta > 0.0 && k >= 0.0) {
                    return Err("a conductor needs eta > 0 and k >= 0".into());
                }
                Facets::Mirror(Some((eta, k)))
            }
            _ => return Err("a conductor takes both 'eta' and 'k', or neither (F = 1)".into()),
        },
        Some(Some("diffuse")) => {
            let rho = if obj.contains_key("rho") {
                field(obj, "rho")?
            } else {
                1.0
            };
            if !(0.0..=1.0).contains(&rho) {
                return Err(format!(
                    "field 'rho' must be in [0, 1], got {}",
                    crate::json::num(rho)
                ));
            }
            Facets::Diffuse(rho)
        }
        Some(Some("dielectric")) => {
            let eta = field(obj, "eta")?;
            if !(eta > 0.0 && eta.is_finite()) {
                return Err(format!(
                    "field 'eta' must be a positive number, got {}",
                    crate::json::num(eta)
                ));
            }
            Facets::Dielectric(eta)
        }
        _ => {
            return Err(
                "field 'material' must be \"conductor\", \"dielectric\" or \"diffuse\"".into(),
            )
        }
    };
    if mu < 0.0 && !matches!(facets, Facets::Dielectric(_)) {
        return Err(format!(
            "field 'mu' must be in (0, 1] for an opaque material, got {}",
            crate::json::num(mu)
        ));
    }
    let quadrature = match obj.get("method").map(|m| m.as_str()) {
        None | Some(Some("walk")) => false,
        Some(Some("quadrature")) => true,
        _ => return Err("field 'method' must be \"walk\" or \"quadrature\"".into()),
    };
    let heights = match obj.get("heights").map(|m| m.as_str()) {
        None | Some(Some("uniform")) => Heights::Uniform,
        Some(Some("gaussian")) => Heights::Gaussian,
        _ => return Err("field 'heights' must be \"uniform\" or \"gaussian\"".into()),
    };
    if obj.contains_key("g2") && !(quadrature && matches!(facets, Facets::Dielectric(_))) {
        return Err(
            "field 'g2' is for a dielectric's method 'quadrature' (the walk's masking is its own)"
                .into(),
        );
    }
    if quadrature {
        return match facets {
            Facets::Mirror(None) => {
                let e1 = single_scattering_albedo(&d, wo);
                Ok(json!({ "e1": e1 }))
            }
            Facets::Dielectric(eta) => {
                // (By default the exact height-correlated G2: the walk's order 1.)
                let masking = crate::json::masking(obj, Masking::CorrelatedBeta)?;
                let (r, t) = single_scattering_albedo_dielectric_level(&d, wo, eta, masking, 4);
                Ok(json!({ "reflect": { "e1": r }, "transmit": { "e1": t } }))
            }
            _ => Err("method 'quadrature' is the single-scattering albedo of the F = 1 conductor or a dielectric (no eta and k, or diffuse)".into()),
        };
    }
    let walks = crate::json::count(obj, "walks", MAX_WALKS, "1e10")?;
    let seed = crate::json::seed(obj)?;
    let a = run_walks(d, heights, &facets, wo, walks, seed);
    let by_order = |b: &ByOrder| {
        json!({
            "orders": b.orders,
            "stderr": b.stderr,
            "total": b.total,
            "total_stderr": b.total_stderr,
        })
    };
    Ok(match facets {
        Facets::Dielectric(_) => json!({
            "reflect": by_order(&a.reflect),
            "transmit": by_order(&a.transmit),
            "total": a.total.mean,
            "total_stderr": a.total.stderr,
        }),
        _ => by_order(&a.reflect),
    })
}

fn run_walks<D: MicrofacetDistribution<f64>>(
    d: D,
    heights: Heights,
    facets: &Facets,
    wo: [f64; 3],
    walks: u64,
    seed: u64,
) -> Albedo {
    let s = RandomWalk::new(d, heights);
    match *facets {
        Facets::Mirror(None) => albedo(&s, &MirrorFacets(One::<1>), wo, walks, seed),
        Facets::Mirror(Some((eta, k))) => albedo(
            &s,
            &MirrorFacets(fresnel::Conductor { eta: [eta], k: [k] }),
            wo,
            walks,
            seed,
        ),
        Facets::Diffuse(rho) => albedo(&s, &DiffuseFacets(rho), wo, walks, seed),
        Facets::Dielectric(eta) => albedo(
            &s,
            &DielectricFacets::new(eta).expect("η checked where the line was read"),
            wo,
            walks,
            seed,
        ),
    }
}

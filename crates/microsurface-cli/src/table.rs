//! `microsurface table`: albedo tables over (α, μ) by scattering order
//! (`microsurface::scattering::table`), written as JSON or the library's binary form by the output's
//! extension, with a progress bar on stderr and every core.

use microsurface::scattering::table::{Grid, Material, Method, Spec};
use serde_json::json;
use std::process::ExitCode;

/// Walks per cell at most (10¹⁰: hours per cell; a typo's 10²⁰ is an error, not a hang).
const MAX_WALKS: u64 = 10_000_000_000;

/// Nodes per axis at most (a 10⁶ × 10⁶ grid is a typo).
const MAX_NODES: usize = 100_000;

fn err(msg: impl std::fmt::Display) -> String {
    format!("table: {msg}")
}

fn number(flag: &str, s: &str) -> Result<f64, String> {
    s.trim()
        .parse::<f64>()
        .map_err(|_| err(format!("{flag}: '{}' is not a number", crate::clip(s))))
}

/// `a0:a1:n[:spacing]`: n nodes from a0 to a1 (n = 1: a0 alone), spaced uniformly in the
/// value (`lin`, the default), its logarithm (`log`) or its square root (`sqrt`).
fn nodes(flag: &str, s: &str) -> Result<Vec<f64>, String> {
    let parts: Vec<&str> = s.split(':').collect();
    if !(3..=4).contains(&parts.len()) {
        return Err(err(format!(
            "{flag} takes FROM:TO:N[:lin|log|sqrt], got '{}'",
            crate::clip(s)
        )));
    }
    let (a, b) = (number(flag, parts[0])?, number(flag, parts[1])?);
    let n = parts[2]
        .trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| (1..=MAX_NODES).contains(&n))
        .ok_or_else(|| {
            err(format!(
                "{flag}: N must be a whole number in [1, {MAX_NODES}]"
            ))
        })?;
    let spacing = parts.get(3).copied().unwrap_or("lin");
    type Map = fn(f64) -> f64;
    let (fwd, inv): (Map, Map) = match spacing {
        "lin" => (|x| x, |x| x),
        "log" => (f64::ln, f64::exp),
        "sqrt" => (f64::sqrt, |x| x * x),
        other => {
            return Err(err(format!(
                "{flag}: spacing must be lin, log or sqrt, got '{}'",
                crate::clip(other)
            )))
        }
    };
    let (fa, fb) = (fwd(a), fwd(b));
    if !(fa.is_finite() && fb.is_finite()) {
        return Err(err(format!(
            "{flag}: {a}:{b} cannot be spaced by {spacing}"
        )));
    }
    Ok((0..n)
        .map(|k| {
            if n == 1 {
                a
            } else if k == n - 1 {
                b
            } else {
                inv(fa + (fb - fa) * k as f64 / (n - 1) as f64)
            }
        })
        .collect())
}

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let mut ndf = None;
    let (mut alpha, mut mu) = (None, None);
    let (mut gamma, mut eta, mut k, mut rho) = (None, None, None, None);
    let mut shape_a = None;
    let mut material = "furnace".to_string();
    let mut method = "walk".to_string();
    let (mut walks, mut seed) = (None, 0u64);
    let mut out = None;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let v = it
            .next()
            .map(String::as_str)
            .ok_or_else(|| err(format!("{} needs a value", crate::clip(flag))))?;
        match flag.as_str() {
            "--ndf" => ndf = Some(v.to_string()),
            "--alpha" => alpha = Some(nodes(flag, v)?),
            "--mu" => mu = Some(nodes(flag, v)?),
            "--gamma" => gamma = Some(number(flag, v)?),
            "--a" => shape_a = Some(number(flag, v)?),
            "--material" => material = v.to_string(),
            "--eta" => eta = Some(number(flag, v)?),
            "--k" => k = Some(number(flag, v)?),
            "--rho" => rho = Some(number(flag, v)?),
            "--method" => method = v.to_string(),
            "--walks" => {
                walks = Some(
                    v.parse::<u64>()
                        .ok()
                        .filter(|&w| (1..=MAX_WALKS).contains(&w))
                        .ok_or_else(|| {
                            err(format!(
                                "--walks must be a whole number in [1, 1e10], got '{}'",
                                crate::clip(v)
                            ))
                        })?,
                )
            }
            "--seed" => {
                seed = v.parse::<u64>().map_err(|_| {
                    err(format!(
                        "--seed must be a whole number in [0, 2^64), got '{}'",
                        crate::clip(v)
                    ))
                })?
            }
            "--out" => out = Some(v.to_string()),
            other => return Err(err(format!("unknown option '{}'", crate::clip(other)))),
        }
    }
    let ndf = ndf.ok_or_else(|| err("--ndf is required"))?;
    let alpha = alpha.ok_or_else(|| err("--alpha is required"))?;
    let mu = mu.ok_or_else(|| err("--mu is required"))?;
    let out = out.ok_or_else(|| err("--out is required"))?;
    let binary = if out.ends_with(".json") {
        false
    } else if out.ends_with(".mfa") {
        true
    } else {
        return Err(err("--out must end in .json or .mfa (the binary form)"));
    };
    let (ndf, gamma) = crate::json::ndf_from_flags(&ndf, gamma, shape_a).map_err(err)?;
    let material = match material.as_str() {
        "furnace" => Material::Furnace,
        "conductor" => Material::Conductor {
            eta: eta.ok_or_else(|| err("a conductor needs --eta and --k"))?,
            k: k.ok_or_else(|| err("a conductor needs --eta and --k"))?,
        },
        "dielectric" => Material::Dielectric {
            eta: eta.ok_or_else(|| err("a dielectric needs --eta"))?,
        },
        "diffuse" => Material::Diffuse {
            rho: rho.unwrap_or(1.0),
        },
        other => {
            return Err(err(format!(
                "--material must be furnace, conductor, dielectric or diffuse, got '{}'",
                crate::clip(other)
            )))
        }
    };
    let method = match method.as_str() {
        "walk" => Method::Walk {
            walks: walks.ok_or_else(|| err("--walks is required for the walk"))?,
            seed,
        },
        "quadrature" => Method::Quadrature,
        other => {
            return Err(err(format!(
                "--method must be walk or quadrature, got '{}'",
                crate::clip(other)
            )))
        }
    };
    let spec = Spec {
        ndf,
        gamma,
        material,
        method,
        alpha,
        mu,
    };
    spec.validate().map_err(err)?;
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:40}] {pos}/{len} units ({eta} left)",
        )
        .expect("a valid template")
        .progress_chars("=> "),
    );
    let grid = Grid::generate(&spec, &|done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    })
    .map_err(err)?;
    bar.finish_and_clear();
    let bytes = if binary {
        grid.to_bytes()
    } else {
        let (na, nm, nq) = (spec.alpha.len(), spec.mu.len(), grid.quantities.len());
        // (f32 values written as their shortest decimal: 0.702, not 0.7020000219345093.)
        let short = |v: f32| v.to_string().parse::<f64>().unwrap_or(f64::NAN);
        let values: Vec<Vec<Vec<f64>>> = (0..na)
            .map(|ia| {
                (0..nm)
                    .map(|im| (0..nq).map(|q| short(grid.value(ia, im, q))).collect())
                    .collect()
            })
            .collect();
        let (method, walks, seed) = match spec.method {
            Method::Quadrature => ("quadrature", None, None),
            Method::Walk { walks, seed } => ("walk", Some(walks), Some(seed)),
        };
        let material = match spec.material {
            Material::Furnace => json!({"kind": "furnace"}),
            Material::Conductor { eta, k } => json!({"kind": "conductor", "eta": eta, "k": k}),
            Material::Dielectric { eta } => json!({"kind": "dielectric", "eta": eta}),
            Material::Diffuse { rho } => json!({"kind": "diffuse", "rho": rho}),
        };
        let mut text = serde_json::to_string(&json!({
            "ndf": spec.ndf.name(),
            "gamma": spec.gamma,
            "material": material,
            "method": method,
            "walks": walks,
            "seed": seed,
            "alpha": spec.alpha,
            "mu": spec.mu,
            "quantities": grid.quantities,
            "values": values,
        }))
        .expect("JSON of numbers");
        text.push('\n');
        text.into_bytes()
    };
    std::fs::write(&out, bytes)
        .map_err(|e| err(format!("cannot write '{}': {e}", crate::clip(&out))))?;
    Ok(ExitCode::SUCCESS)
}

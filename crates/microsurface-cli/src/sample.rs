//! `microsurface sample`: writes sampled microfacet normals, one `x y z` per line.

use microsurface::check::chi2::SplitMix64;
use microsurface::{Exact, MicrofacetDistribution, NdfKind, Vec3};
use std::io::{BufWriter, Write};
use std::process::ExitCode;

struct Args {
    kind: NdfKind,
    alpha: f64,
    alpha_y: Option<f64>,
    gamma: Option<f64>,
    visible: bool,
    wi: Option<Vec3>,
    n: u64,
    seed: u64,
}

fn value<'a>(flag: &str, v: Option<&'a String>) -> Result<&'a str, String> {
    v.map(String::as_str)
        .ok_or_else(|| format!("sample: {flag} needs a value"))
}

fn number(flag: &str, s: &str) -> Result<f64, String> {
    s.parse::<f64>()
        .map_err(|_| format!("sample: {flag}: '{}' is not a number", crate::clip(s)))
}

fn parse(args: &[String]) -> Result<Args, String> {
    let mut kind = None;
    let mut alpha = None;
    let mut a = Args {
        kind: NdfKind::Ggx,
        alpha: 0.0,
        alpha_y: None,
        gamma: None,
        visible: false,
        wi: None,
        n: 0,
        seed: 0,
    };
    let mut n = None;
    let mut shape_a = None;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let v = value(flag, it.next());
        match flag.as_str() {
            "--ndf" => kind = Some(v?.to_string()),
            "--alpha" => alpha = Some(number(flag, v?)?),
            "--alpha-y" => a.alpha_y = Some(number(flag, v?)?),
            "--gamma" => a.gamma = Some(number(flag, v?)?),
            "--a" => shape_a = Some(number(flag, v?)?),
            "--mode" => {
                a.visible = match v? {
                    "dcos" => false,
                    "visible" => true,
                    other => {
                        return Err(format!(
                            "sample: --mode must be dcos or visible, got '{}'",
                            crate::clip(other)
                        ))
                    }
                }
            }
            "--wi" => {
                let parts: Vec<f64> = v?
                    .split(',')
                    .map(|s| number(flag, s.trim()))
                    .collect::<Result<_, _>>()?;
                if parts.len() != 3 || parts.iter().any(|x| !x.is_finite()) {
                    return Err("sample: --wi needs three finite numbers X,Y,Z".into());
                }
                // Any finite nonzero vector, normalised without overflow (1.7e308,0,1.7e308
                // is the direction (1, 0, 1)/√2).
                let w = Vec3::new(parts[0], parts[1], parts[2]).to_unit();
                if w.x.is_nan() {
                    return Err("sample: --wi must not be the zero vector".into());
                }
                a.wi = Some(w);
            }
            "--n" => {
                n = Some(
                    v?.parse::<u64>()
                        .map_err(|_| "sample: --n must be a non-negative integer".to_string())?,
                )
            }
            "--seed" => {
                a.seed = v?
                    .parse::<u64>()
                    .map_err(|_| "sample: --seed must be a non-negative integer".to_string())?
            }
            other => {
                return Err(format!(
                    "sample: unknown option '{}' (see `microsurface sample --help`)",
                    crate::clip(other)
                ))
            }
        }
    }
    let kind = kind.ok_or("sample: --ndf is required")?;
    a.alpha = alpha.ok_or("sample: --alpha is required")?;
    (a.kind, a.gamma) =
        crate::json::ndf_from_flags(&kind, a.gamma, shape_a).map_err(|e| format!("sample: {e}"))?;
    if a.wi.is_some() && !a.visible {
        return Err(
            "sample: --wi applies to visible normals only (add --mode visible); D·cos \
             sampling has no incident direction"
                .into(),
        );
    }
    a.n = n.unwrap_or(100_000);
    Ok(a)
}

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let a = parse(args)?;
    if a.kind == NdfKind::Gtr && a.alpha_y.is_some() {
        return Err("sample: GTR is isotropic (no --alpha-y)".into());
    }
    // The exact path (invertible warps; the visible normals of GTR by the polar inversion).
    let sampler = Exact::new(a.kind, a.alpha, a.alpha_y.unwrap_or(a.alpha), a.gamma)
        .map_err(|e| format!("sample: {e}"))?;
    let wi = a.wi.unwrap_or(Vec3::Z);
    let mut rng = SplitMix64(a.seed);
    let mut out = BufWriter::new(std::io::stdout().lock());
    for _ in 0..a.n {
        let u = [rng.next_f64(), rng.next_f64()];
        let m = Vec3::from(if a.visible {
            sampler.sample_wm(wi.into(), u)
        } else {
            sampler.sample_dcos(u).wm
        });
        if writeln!(out, "{} {} {}", m.x, m.y, m.z).is_err() {
            // A closed pipe (e.g. `| head`) ends the run quietly.
            return Ok(ExitCode::SUCCESS);
        }
    }
    out.flush().ok();
    Ok(ExitCode::SUCCESS)
}

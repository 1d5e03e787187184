//! `microfacet verify`: runs the identity checks of `microfacet::verify` over a sweep.

use microfacet::verify::{run as run_checks, Sweep};
use microfacet::NdfKind;
use std::process::ExitCode;
use std::time::Instant;

fn parse_list<T>(
    flag: &str,
    value: Option<&String>,
    parse: impl Fn(&str) -> Result<T, String>,
) -> Result<Vec<T>, String> {
    let value = value.ok_or_else(|| format!("{flag} needs a value"))?;
    value
        .split(',')
        .map(|s| parse(s.trim()).map_err(|e| format!("{flag}: {e}")))
        .collect()
}

fn number(s: &str) -> Result<f64, String> {
    s.parse::<f64>()
        .map_err(|_| format!("'{}' is not a number", crate::clip(s)))
}

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let mut sweep = Sweep::default();
    let mut gamma_given = false;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--ndf" => {
                sweep.kinds = parse_list(flag, it.next(), |s| {
                    s.parse::<NdfKind>().map_err(|e| e.to_string())
                })?
            }
            "--alpha" => sweep.alphas = parse_list(flag, it.next(), number)?,
            "--gamma" => sweep.gammas = parse_list(flag, it.next(), number)?,
            other => {
                return Err(format!(
                    "verify: unknown option '{}' (see `microfacet verify --help`)",
                    crate::clip(other)
                ))
            }
        }
        gamma_given |= flag == "--gamma";
    }
    if gamma_given && !sweep.kinds.contains(&NdfKind::Gtr) {
        return Err("verify: --gamma applies to gtr only (add gtr to --ndf)".into());
    }
    // Reject bad parameters up front with the library's own message.
    for &kind in &sweep.kinds {
        for &a in &sweep.alphas {
            let gammas: Vec<Option<f64>> = if kind == NdfKind::Gtr {
                sweep.gammas.iter().copied().map(Some).collect()
            } else {
                vec![None]
            };
            for g in gammas {
                microfacet::AnyNdf::new(kind, a, g).map_err(|e| e.to_string())?;
            }
        }
    }
    let start = Instant::now();
    let checks = run_checks(&sweep, |c| {
        println!(
            "{}  {:9.2e} ≤ {:.0e}  {:28}  {}",
            if c.pass() { "PASS" } else { "FAIL" },
            c.residual,
            c.tol,
            c.subject,
            c.identity
        );
    });
    let failed = checks.iter().filter(|c| !c.pass()).count();
    let worst = checks.iter().map(|c| c.residual).fold(0.0_f64, |m, r| {
        if r.is_nan() {
            f64::NAN
        } else {
            m.max(r)
        }
    });
    println!(
        "verify: {} checks, worst residual {:.2e}, {:.1} s",
        checks.len(),
        worst,
        start.elapsed().as_secs_f64()
    );
    println!("{} passed, {} failed", checks.len() - failed, failed);
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

//! `microsurface verify`: runs the identity checks of `microsurface::check::verify` over a sweep.

use microsurface::check::verify::{run as run_checks, Sweep};
use microsurface::NdfKind;
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
    let mut shapes: Vec<(String, Vec<f64>)> = Vec::new();
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--ndf" => {
                sweep.kinds = parse_list(flag, it.next(), |s| {
                    s.parse::<NdfKind>().map_err(|e| e.to_string())
                })?
            }
            "--alpha" => sweep.alphas = parse_list(flag, it.next(), number)?,
            "--gamma" | "--a" => shapes.push((flag.clone(), parse_list(flag, it.next(), number)?)),
            other => {
                return Err(format!(
                    "verify: unknown option '{}' (see `microsurface verify --help`)",
                    crate::clip(other)
                ))
            }
        }
    }
    // --gamma: the γ of gtr, student_t and gen_exponential; --a: bessel_k's a.
    for (flag, values) in shapes {
        let takes = |k: NdfKind| match k.shape_name() {
            Some("a") => flag == "--a",
            Some(_) => flag == "--gamma",
            None => false,
        };
        let kinds: Vec<NdfKind> = sweep.kinds.iter().copied().filter(|&k| takes(k)).collect();
        if kinds.is_empty() {
            return Err(if flag == "--a" {
                "verify: --a applies to bessel_k only (add bessel_k to --ndf)".into()
            } else {
                "verify: --gamma applies to gtr, student_t and gen_exponential only (add one of them to --ndf)".into()
            });
        }
        for k in kinds {
            sweep.shapes.retain(|(kk, _)| *kk != k);
            sweep.shapes.push((k, values.clone()));
        }
    }
    // Reject bad parameters up front with the library's own message.
    for &kind in &sweep.kinds {
        for &a in &sweep.alphas {
            for g in sweep.shapes_of(kind) {
                microsurface::AnyNdf::new(kind, a, g).map_err(|e| e.to_string())?;
            }
        }
    }
    let start = Instant::now();
    let checks = run_checks(&sweep, |c| match c.skipped {
        Some(why) => println!("SKIP  {:28}  {}  ({why})", c.subject, c.identity),
        None => println!(
            "{}  {:9.2e} ≤ {:.0e}  {:28}  {}",
            if c.pass() { "PASS" } else { "FAIL" },
            c.residual,
            c.tol,
            c.subject,
            c.identity
        ),
    });
    let failed = checks.iter().filter(|c| !c.pass()).count();
    let skipped = checks.iter().filter(|c| c.skipped.is_some()).count();
    let made = checks.iter().filter(|c| c.skipped.is_none());
    let worst =
        made.map(|c| c.residual)
            .fold(0.0_f64, |m, r| if r.is_nan() { f64::NAN } else { m.max(r) });
    println!(
        "verify: {} checks, worst residual {:.2e}, {:.1} s",
        checks.len(),
        worst,
        start.elapsed().as_secs_f64()
    );
    println!(
        "{} passed, {} failed, {} skipped",
        checks.len() - failed - skipped,
        failed,
        skipped
    );
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    })
}

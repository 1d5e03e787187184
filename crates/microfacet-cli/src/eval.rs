//! `microfacet eval`: JSON lines in, JSON lines out, in order; a bad line gets
//! `{"error": "..."}` and the run goes on; exit 1 if any line failed.

use microfacet::{AnyNdf, Ndf, NdfKind};
use serde_json::{Map, Value};
use std::io::{BufRead, BufWriter, Write};
use std::process::ExitCode;

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    if let Some(a) = args.first() {
        return Err(format!(
            "eval: unexpected argument '{a}' (it reads JSON lines on stdin)"
        ));
    }
    let stdin = std::io::stdin().lock();
    let mut out = BufWriter::new(std::io::stdout().lock());
    let mut failed = false;
    for line in stdin.lines() {
        let line = line.map_err(|e| format!("eval: reading stdin: {e}"))?;
        let reply = match eval_line(&line) {
            Ok(v) => serde_json::json!({ "value": v }),
            Err(e) => {
                failed = true;
                serde_json::json!({ "error": e })
            }
        };
        writeln!(out, "{reply}").map_err(|e| format!("eval: writing stdout: {e}"))?;
    }
    out.flush()
        .map_err(|e| format!("eval: writing stdout: {e}"))?;
    Ok(if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

fn field(obj: &Map<String, Value>, name: &str) -> Result<f64, String> {
    match obj.get(name) {
        None => Err(format!("missing field '{name}'")),
        Some(v) => v
            .as_f64()
            .ok_or_else(|| format!("field '{name}' must be a number, got {v}")),
    }
}

/// A direction cosine in [−1, 1].
fn cosine(obj: &Map<String, Value>, name: &str) -> Result<f64, String> {
    let u = field(obj, name)?;
    if !(-1.0..=1.0).contains(&u) {
        return Err(format!("field '{name}' must be in [-1, 1], got {u}"));
    }
    Ok(u)
}

/// Evaluates one request line.
pub fn eval_line(line: &str) -> Result<f64, String> {
    let v: Value = serde_json::from_str(line).map_err(|e| format!("not valid JSON: {e}"))?;
    let obj = v.as_object().ok_or("expected a JSON object")?;
    let name = obj
        .get("ndf")
        .ok_or("missing field 'ndf'")?
        .as_str()
        .ok_or("field 'ndf' must be a string")?;
    let kind: NdfKind = name
        .parse()
        .map_err(|e: microfacet::family::UnknownNdf| e.to_string())?;
    let alpha = field(obj, "alpha")?;
    let gamma = match kind {
        NdfKind::Gtr => Some(field(obj, "gamma")?),
        _ => None,
    };
    let ndf = AnyNdf::new(kind, alpha, gamma).map_err(|e| e.to_string())?;
    let quantity = obj
        .get("quantity")
        .ok_or("missing field 'quantity'")?
        .as_str()
        .ok_or("field 'quantity' must be a string")?;
    let value = match quantity {
        "d" => ndf.d(cosine(obj, "u")?),
        "sigma" => ndf.sigma(cosine(obj, "u")?),
        "lambda" => {
            let u = cosine(obj, "u")?;
            if u == 0.0 {
                return Err("lambda diverges at u = 0 (grazing incidence); g1 is 0 there".into());
            }
            ndf.lambda(u)
        }
        "g1" => ndf.g1(cosine(obj, "u")?),
        "g2" => ndf.g2(cosine(obj, "u_o")?, cosine(obj, "u_i")?),
        "p22" => ndf.p22(finite(obj, "p")?, finite(obj, "q")?),
        "p2" => ndf.p2(finite(obj, "p")?),
        "f" => {
            let x = finite(obj, "x")?;
            ndf.f(x).ok_or_else(|| {
                format!("f(x) is defined only for shape-invariant NDFs, not {name}")
            })?
        }
        other => {
            return Err(format!(
                "unknown quantity '{other}' (expected one of d, p22, p2, f, sigma, lambda, g1, g2)"
            ))
        }
    };
    if !value.is_finite() {
        return Err(format!("{quantity} is not finite for this input"));
    }
    Ok(value)
}

fn finite(obj: &Map<String, Value>, name: &str) -> Result<f64, String> {
    let x = field(obj, name)?;
    if !x.is_finite() {
        return Err(format!("field '{name}' must be finite"));
    }
    Ok(x)
}

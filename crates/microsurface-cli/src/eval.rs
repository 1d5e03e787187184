//! `microsurface eval`: JSON lines in, JSON lines out, in order; a bad line gets
//! `{"error": "..."}` and the run goes on; exit 1 if any line failed.

use crate::json::{field, json_lines};
use microsurface::{AnyNdf, Ndf};
use serde_json::{Map, Value};
use std::process::ExitCode;

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    json_lines("eval", args, |text| {
        eval_line(text).map(|v| serde_json::json!({ "value": v }))
    })
}

/// The fields a request may have besides ndf, alpha, the shape (gamma or a) and quantity.
fn arguments(quantity: &str) -> Option<&'static [&'static str]> {
    Some(match quantity {
        "d" | "sigma" | "lambda" | "g1" => &["u"],
        "g2" => &["u_o", "u_i"],
        "p22" => &["p", "q"],
        "p2" => &["p"],
        "f" => &["x"],
        _ => return None,
    })
}

/// A direction cosine in [−1, 1]; up to 4 ulp past ±1 (the z of a rounded unit vector) is
/// accepted, and the library treats it as ±1.
fn cosine(obj: &Map<String, Value>, name: &str) -> Result<f64, String> {
    let u = field(obj, name)?;
    if u.abs() > 1.0 + 4.0 * f64::EPSILON || u.is_nan() {
        return Err(format!(
            "field '{name}' must be in [-1, 1], got {}",
            crate::json::num(u)
        ));
    }
    Ok(u)
}

/// Evaluates one request line.
pub fn eval_line(line: &str) -> Result<f64, String> {
    let v: Value = serde_json::from_str(line).map_err(|e| format!("not valid JSON: {e}"))?;
    let obj = v.as_object().ok_or("expected a JSON object")?;
    let (kind, gamma) = crate::json::ndf(obj)?;
    let name = kind.name();
    let alpha = field(obj, "alpha")?;
    let ndf = AnyNdf::new(kind, alpha, gamma).map_err(|e| e.to_string())?;
    let quantity = obj
        .get("quantity")
        .ok_or("missing field 'quantity'")?
        .as_str()
        .ok_or("field 'quantity' must be a string")?;
    let Some(args) = arguments(quantity) else {
        return Err(format!(
            "unknown quantity '{}' (expected one of d, p22, p2, f, sigma, lambda, g1, g2)",
            crate::clip(quantity)
        ));
    };
    // Every other field is an error (an `alpha_y` would otherwise be ignored silently).
    for key in obj.keys() {
        let known = matches!(key.as_str(), "ndf" | "alpha" | "quantity")
            || Some(key.as_str()) == kind.shape_name()
            || args.contains(&key.as_str());
        if !known {
            return Err(format!(
                "unknown field '{}' for {name} {quantity} (expected ndf, alpha{}, quantity, {})",
                crate::clip(key),
                kind.shape_name()
                    .map(|n| format!(", {n}"))
                    .unwrap_or_default(),
                args.join(", ")
            ));
        }
    }
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
        // (`arguments` has answered for every other name.)
        _ => return Err(format!("unknown quantity '{}'", crate::clip(quantity))),
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

//! The JSON-lines plumbing every line-based subcommand shares (`eval`, `bsdf`, `albedo`): the
//! line loop with its error lines and exit code, and the fields' readers (numbers, arrays,
//! directions, spectra, the NDF and its parameters), each with one clear error message.

use microsurface::NdfKind;
use serde_json::{Map, Value};
use std::io::{BufRead, BufWriter, Write};
use std::process::ExitCode;

/// The masking-shadowing term of field `g2` (`bsdf`, and `albedo`'s dielectric quadrature):
/// "correlated", "separable" or "correlated_beta"; `default` where the field is absent.
pub(crate) fn masking(
    obj: &Map<String, Value>,
    default: microsurface::bsdf::Masking,
) -> Result<microsurface::bsdf::Masking, String> {
    use microsurface::bsdf::Masking;
    match obj.get("g2") {
        None => Ok(default),
        Some(v) => match v.as_str() {
            Some("correlated") => Ok(Masking::Correlated),
            Some("separable") => Ok(Masking::Separable),
            Some("correlated_beta") => Ok(Masking::CorrelatedBeta),
            _ => Err(
                "field 'g2' must be \"correlated\", \"separable\" or \"correlated_beta\"".into(),
            ),
        },
    }
}

/// The JSON-lines loop of `eval` and `bsdf`: one reply per non-empty input line, in order;
/// a line whose handler fails (or that is not UTF-8) gets `{"error": ...}` and the run goes
/// on; exit 1 if any line failed.
pub(crate) fn json_lines(
    command: &str,
    args: &[String],
    mut handle: impl FnMut(&str) -> Result<Value, String>,
) -> Result<ExitCode, String> {
    if let Some(a) = args.first() {
        return Err(format!(
            "{command}: unexpected argument '{}' (it reads JSON lines on stdin)",
            crate::clip(a)
        ));
    }
    let mut stdin = std::io::stdin().lock();
    let mut out = BufWriter::new(std::io::stdout().lock());
    let mut failed = false;
    let mut line = Vec::new();
    loop {
        line.clear();
        let n = stdin
            .read_until(b'\n', &mut line)
            .map_err(|e| format!("{command}: reading stdin: {e}"))?;
        if n == 0 {
            break;
        }
        // A line that is not UTF-8 is a bad line like any other: an error reply, and on.
        let reply = match std::str::from_utf8(&line) {
            Ok(text) if text.trim().is_empty() => continue,
            Ok(text) => handle(text),
            Err(_) => Err("the line is not valid UTF-8".to_string()),
        };
        let reply = reply.unwrap_or_else(|e| {
            failed = true;
            serde_json::json!({ "error": e })
        });
        writeln!(out, "{reply}").map_err(|e| format!("{command}: writing stdout: {e}"))?;
    }
    out.flush()
        .map_err(|e| format!("{command}: writing stdout: {e}"))?;
    Ok(if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    })
}

/// Err for a field of `obj` not among `fields` (the JSON-lines commands' strictness).
pub(crate) fn known_fields(obj: &Map<String, Value>, fields: &[&str]) -> Result<(), String> {
    match obj.keys().find(|k| !fields.contains(&k.as_str())) {
        Some(key) => Err(format!(
            "unknown field '{}' (expected {})",
            crate::clip(key),
            fields.join(", ")
        )),
        None => Ok(()),
    }
}

/// The request's NDF and shape: "ndf" as the library's spec parser reads it
/// ([`microsurface::NdfSpec`]: `"ggx"`, `"gtr:1.5"`, `"Student-T:2.5"`), the shape from the
/// spec or from its own field ("gamma" or "a", [`shape`]), not both.
pub(crate) fn ndf(obj: &Map<String, Value>) -> Result<(NdfKind, Option<f64>), String> {
    let name = string(obj, "ndf")?;
    match ndf_name(name)? {
        (kind, Some(spec_shape)) => {
            if let Some(key) = ["gamma", "a"].into_iter().find(|k| obj.contains_key(*k)) {
                return Err(format!(
                    "field '{key}' given with a shape in 'ndf' ('{}'): give the shape once",
                    crate::clip(name)
                ));
            }
            Ok((kind, spec_shape))
        }
        (kind, None) => Ok((kind, shape(obj, kind)?)),
    }
}

/// An NDF name as the JSON lines and the flags give it: with a `:` the library's spec
/// (`gtr:1.5`: the kind and `Some(shape)`), else a kind alone (`None`: its shape, if any,
/// comes from its own field or flag).
fn ndf_name(name: &str) -> Result<(NdfKind, Option<Option<f64>>), String> {
    if name.contains(':') {
        let spec: microsurface::NdfSpec = name.parse().map_err(|e| format!("{e}"))?;
        return Ok((spec.kind, Some(spec.shape)));
    }
    let kind: NdfKind = name
        .parse()
        .map_err(|e: microsurface::ndf::UnknownNdf| e.to_string())?;
    Ok((kind, None))
}

/// The request's shape parameter, for the kinds that have one ([`NdfKind::shape_name`]):
/// "gamma" (gtr, student_t, gen_exponential) or "a" (bessel_k); a shape field on a kind
/// without it is an error.
pub(crate) fn shape(obj: &Map<String, Value>, kind: NdfKind) -> Result<Option<f64>, String> {
    for key in ["gamma", "a"] {
        if obj.contains_key(key) && kind.shape_name() != Some(key) {
            return Err(format!(
                "unknown field '{key}' for ndf {kind} ({})",
                if key == "gamma" {
                    "gamma is for gtr, student_t and gen_exponential"
                } else {
                    "a is for bessel_k"
                }
            ));
        }
    }
    match kind.shape_name() {
        Some(name) => Ok(Some(field(obj, name)?)),
        None => Ok(None),
    }
}

/// The NDF and shape of a command line: `--ndf` as the spec parser reads it (`ggx`,
/// `gtr:1.5`), the shape there or from `--gamma` / `--a` ([`shape_from_flags`]), not both.
pub(crate) fn ndf_from_flags(
    ndf: &str,
    gamma: Option<f64>,
    a: Option<f64>,
) -> Result<(NdfKind, Option<f64>), String> {
    match ndf_name(ndf)? {
        (kind, Some(spec_shape)) => {
            if gamma.is_some() || a.is_some() {
                return Err("the shape is given twice (in --ndf and by --gamma/--a)".into());
            }
            Ok((kind, spec_shape))
        }
        (kind, None) => Ok((kind, shape_from_flags(kind, gamma, a)?)),
    }
}

/// The shape parameter from a command line's `--gamma` / `--a` for `kind`: required where
/// the kind has one ([`NdfKind::shape_name`]), an error where it has not.
pub(crate) fn shape_from_flags(
    kind: NdfKind,
    gamma: Option<f64>,
    a: Option<f64>,
) -> Result<Option<f64>, String> {
    let (want, other) = match kind.shape_name() {
        Some("a") => (a, gamma.map(|_| "--gamma")),
        Some(_) => (gamma, a.map(|_| "--a")),
        None => {
            return match (gamma, a) {
                (None, None) => Ok(None),
                (Some(_), _) => Err(format!(
                    "--gamma applies to gtr, student_t and gen_exponential only, not {kind}"
                )),
                _ => Err(format!("--a applies to bessel_k only, not {kind}")),
            }
        }
    };
    if let Some(flag) = other {
        return Err(format!(
            "{flag} does not apply to {kind} (its shape is --{})",
            kind.shape_name().unwrap_or("")
        ));
    }
    want.map(Some).ok_or_else(|| {
        format!(
            "--{} is required for {kind}",
            kind.shape_name().unwrap_or("")
        )
    })
}

/// A number as an error message shows it: in full where that is short, in scientific
/// notation where it would be long (1e308 written out is 309 digits; errors stay one short
/// line).
pub(crate) fn num(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e7).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

pub(crate) fn field(obj: &Map<String, Value>, name: &str) -> Result<f64, String> {
    match obj.get(name) {
        None => Err(format!("missing field '{name}'")),
        Some(v) => v.as_f64().ok_or_else(|| {
            format!(
                "field '{name}' must be a number, got {}",
                crate::clip(&v.to_string())
            )
        }),
    }
}

/// The request's "ndf", "alpha" (a or [ax, ay]) and shape parameter ("gamma" for gtr,
/// student_t and gen_exponential, "a" for bessel_k).
pub(crate) fn ndf_alpha(
    obj: &Map<String, Value>,
) -> Result<(NdfKind, f64, f64, Option<f64>), String> {
    let (kind, shape) = ndf(obj)?;
    let (ax, ay) = alpha(obj)?;
    Ok((kind, ax, ay, shape))
}

pub(crate) fn string<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a str, String> {
    obj.get(name)
        .ok_or_else(|| format!("missing field '{name}'"))?
        .as_str()
        .ok_or_else(|| format!("field '{name}' must be a string"))
}

/// "alpha": a or [ax, ay].
pub(crate) fn alpha(obj: &Map<String, Value>) -> Result<(f64, f64), String> {
    match obj.get("alpha") {
        Some(Value::Array(a)) => {
            let v = numbers(a, "alpha", 2)?;
            Ok((v[0], v[1]))
        }
        _ => {
            let a = field(obj, "alpha")?;
            Ok((a, a))
        }
    }
}

/// An array of exactly `n` finite numbers.
pub(crate) fn numbers(a: &[Value], name: &str, n: usize) -> Result<Vec<f64>, String> {
    let v: Option<Vec<f64>> = a.iter().map(Value::as_f64).collect();
    match v {
        Some(v) if v.len() == n && v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(format!(
            "field '{name}' must be an array of {n} finite numbers"
        )),
    }
}

pub(crate) fn array(obj: &Map<String, Value>, name: &str, n: usize) -> Result<Vec<f64>, String> {
    match obj.get(name) {
        None => Err(format!("missing field '{name}'")),
        Some(Value::Array(a)) => numbers(a, name, n),
        Some(_) => Err(format!(
            "field '{name}' must be an array of {n} finite numbers"
        )),
    }
}

/// A direction: any finite nonzero 3-vector, normalised.
pub(crate) fn direction(obj: &Map<String, Value>, name: &str) -> Result<[f64; 3], String> {
    let v = array(obj, name, 3)?;
    let w = microsurface::bsdf::frame::normalize([v[0], v[1], v[2]]);
    if !w[0].is_finite() {
        return Err(format!("field '{name}' must be a nonzero vector"));
    }
    Ok(w)
}

/// η (scalar or RGB) and k (RGB), per channel.
pub(crate) fn spectrum(obj: &Map<String, Value>, name: &str) -> Result<[f64; 3], String> {
    match obj.get(name) {
        Some(Value::Array(a)) => {
            let v = numbers(a, name, 3)?;
            Ok([v[0], v[1], v[2]])
        }
        _ => {
            let x = field(obj, name)?;
            if !x.is_finite() {
                return Err(format!("field '{name}' must be finite"));
            }
            Ok([x; 3])
        }
    }
}

/// A count field: a whole number in [1, `max`] (`max_text` as the error writes it).
pub(crate) fn count(
    obj: &Map<String, Value>,
    name: &str,
    max: f64,
    max_text: &str,
) -> Result<u64, String> {
    let n = field(obj, name)?;
    if !((1.0..=max).contains(&n) && n.fract() == 0.0) {
        return Err(format!(
            "field '{name}' must be a whole number in [1, {max_text}], got {}",
            num(n)
        ));
    }
    Ok(n as u64)
}

/// The optional "seed": a whole number in [0, 2^64), 0 when absent.
pub(crate) fn seed(obj: &Map<String, Value>) -> Result<u64, String> {
    if !obj.contains_key("seed") {
        return Ok(0);
    }
    let s = field(obj, "seed")?;
    if !((0.0..1.8e19).contains(&s) && s.fract() == 0.0) {
        return Err(format!(
            "field 'seed' must be a whole number in [0, 2^64), got {}",
            num(s)
        ));
    }
    Ok(s as u64)
}

//! `microsurface lut`: the tables real-time engines load (`microsurface::scattering::lut`),
//! computed on every core with a progress bar, written in one of the [`format`]s, with a
//! manifest beside them (`<file>.json`: the generator, the command, every parameter and
//! axis, the layout, and the errors measured: the linear filter's against the quadrature
//! off the nodes, and the storage's against the computed values, read back from the file).

pub mod format;

use format::{Format, LutData};
use microsurface::scattering::lut::{Lut, LutKind, LutSpec, MuAxis, Nodes, RoughnessAxis};
use microsurface::NdfSpec;
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

fn err(msg: impl std::fmt::Display) -> String {
    format!("lut: {msg}")
}

fn count(flag: &str, v: &str, min: usize) -> Result<usize, String> {
    v.trim()
        .parse::<usize>()
        .ok()
        .filter(|&n| n >= min)
        .ok_or_else(|| {
            err(format!(
                "{flag} must be a whole number ≥ {min}, got '{}'",
                crate::clip(v)
            ))
        })
}

/// What a channel means, for the manifest.
fn meaning(kind: LutKind, channel: &str) -> &'static str {
    match (kind, channel) {
        (LutKind::Albedo, _) => "E(mu): directional albedo of the F = 1 conductor (single scattering, height-correlated G2)",
        (LutKind::AlbedoAvg, _) => "E_avg = 2 int E(mu) mu dmu",
        (LutKind::Dfg, "A") => "split-sum scale: int f(F=1) cos (1 - (1-c)^5); Schlick albedo = F0 A + B",
        (LutKind::Dfg, "B") => "split-sum bias: int f(F=1) cos (1-c)^5",
        (LutKind::Dfg, _) => "F82-tint term: int f(F=1) cos c (1-c)^6; F82-tint albedo = F0 A + B - a C",
        (LutKind::Dielectric, "R") => "reflected share of single scattering (exact Fresnel)",
        (LutKind::Dielectric, _) => "transmitted share of single scattering (importance transport)",
        (LutKind::DielectricAvg, "R_avg") => "2 int R(mu) mu dmu",
        (LutKind::DielectricAvg, _) => "2 int T(mu) mu dmu",
    }
}

fn bar(what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(&format!(
            "{what} {{elapsed_precise}} [{{bar:40}}] {{pos}}/{{len}} nodes ({{eta}} left)"
        ))
        .expect("a valid template")
        .progress_chars("=> "),
    );
    bar
}

pub fn run(args: &[String]) -> Result<ExitCode, String> {
    let mut ndf: Option<NdfSpec> = None;
    let (mut gamma, mut shape_a) = (None, None);
    let mut kind = None;
    let mut spec_size = None;
    let (mut eta_size, mut aspect_size) = (None, None);
    let (mut mu_axis, mut roughness_axis) = (None, None);
    let (mut alpha_max, mut level) = (None, None);
    let mut format = None;
    let mut out = None;
    let mut check = 8usize;
    let mut nodes = None;
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let v = it
            .next()
            .map(String::as_str)
            .ok_or_else(|| err(format!("{} needs a value", crate::clip(flag))))?;
        let number = |v: &str| {
            v.trim()
                .parse::<f64>()
                .map_err(|_| err(format!("{flag}: '{}' is not a number", crate::clip(v))))
        };
        match flag.as_str() {
            "--ndf" => ndf = Some(v.parse::<NdfSpec>().map_err(err)?),
            "--gamma" => gamma = Some(number(v)?),
            "--a" => shape_a = Some(number(v)?),
            "--kind" => kind = Some(v.parse::<LutKind>().map_err(err)?),
            "--size" => spec_size = Some(count(flag, v, 1)?),
            "--eta-size" => eta_size = Some(count(flag, v, 1)?),
            "--aspect-size" => aspect_size = Some(count(flag, v, 0)?),
            "--mu-axis" => mu_axis = Some(v.parse::<MuAxis>().map_err(err)?),
            "--roughness-axis" => roughness_axis = Some(v.parse::<RoughnessAxis>().map_err(err)?),
            "--alpha-max" => alpha_max = Some(number(v)?),
            "--level" => level = Some(count(flag, v, 0)?),
            "--check" => check = count(flag, v, 0)?,
            "--nodes" => nodes = Some(v.parse::<Nodes>().map_err(err)?),
            "--format" => format = Some(v.parse::<Format>().map_err(err)?),
            "--out" => out = Some(PathBuf::from(v)),
            other => return Err(err(format!("unknown option '{}'", crate::clip(other)))),
        }
    }
    let mut ndf = ndf.ok_or_else(|| err("--ndf is required"))?;
    if gamma.is_some() || shape_a.is_some() {
        if ndf.shape.is_some() {
            return Err(err(
                "the shape is given twice (in --ndf and by --gamma/--a)",
            ));
        }
        ndf.shape = crate::json::shape_from_flags(ndf.kind, gamma, shape_a).map_err(err)?;
    }
    let ndf = NdfSpec::new(ndf.kind, ndf.shape).map_err(err)?;
    let kind = kind.ok_or_else(|| err("--kind is required"))?;
    let mut spec = LutSpec::new(ndf, kind);
    spec.size = spec_size.unwrap_or(spec.size);
    spec.eta_size = eta_size.unwrap_or(spec.eta_size);
    spec.aspect_size = aspect_size.unwrap_or(spec.aspect_size);
    spec.mu_axis = mu_axis.unwrap_or(spec.mu_axis);
    spec.roughness_axis = roughness_axis.unwrap_or(spec.roughness_axis);
    spec.alpha_max = alpha_max.unwrap_or(spec.alpha_max);
    spec.nodes = nodes.unwrap_or(spec.nodes);
    if let Some(l) = level {
        spec.level = u32::try_from(l).unwrap_or(u32::MAX);
    }
    // The format: --format, else --out's extension, else .npy.
    let format = match (format, &out) {
        (Some(f), _) => f,
        (None, Some(path)) => Format::ALL
            .into_iter()
            .find(|f| path.extension().is_some_and(|e| e == f.extension()))
            .ok_or_else(|| {
                err(format!(
                    "cannot tell the format from '{}': give --format",
                    crate::clip(&path.display().to_string())
                ))
            })?,
        (None, None) => Format::Npy,
    };
    let name = format!(
        "{}_{}_{}",
        ndf.to_string().replace([':', '.'], "_"),
        kind.name().replace('-', "_"),
        spec.size
    );
    let out = out.unwrap_or_else(|| PathBuf::from(format!("{name}.{}", format.extension())));

    let progress = bar("computing");
    let lut = Lut::compute(&spec, &|done, total| {
        progress.set_length(total as u64);
        progress.set_position(done as u64);
    })
    .map_err(err)?;
    progress.finish_and_clear();

    // The averages (albedo-avg, dielectric-avg) have one axis, the roughness: written as a
    // table of one column, a trailing axis `avg` of one node, so that every format's layout
    // (μ the image's width, roughness its height; the .npy shape) holds unchanged.
    let (mut axes, mut dims): (Vec<String>, Vec<usize>) = (
        lut.axes.iter().map(|a| a.name.to_string()).collect(),
        lut.dims(),
    );
    if dims.len() == 1 {
        axes.push("avg".into());
        dims.push(1);
    }
    let data = LutData {
        name: name.clone(),
        axes,
        dims,
        channels: lut.channels.iter().map(|c| c.to_string()).collect(),
        // (16-bit PNG holds [0, 1]: a quadrature's 1 + 1e-9 is stored as 1, and counted in
        // the storage error below.)
        values: lut
            .values
            .iter()
            .map(|&v| {
                if format.is_exact() {
                    v as f32
                } else {
                    v.clamp(0.0, 1.0) as f32
                }
            })
            .collect(),
    };
    format::write(&data, format, &out).map_err(err)?;
    // The storage's error: the file read back against the f64 values.
    let back = format::read(format, &out).map_err(err)?;
    if back.dims != data.dims || back.values.len() != lut.values.len() {
        return Err(err(format!(
            "'{}' did not read back as written",
            out.display()
        )));
    }
    let storage = back
        .values
        .iter()
        .zip(&lut.values)
        .map(|(&a, &b)| (a as f64 - b).abs())
        .fold(0.0, f64::max);

    let filter = if check > 0 {
        let progress = bar("checking");
        let acc = lut.error(check, &|done, total| {
            progress.set_length(total as u64);
            progress.set_position(done as u64);
        });
        progress.finish_and_clear();
        let stat = |s: &microsurface::scattering::lut::ErrorStat| {
            json!({
                "max_abs": s.max_abs,
                "rms": s.rms,
                "at": {"coords": s.at.0, "channel": lut.channels.get(s.at.1)},
                "points": s.points,
            })
        };
        json!({
            "interior": stat(&acc.interior),
            "border": stat(&acc.border),
            "per_axis": check,
            "reference": format!("quadrature at level {}", (spec.level + 1).min(7)),
            "how": "the linear filter between the nodes (clamped to the end nodes) against the quantity: interior at the midpoints between nodes, border where a coordinate of a texel-centred axis is halfway between the end node and the edge",
        })
    } else {
        serde_json::Value::Null
    };
    let manifest = json!({
        "generator": format!("microsurface {}", env!("CARGO_PKG_VERSION")),
        "command": std::iter::once("microsurface lut".to_string())
            .chain(args.iter().cloned())
            .collect::<Vec<_>>()
            .join(" "),
        "file": out.file_name().map(|f| f.to_string_lossy().into_owned()),
        "format": format.extension(),
        "ndf": ndf.to_string(),
        "kind": kind.name(),
        "channels": lut.channels.iter().map(|c| json!({"name": c, "meaning": meaning(kind, c)})).collect::<Vec<_>>(),
        "axes": lut.axes.iter().map(|a| json!({
            "name": a.name,
            "nodes": a.coords.len(),
            "map": a.map,
            "coords": match (a.interpolated, a.nodes) {
                (false, _) => "node index",
                (true, Nodes::Centres) => "texel centres (i + 0.5)/n",
                (true, Nodes::Edges) => "edges i/(n - 1)",
            },
            "params": a.params,
        })).collect::<Vec<_>>(),
        "layout": if lut.axes.len() == 1 {
            "row-major over the axes (outermost first), then the channels; one axis (the roughness), written as a column: the file's dims are [roughness, 1] (a trailing axis 'avg' of one node)"
        } else {
            "row-major over the axes (outermost first), then the channels"
        },
        "masking": "height-correlated G2 = 1/(1 + L(wo) + L(wi))",
        "alpha_max": spec.alpha_max,
        "level": spec.level,
        "error": {
            "filter": filter,
            "storage": {
                "max_abs": storage,
                "how": if format.is_exact() { "f32, read back from the file" } else { "16-bit, read back from the file" },
            },
        },
    });
    let manifest_path = manifest_path(&out);
    let mut text = serde_json::to_string_pretty(&manifest).expect("JSON of numbers");
    text.push('\n');
    std::fs::write(&manifest_path, text).map_err(|e| {
        err(format!(
            "cannot write '{}': {e}",
            crate::clip(&manifest_path.display().to_string())
        ))
    })?;
    eprintln!("wrote {} and {}", out.display(), manifest_path.display());
    Ok(ExitCode::SUCCESS)
}

/// The manifest beside a table: `<file>.json` (`ggx_dfg_32.exr.json`), so that tables of
/// one name in several formats keep theirs apart.
fn manifest_path(out: &Path) -> PathBuf {
    let mut s = out.as_os_str().to_owned();
    s.push(".json");
    PathBuf::from(s)
}

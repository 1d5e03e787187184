//! `microsurface`: the command-line face of the library. One file per subcommand; this file only
//! dispatches and turns failures into one-line messages with a non-zero exit code.

mod albedo;
mod bsdf;
mod eval;
mod json;
mod lut;
mod report;
mod sample;
mod table;
mod verify;

use std::process::ExitCode;

const VERIFY_USAGE: &str = "\
  microsurface verify [--ndf LIST] [--alpha LIST] [--gamma LIST]
      check every identity of the source pages by numerical integration;
      one line per check (PASS/FAIL, residual); exit 1 if any fails.
      LIST is comma-separated, e.g. --ndf ggx,gtr --alpha 0.1,0.5 --gamma 1,1.5
      (--gamma sets the γ of gtr, student_t and gen_exponential, --a the a of bessel_k;
      each needs such an NDF among --ndf; default shapes otherwise)
";

const EVAL_USAGE: &str = "\
  microsurface eval
      JSON lines in, JSON lines out, in order, e.g.
      {\"ndf\":\"gtr\",\"alpha\":0.3,\"gamma\":1.5,\"quantity\":\"lambda\",\"u\":0.5} -> {\"value\":...}
      quantities: d, sigma, lambda, g1 (u); p22 (p, q); p2 (p); f (x); g2 (u_o, u_i)
      (shape: \"gamma\" for gtr, student_t, gen_exponential, \"a\" for bessel_k;
      any other field is an error). u ∈ [-1, 1]: for u < 0,
      sigma is the projected area seen from below, lambda is Heitz's extension
      -1 - lambda(-u), and g1, g2 use |u|. A bad line gets {\"error\": ...} and the
      run goes on (exit 1 at the end); empty lines are skipped.
";

const SAMPLE_USAGE: &str = "\
  microsurface sample --ndf NAME --alpha A [--alpha-y AY] [--gamma G | --a A] [--mode dcos|visible]
                    [--wi X,Y,Z] [--n N] [--seed S]
      write N sampled normals (default 100000), one `x y z` per line; D·cos (default)
      or visible normals for the incident direction --wi (visible mode only; any
      finite nonzero vector, normalised; default 0,0,1). --gamma: required for gtr,
      student_t, gen_exponential; --a: required for bessel_k.
";

const BSDF_USAGE: &str = "\
  microsurface bsdf
      rough conductor and dielectric BSDFs (pbrt-v4's conventions:
      f without the cosine, pdf per solid angle, local frame z = normal, radiance
      transport), JSON lines in, one line out per line, e.g.
      {\"bsdf\":\"conductor\",\"ndf\":\"ggx\",\"alpha\":[0.3,0.1],\"eta\":[0.2,0.9,1.1],
       \"k\":[3.9,2.4,2.2],\"op\":\"eval\",\"wo\":[0,0.6,0.8],\"wi\":[0.3,0,0.95]}
        -> {\"f\":[r,g,b],\"pdf\":p}
      op sample takes \"u\":[uc,u0,u1] in [0,1) instead of wi -> {\"wi\":[...],\"f\":[...],
        \"pdf\":p,\"kind\":\"reflection\"|\"transmission\"|\"rejected\",\"specular\":b}
      alpha: a or [ax, ay]; gamma for gtr (anisotropic only at gamma 2), student_t and
      gen_exponential, a for bessel_k; conductor:
      eta and k (number or [r,g,b]; neither: F = 1); dielectric: eta (one number);
      g2: correlated (default: 1/(1+L(wo)+L(wi))), separable (G1(wo) G1(wi)) or
      correlated_beta (a transmission's exact B(1+L(wo),1+L(wi)), the walk's order 1);
      single scattering only. Directions are normalised. Errors as in eval.
      scattering: single (default), kulla_conty or turquin (energy compensation: the lost
        energy put back from albedo tables, shipped or computed once per material),
        walk (the random walk of Heitz et al. 2016: sample is the walk, eval one
        stochastic estimate seeded by the directions, pdf the MIS stand-in); ndf names are
        case-insensitive and take aliases (trowbridge_reitz, student-t, ...).
      op eval_ms: the multiple-scattering BSDF (the random walk of Heitz et al. 2016)
        by order, the mean of \"samples\" stochastic evaluations from \"seed\" (default 0)
        -> {\"orders\":[f1,f2,f3,f4plus],\"stderr\":[...],\"total\":f,\"total_stderr\":e},
        each an [r,g,b] triple (orders 1: single scattering, height-correlated G2).
";

const ALBEDO_USAGE: &str = "\
  microsurface albedo
      the albedo of a rough microsurface by scattering order, from the random walk of
      Heitz et al. 2016 (multiple scattering), JSON lines in, one line out per line, e.g.
      {\"ndf\":\"ggx\",\"alpha\":1,\"mu\":0.5,\"walks\":100000,\"seed\":1}
        -> {\"orders\":[E1,E2,E3,E4plus],\"stderr\":[...],\"total\":E,\"total_stderr\":e}
      material: conductor (default; eta and k numbers or [r,g,b], channel 0 used;
      neither: F = 1), dielectric (\"eta\" > 0, mu < 0 from inside; -> {\"reflect\":
      {...},\"transmit\":{...},\"total\":E,\"total_stderr\":e}) or diffuse
      (Lambertian facets, \"rho\" in [0,1], default 1); alpha: a or [ax, ay]; gamma
      or a as in eval; heights: uniform (default) or gaussian;
      \"method\":\"quadrature\" -> {\"e1\":value}, the F = 1 conductor's single
      scattering by deterministic quadrature; for a dielectric {\"reflect\":{\"e1\":r},
      \"transmit\":{\"e1\":t}} (by default the exact height-correlated G2, the walk's
      order 1; \"g2\" as in bsdf chooses another). Errors as in eval.
";

const TABLE_USAGE: &str = "\
  microsurface table --ndf NAME --alpha FROM:TO:N[:lin|log|sqrt] --mu FROM:TO:N[:...]
                   --out FILE.json|FILE.mfa [--gamma G] [--material M] [--eta X]
                   [--k X] [--rho X] [--method walk|quadrature] [--walks N] [--seed S]
      albedo tables over (alpha, mu): by scattering order from the random walk
      (reflected r1..r4, r, transmitted t1..t4, t, total e, each with _se, its
      standard error), or the F = 1 conductor's single scattering e1 by quadrature.
      material: furnace (F = 1, default), conductor (--eta, --k), dielectric (--eta;
      mu < 0 from inside), diffuse (--rho, default 1). Every core; deterministic for
      a given --seed (default 0) whatever the thread count. FILE.mfa: the binary form
      documented in microsurface::scattering::table.
";

const LUT_USAGE: &str = "\
  microsurface lut --ndf NAME --kind albedo|albedo-avg|dfg|dielectric|dielectric-avg
                 [--gamma G | --a A] [--size N] [--eta-size N] [--aspect-size N]
                 [--mu-axis mu|sqrt_mu] [--roughness-axis sqrt_alpha|alpha]
                 [--alpha-max A] [--format npy|png|exr|ktx2|c|rust|wgsl] [--out FILE]
                 [--nodes centres|edges] [--level L] [--check N]
      the tables real-time engines load (microsurface::scattering::lut): E(mu, alpha)
      of the F = 1 conductor and its average, the split-sum terms A, B (Schlick:
      F0 A + B) and C (F82-tint: F0 A + B - a C), a dielectric's R and T from both
      sides over (side, eta, alpha, mu) and their averages; --size nodes along mu and
      roughness (default 32), --eta-size along eta = 1 + 2 x^2 (default 16),
      --aspect-size along alpha_y/alpha_x (anisotropic, averaged over the azimuth;
      default 0, isotropic); nodes at texel centres (i + 0.5)/n, for a GPU's linear
      filter, or with --nodes edges at i/(n - 1), both ends included (Cycles' lookup;
      mu = 0 and alpha = 0 taken at their limits). The format by --format,
      else FILE's extension, else npy; FILE defaults to NDF_KIND_SIZE.EXT. Writes
      FILE.json beside it: the parameters, axes, layout and the errors measured (the
      linear filter against the quadrature at --check points per axis, default 8, 0
      skips; the file read back against the values). Every core, progress on stderr.
";

const REPORT_USAGE: &str = "\
  microsurface report [--out DIR]
      write DIR/index.html (default report/): every NDF's quantities, identities,
      superpositions and sample histograms as inline SVG plots, and the verify table
";

/// The end of the full usage text.
const USAGE_TAIL: &str = "\
  microsurface --help | --version

options take their value as `--name value` or `--name=value`;
`microsurface COMMAND --help` shows one command.
";

/// Splits `--name=value` into `--name`, `value` (the forms are equivalent).
fn split_flags(args: &[String]) -> Vec<String> {
    let mut out = Vec::with_capacity(args.len());
    for a in args {
        match a.split_once('=') {
            Some((name, value)) if name.starts_with("--") => {
                out.push(name.to_string());
                out.push(value.to_string());
            }
            _ => out.push(a.clone()),
        }
    }
    out
}

/// At most 60 characters of user input, for error messages (an unknown 1 MB name is not
/// echoed whole).
pub fn clip(s: &str) -> String {
    const MAX: usize = 60;
    match s.char_indices().nth(MAX) {
        Some((i, _)) => format!("{}… ({} bytes)", &s[..i], s.len()),
        None => s.to_string(),
    }
}

fn main() -> ExitCode {
    // A panic is a bug, but the user still gets one line, not a backtrace.
    std::panic::set_hook(Box::new(|info| {
        eprintln!("microsurface: internal error: {info}");
    }));
    // Arguments that are not valid UTF-8 are not options of ours: one line, exit 2.
    let args: Result<Vec<String>, _> = std::env::args_os()
        .skip(1)
        .map(|a| a.into_string())
        .collect();
    let Ok(args) = args else {
        eprintln!("microsurface: arguments must be valid UTF-8");
        return ExitCode::from(2);
    };
    let rest = split_flags(args.get(1..).unwrap_or(&[]));
    let help = rest.iter().any(|a| a == "--help" || a == "-h");
    let usage = |text: &str| {
        print!("usage:\n{text}");
        Ok(ExitCode::SUCCESS)
    };
    let result = match args.first().map(String::as_str) {
        Some("verify") if help => usage(VERIFY_USAGE),
        Some("eval") if help => usage(EVAL_USAGE),
        Some("sample") if help => usage(SAMPLE_USAGE),
        Some("report") if help => usage(REPORT_USAGE),
        Some("bsdf") if help => usage(BSDF_USAGE),
        Some("albedo") if help => usage(ALBEDO_USAGE),
        Some("table") if help => usage(TABLE_USAGE),
        Some("lut") if help => usage(LUT_USAGE),
        Some("albedo") => albedo::run(&rest),
        Some("table") => table::run(&rest),
        Some("lut") => lut::run(&rest),
        Some("bsdf") => bsdf::run(&rest),
        Some("verify") => verify::run(&rest),
        Some("eval") => eval::run(&rest),
        Some("sample") => sample::run(&rest),
        Some("report") => report::run(&rest),
        Some("-h" | "--help" | "help") => {
            print!(
                "microsurface {} — microfacet NDFs, exact and verified\n\nusage:\n\
                 {VERIFY_USAGE}{EVAL_USAGE}{BSDF_USAGE}{ALBEDO_USAGE}{TABLE_USAGE}{LUT_USAGE}{SAMPLE_USAGE}{REPORT_USAGE}{USAGE_TAIL}",
                env!("CARGO_PKG_VERSION")
            );
            Ok(ExitCode::SUCCESS)
        }
        Some("-V" | "--version") => {
            println!("microsurface {}", env!("CARGO_PKG_VERSION"));
            Ok(ExitCode::SUCCESS)
        }
        None => Err("no command given (try `microsurface --help`)".to_string()),
        Some(other) => Err(format!(
            "unknown command '{}' (try `microsurface --help`)",
            clip(other)
        )),
    };
    match result {
        Ok(code) => code,
        Err(msg) => {
            eprintln!("microsurface: {msg}");
            ExitCode::from(2)
        }
    }
}

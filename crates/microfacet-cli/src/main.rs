//! `microfacet`: the command-line face of the library. One file per subcommand; this file only
//! dispatches and turns failures into one-line messages with a non-zero exit code.

mod eval;
mod report;
mod sample;
mod svg;
mod verify;

use std::process::ExitCode;

const USAGE: &str = "\
microfacet — microfacet NDFs, exact and verified

usage:
  microfacet verify [--ndf LIST] [--alpha LIST] [--gamma LIST]
      check every identity of the source pages by numerical integration;
      one line per check (PASS/FAIL, residual); exit 1 if any fails.
      LIST is comma-separated, e.g. --ndf ggx,gtr --alpha 0.1,0.5 --gamma 1,1.5
  microfacet eval
      JSON lines in, JSON lines out, e.g.
      {\"ndf\":\"gtr\",\"alpha\":0.3,\"gamma\":1.5,\"quantity\":\"lambda\",\"u\":0.5} -> {\"value\":...}
      quantities: d, sigma, lambda, g1 (u); p22 (p, q); p2 (p); f (x); g2 (u_o, u_i)
  microfacet sample --ndf NAME --alpha A [--alpha-y AY] [--gamma G] [--mode dcos|visible]
                    [--wi X,Y,Z] [--n N] [--seed S]
      write N sampled normals (default 100000), one `x y z` per line; D·cos (default)
      or visible normals for the incident direction --wi (default 0,0,1)
  microfacet report [--out DIR]
      write DIR/index.html (default report/): every NDF's quantities, identities,
      superpositions and sample histograms as inline SVG plots, and the verify table
  microfacet --help
";

fn main() -> ExitCode {
    // A panic is a bug, but the user still gets one line, not a backtrace.
    std::panic::set_hook(Box::new(|info| {
        eprintln!("microfacet: internal error: {info}");
    }));
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("verify") => verify::run(&args[1..]),
        Some("eval") => eval::run(&args[1..]),
        Some("sample") => sample::run(&args[1..]),
        Some("report") => report::run(&args[1..]),
        Some("-h" | "--help" | "help") => {
            print!("{USAGE}");
            Ok(ExitCode::SUCCESS)
        }
        None => Err("no command given (try `microfacet --help`)".to_string()),
        Some(other) => Err(format!(
            "unknown command '{other}' (try `microfacet --help`)"
        )),
    };
    match result {
        Ok(code) => code,
        Err(msg) => {
            eprintln!("microfacet: {msg}");
            ExitCode::from(2)
        }
    }
}

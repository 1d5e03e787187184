//! `microsurface report`: the page is complete (every NDF section, every plot with drawn data,
//! no scripts, nothing fetched from the network) and renders in a real browser (headless
//! Debian Chromium: no console errors, same DOM, a screenshot). Chromium is required when CI
//! is set (.ci/run installs it); elsewhere the browser half is skipped with a message.

use std::path::{Path, PathBuf};
use std::process::Command;

const SECTIONS: [&str; 9] = [
    "beckmann",
    "ggx",
    "gtr",
    "double_ggx",
    "exponential",
    "comparison",
    "verify",
    "bsdf",
    "multiple-scattering",
];

/// The browser half of the legend check (see `report_is_complete_and_renders`).
const LEGEND_CHECK: &str = r#"
const out = {plots: 0, legends: 0, vertices: 0, covered: []};
document.querySelectorAll('svg.plot').forEach((svg, i) => {
  out.plots++;
  const boxes = [...svg.querySelectorAll('.legend-box')].map(r => r.getBBox());
  out.legends += boxes.length;
  const pts = [];
  svg.querySelectorAll('polyline.data').forEach(p => {
    for (let k = 0; k < p.points.numberOfItems; k++) {
      const q = p.points.getItem(k); pts.push([q.x, q.y]);
    }
  });
  svg.querySelectorAll('circle.data').forEach(c => pts.push([c.cx.baseVal.value, c.cy.baseVal.value]));
  svg.querySelectorAll('path.data, rect.data').forEach(e => {
    const b = e.getBBox();
    pts.push([b.x, b.y], [b.x + b.width, b.y], [b.x, b.y + b.height], [b.x + b.width, b.y + b.height]);
  });
  out.vertices += pts.length;
  for (const b of boxes) {
    for (const [x, y] of pts) {
      if (x >= b.x && x <= b.x + b.width && y >= b.y && y <= b.y + b.height) {
        out.covered.push({plot: i, title: svg.getAttribute('aria-label'), x, y});
        break;
      }
    }
  }
});
const pre = document.createElement('pre');
pre.id = 'legend-check';
pre.textContent = JSON.stringify(out);
document.body.appendChild(pre);
"#;

fn svgs(html: &str) -> Vec<&str> {
    html.split("<svg")
        .skip(1)
        .map(|s| s.split("</svg>").next().unwrap())
        .collect()
}

fn chromium() -> Option<PathBuf> {
    ["chromium", "chromium-browser"].iter().find_map(|name| {
        let out = Command::new("which").arg(name).output().ok()?;
        out.status
            .success()
            .then(|| PathBuf::from(String::from_utf8_lossy(&out.stdout).trim()))
    })
}

fn headless(chrome: &Path, profile: &Path, extra: &[&str], url: &str) -> std::process::Output {
    Command::new(chrome)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
            "--enable-logging=stderr",
            "--v=0",
            "--virtual-time-budget=5000",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(extra)
        .arg(url)
        .output()
        .expect("chromium runs")
}

#[test]
fn report_is_complete_and_renders() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report");
    let out = Command::new(env!("CARGO_BIN_EXE_microsurface"))
        .args(["report", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("section exponential") && stderr.contains("wrote"),
        "progress: {stderr}"
    );
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();

    for id in SECTIONS {
        assert!(
            html.contains(&format!("<section id=\"{id}\"")),
            "section {id} missing"
        );
    }
    assert!(!html.contains("<script"), "the page needs no scripts");
    assert!(html.contains("<figcaption>"), "plots have captions");
    assert!(
        html.contains(&format!("microsurface {}", env!("CARGO_PKG_VERSION"))),
        "version stamp"
    );
    assert!(
        html.contains("<details>"),
        "the full identity list is folded"
    );
    assert!(
        !html.contains("<h2>double_ggx</h2>"),
        "headings are names, not code names"
    );
    assert!(
        !html.contains("src=\"http") && !html.contains("href=\"http"),
        "nothing from the network"
    );
    let plots = svgs(&html);
    assert!(plots.len() >= 60, "{} plots", plots.len());
    for (i, svg) in plots.iter().enumerate() {
        let data = svg.matches("class=\"data\"").count();
        assert!(
            data > 0,
            "plot {i} has no data: {}",
            &svg[..svg.len().min(300)]
        );
        assert!(svg.contains("<text"), "plot {i} has no axis labels");
    }
    assert!(
        html.contains(" 0 failed</h2>"),
        "the identity table has failures"
    );

    let Some(chrome) = chromium() else {
        assert!(
            std::env::var_os("CI").is_none(),
            "CI must install chromium (.ci/run does)"
        );
        eprintln!("chromium not found: skipping the browser check");
        return;
    };
    let url = format!("file://{}", dir.join("index.html").display());
    let profile = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("chromium-profile");
    let dom = headless(&chrome, &profile, &["--dump-dom"], &url);
    assert!(
        dom.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&dom.stderr)
    );
    let dom_text = String::from_utf8_lossy(&dom.stdout);
    let log = String::from_utf8_lossy(&dom.stderr);
    for bad in ["CONSOLE", "Uncaught", "Failed to load"] {
        assert!(!log.contains(bad), "browser log has {bad}: {log}");
    }
    for id in SECTIONS {
        assert!(
            dom_text.contains(&format!("id=\"{id}\"")),
            "rendered DOM lacks {id}"
        );
    }
    assert_eq!(svgs(&dom_text).len(), plots.len(), "rendered plots");

    // Legends never cover data: a copy of the page with a script that, after layout, tests
    // every vertex of every data polyline, marker and bar corner of each plot against its
    // legend box (in the SVG's own coordinates), and writes the verdict into the DOM.
    let check = dir.join("legend-check.html");
    std::fs::write(
        &check,
        html.replace(
            "</body>",
            &format!("<script>{LEGEND_CHECK}</script></body>"),
        ),
    )
    .unwrap();
    let dom = headless(
        &chrome,
        &profile,
        &["--dump-dom"],
        &format!("file://{}", check.display()),
    );
    let dom_text = String::from_utf8_lossy(&dom.stdout);
    let verdict = dom_text
        .split("<pre id=\"legend-check\">")
        .nth(1)
        .and_then(|s| s.split("</pre>").next())
        .expect("the legend check ran");
    let v: serde_json::Value = serde_json::from_str(&verdict.replace("&quot;", "\"")).unwrap();
    assert_eq!(v["plots"].as_u64(), Some(plots.len() as u64), "{v}");
    assert!(
        v["legends"].as_u64().unwrap() >= plots.len() as u64 - 1,
        "{v}"
    );
    assert!(v["vertices"].as_u64().unwrap() > 10_000, "{v}");
    assert_eq!(v["covered"].as_array().map(Vec::len), Some(0), "{v}");

    let shot = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report.png");
    let s = headless(
        &chrome,
        &profile,
        &[
            "--window-size=1400,3000",
            &format!("--screenshot={}", shot.display()),
        ],
        &url,
    );
    assert!(s.status.success());
    let png = std::fs::read(&shot).unwrap();
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 50_000,
        "screenshot of {} bytes",
        png.len()
    );
}

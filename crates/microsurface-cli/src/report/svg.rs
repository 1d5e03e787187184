//! Hand-written SVG line plots for the report: axes with "nice" ticks, labels, a legend, linear
//! or logarithmic y, lines, dashed lines, two kinds of markers and histograms, and a caption
//! (formula and source) under each. Every data-bearing element carries `class="data"` so that
//! tests can check a plot is not an empty frame; the legend sits below the plot area, in a box
//! of its own (`class="legend-box"`), so it never covers data (the browser test checks that no
//! legend box contains a vertex of a data path or a marker), and its swatches are drawn in
//! their series' style (solid, dashed, circles, crosses, bars).

use std::fmt::Write;

const W: f64 = 440.0;
const H: f64 = 300.0;
const LEFT: f64 = 62.0;
const RIGHT: f64 = 12.0;
const TOP: f64 = 30.0;
const BOTTOM: f64 = 46.0;
const COLORS: [&str; 7] = [
    "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b",
];

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Style {
    Line,
    Dashed,
    Markers,
    /// Crosses, for a second marker series over the first (circles).
    Crosses,
    /// Histogram bars: points are (bin centre, height) with equal bin widths.
    Bars,
}

/// One curve.
#[derive(Clone, Debug)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub style: Style,
    /// The palette index (default: the series' position), so that markers can share the
    /// colour of the line they check.
    pub color: Option<usize>,
}

impl Series {
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, style: Style) -> Self {
        Series {
            label: label.into(),
            points,
            style,
            color: None,
        }
    }

    pub fn color(mut self, k: usize) -> Self {
        self.color = Some(k);
        self
    }
}

/// A plot.
#[derive(Clone, Debug, Default)]
pub struct Plot {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub log_y: bool,
    pub series: Vec<Series>,
    /// What is plotted, its formula and its source (HTML-escaped when rendered).
    pub caption: String,
    /// One unit is as long on x as on y (polar plots drawn as curves in a plane).
    pub equal: bool,
}

impl Plot {
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Plot {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            ..Plot::default()
        }
    }

    pub fn log_y(mut self) -> Self {
        self.log_y = true;
        self
    }

    pub fn with(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }

    /// Equal scales on x and y: the ranges are widened about their centres until a unit
    /// spans as many pixels on both axes.
    pub fn equal_aspect(mut self) -> Self {
        self.equal = true;
        self
    }

    pub fn caption(mut self, text: impl Into<String>) -> Self {
        self.caption = text.into();
        self
    }

    /// The plot and its caption as an HTML `<figure>`.
    pub fn to_html(&self) -> String {
        format!(
            "<figure>{}<figcaption>{}</figcaption></figure>",
            self.to_svg(),
            esc(&self.caption)
        )
    }

    /// The y value as plotted (log10 on a log axis; None if not plottable).
    fn ty(&self, y: f64) -> Option<f64> {
        if !y.is_finite() {
            return None;
        }
        if self.log_y {
            if y > 0.0 {
                Some(y.log10())
            } else {
                None
            }
        } else {
            Some(y)
        }
    }

    /// Renders the plot as an inline `<svg>` element.
    pub fn to_svg(&self) -> String {
        let pts: Vec<(f64, f64)> = self
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter_map(|&(x, y)| Some((x, self.ty(y)?)))
            .filter(|(x, _)| x.is_finite())
            .collect();
        let (mut x0, mut x1) = bounds(pts.iter().map(|p| p.0));
        let (mut y0, mut y1) = bounds(pts.iter().map(|p| p.1));
        if self.series.iter().any(|s| s.style == Style::Bars) && !self.log_y {
            y0 = y0.min(0.0);
        }
        if self.log_y {
            // At most 12 decades below the maximum: deeper tails are not readable.
            y0 = y0.max(y1 - 12.0).floor();
            y1 = y1.ceil();
        }
        pad(&mut x0, &mut x1, 0.0);
        pad(&mut y0, &mut y1, if self.log_y { 0.0 } else { 0.04 });
        if self.equal && !self.log_y {
            // Units per pixel on each axis; the smaller is widened to the larger.
            let (wx, wy) = (W - LEFT - RIGHT, H - TOP - BOTTOM);
            let k = ((x1 - x0) / wx).max((y1 - y0) / wy);
            let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
            (x0, x1) = (cx - 0.5 * k * wx, cx + 0.5 * k * wx);
            (y0, y1) = (cy - 0.5 * k * wy, cy + 0.5 * k * wy);
        }
        let px = |x: f64| LEFT + (x - x0) / (x1 - x0) * (W - LEFT - RIGHT);
        let py = |y: f64| H - BOTTOM - (y.clamp(y0, y1) - y0) / (y1 - y0) * (H - TOP - BOTTOM);

        // The legend: below the plot area, one entry per series, two columns beyond three.
        let cols = if self.series.len() > 3 { 2 } else { 1 };
        let rows = self.series.len().div_ceil(cols);
        let legend_h = if rows == 0 {
            0.0
        } else {
            14.0 * rows as f64 + 8.0
        };
        let total_h = H + legend_h;
        let mut s = String::new();
        let _ = write!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" class="plot" viewBox="0 0 {W} {total_h}" width="{W}" height="{total_h}" role="img" aria-label="{}">"#,
            esc(&self.title)
        );
        let _ = write!(
            s,
            r##"<rect x="{LEFT}" y="{TOP}" width="{}" height="{}" fill="#fff" stroke="#444"/>"##,
            W - LEFT - RIGHT,
            H - TOP - BOTTOM
        );
        // Ticks and grid.
        for t in ticks(x0, x1) {
            let x = px(t);
            let _ = write!(
                s,
                r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{}" stroke="#e4e4e4"/><text x="{x:.1}" y="{}" font-size="11" text-anchor="middle">{}</text>"##,
                H - BOTTOM,
                H - BOTTOM + 14.0,
                fmt_tick(t)
            );
        }
        let yt = if self.log_y {
            let step = ((y1 - y0) / 6.0).ceil().max(1.0);
            let mut v = Vec::new();
            let mut t = y0.ceil();
            while t <= y1 + 1e-9 {
                v.push(t);
                t += step;
            }
            v
        } else {
            ticks(y0, y1)
        };
        for t in yt {
            let y = py(t);
            let label = if self.log_y {
                format!("1e{}", t as i64)
            } else {
                fmt_tick(t)
            };
            let _ = write!(
                s,
                r##"<line x1="{LEFT}" y1="{y:.1}" x2="{}" y2="{y:.1}" stroke="#e4e4e4"/><text x="{}" y="{:.1}" font-size="11" text-anchor="end">{label}</text>"##,
                W - RIGHT,
                LEFT - 4.0,
                y + 4.0
            );
        }
        let _ = write!(
            s,
            r#"<text x="{}" y="18" font-size="13" font-weight="bold" text-anchor="middle">{}</text>"#,
            W / 2.0,
            esc(&self.title)
        );
        let _ = write!(
            s,
            r#"<text x="{}" y="{}" font-size="12" text-anchor="middle">{}</text>"#,
            (LEFT + W - RIGHT) / 2.0,
            H - 10.0,
            esc(&self.x_label)
        );
        let _ = write!(
            s,
            r#"<text x="14" y="{}" font-size="12" text-anchor="middle" transform="rotate(-90 14 {})">{}</text>"#,
            (TOP + H - BOTTOM) / 2.0,
            (TOP + H - BOTTOM) / 2.0,
            esc(&self.y_label)
        );
        // Data.
        for (k, series) in self.series.iter().enumerate() {
            let c = COLORS[series.color.unwrap_or(k) % COLORS.len()];
            let visible: Vec<(f64, f64)> = series
                .points
                .iter()
                .filter_map(|&(x, y)| Some((x, self.ty(y)?)))
                .filter(|(x, y)| x.is_finite() && *y >= y0 - 1e-9)
                .collect();
            match series.style {
                Style::Line | Style::Dashed => {
                    let dash = if series.style == Style::Dashed {
                        r#" stroke-dasharray="5 3""#
                    } else {
                        ""
                    };
                    let mut p = String::new();
                    for (x, y) in &visible {
                        let _ = write!(p, "{:.2},{:.2} ", px(*x), py(*y));
                    }
                    let _ = write!(
                        s,
                        r#"<polyline class="data" fill="none" stroke="{c}" stroke-width="1.6"{dash} points="{}"/>"#,
                        p.trim_end()
                    );
                }
                Style::Markers => {
                    for (x, y) in &visible {
                        circle(&mut s, "data", px(*x), py(*y), c);
                    }
                }
                Style::Crosses => {
                    for (x, y) in &visible {
                        cross(&mut s, "data", px(*x), py(*y), c);
                    }
                }
                Style::Bars => {
                    let w = if visible.len() > 1 {
                        (px(visible[1].0) - px(visible[0].0)).abs()
                    } else {
                        4.0
                    };
                    let base = py(if self.log_y { y0 } else { 0.0f64.max(y0) });
                    for (x, y) in &visible {
                        let top = py(*y);
                        let _ = write!(
                            s,
                            r#"<rect class="data" x="{:.2}" y="{:.2}" width="{:.2}" height="{:.2}" fill="{c}" fill-opacity="0.35"/>"#,
                            px(*x) - w / 2.0,
                            top.min(base),
                            w,
                            (base - top).abs()
                        );
                    }
                }
            }
        }
        // The legend, in its own box below the axis label.
        if !self.series.is_empty() {
            let _ = write!(
                s,
                r##"<g class="legend"><rect class="legend-box" x="{LEFT}" y="{H}" width="{}" height="{:.1}" fill="#fff" stroke="#ccc"/>"##,
                W - LEFT - RIGHT,
                legend_h - 4.0
            );
            let col_w = (W - LEFT - RIGHT) / cols as f64;
            for (k, series) in self.series.iter().enumerate() {
                let c = COLORS[series.color.unwrap_or(k) % COLORS.len()];
                let lx = LEFT + 8.0 + col_w * (k / rows) as f64;
                let ly = H + 10.0 + 14.0 * (k % rows) as f64;
                swatch(&mut s, series.style, lx, ly, c);
                let _ = write!(
                    s,
                    r#"<text x="{:.1}" y="{:.1}" font-size="10">{}</text>"#,
                    lx + 26.0,
                    ly + 3.5,
                    esc(&series.label)
                );
            }
            s.push_str("</g>");
        }
        s.push_str("</svg>");
        s
    }
}

/// A marker circle at (x, y).
fn circle(s: &mut String, class: &str, x: f64, y: f64, c: &str) {
    let _ = write!(
        s,
        r#"<circle class="{class}" cx="{x:.2}" cy="{y:.2}" r="2.6" fill="none" stroke="{c}"/>"#
    );
}

/// A marker cross (×) centred at (x, y).
fn cross(s: &mut String, class: &str, x: f64, y: f64, c: &str) {
    let _ = write!(
        s,
        r#"<path class="{class}" d="M{:.2} {:.2}l6 6m0 -6l-6 6" stroke="{c}" stroke-width="1.3" fill="none"/>"#,
        x - 3.0,
        y - 3.0
    );
}

/// A legend swatch for `style`, 20 units wide, centred vertically on y.
fn swatch(s: &mut String, style: Style, x: f64, y: f64, c: &str) {
    match style {
        Style::Line | Style::Dashed => {
            let dash = if style == Style::Dashed {
                r#" stroke-dasharray="5 3""#
            } else {
                ""
            };
            let _ = write!(
                s,
                r#"<line x1="{x:.1}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="{c}" stroke-width="1.6"{dash}/>"#,
                x + 20.0
            );
        }
        Style::Markers => {
            circle(s, "swatch", x + 5.0, y, c);
            circle(s, "swatch", x + 15.0, y, c);
        }
        Style::Crosses => {
            cross(s, "swatch", x + 5.0, y, c);
            cross(s, "swatch", x + 15.0, y, c);
        }
        Style::Bars => {
            let _ = write!(
                s,
                r#"<rect x="{x:.1}" y="{:.1}" width="20" height="8" fill="{c}" fill-opacity="0.35"/>"#,
                y - 4.0
            );
        }
    }
}

fn bounds(v: impl Iterator<Item = f64>) -> (f64, f64) {
    v.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    })
}

fn pad(lo: &mut f64, hi: &mut f64, frac: f64) {
    if !lo.is_finite() || !hi.is_finite() {
        *lo = 0.0;
        *hi = 1.0;
    }
    if *hi - *lo < 1e-12 {
        *lo -= 0.5;
        *hi += 0.5;
    }
    let d = (*hi - *lo) * frac;
    *lo -= d;
    *hi += d;
}

/// About six ticks at multiples of 1, 2 or 5 × 10^k.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let raw = (hi - lo) / 6.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let mut t = (lo / step).ceil() * step;
    let mut v = Vec::new();
    while t <= hi + 1e-9 * step {
        v.push(if t.abs() < 1e-12 * step { 0.0 } else { t });
        t += step;
    }
    v
}

fn fmt_tick(t: f64) -> String {
    let s = format!("{t:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.').to_string();
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// Escapes text for XML.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

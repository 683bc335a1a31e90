//! Second-order figures (`subdlab curvature --out`): the central ring (each
//! μ-eigenfunction as a colour map of heights over the characteristic ring,
//! one panel per eigenfunction; a Jordan chain's top says so in its title)
//! and the limit-surface curvature rings (input nets sampled from rotated
//! quadratics q_{t,θ} over the characteristic map, refined with the scheme's
//! rules, each ring's faces coloured by the sign of the Gaussian curvature
//! of a quadratic fitted to the refined control points around the face:
//! `curvature::figure`).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{err, square_window as window, tick_label, Figure, Style, FONT};
use crate::curvature::Curvature;
use crate::error::Error;

/// Which second-order figure to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurvatureFigureKind {
    CentralRing,
    Surface,
}

pub struct CurvatureFigure<'a> {
    pub c: &'a Curvature,
    pub kind: CurvatureFigureKind,
    pub style: Style,
}

/// Base font size of the figure (the subtitle), which `Style::font_size` replaces.
const BASE_FONT: u32 = 16;

const NEG: (f64, f64, f64) = (33.0, 102.0, 172.0);
const POS: (f64, f64, f64) = (178.0, 24.0, 43.0);

/// Diverging colour map: −1 blue, 0 white, +1 red.
fn diverging(t: f64) -> RGBColor {
    let t = if t.is_finite() { t.clamp(-1.0, 1.0) } else { 0.0 };
    let (c, a) = if t < 0.0 { (NEG, -t) } else { (POS, t) };
    let mix = |x: f64| (255.0 + (x - 255.0) * a).round() as u8;
    RGBColor(mix(c.0), mix(c.1), mix(c.2))
}

impl Figure for CurvatureFigure<'_> {
    fn size(&self) -> (u32, u32) {
        self.style.size(self.own_size())
    }
    fn dpi(&self) -> Option<f64> {
        self.style.dpi
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        self.draw_figure(root)
    }
}

impl CurvatureFigure<'_> {
    fn own_size(&self) -> (u32, u32) {
        match self.kind {
            CurvatureFigureKind::CentralRing => {
                let panels = self.c.figures.as_ref().map_or(1, |f| f.mu_functions.len().max(1)) as u32;
                let cols = panels.min(3);
                let rows = panels.div_ceil(3);
                (cols * 420 + 20, rows * 440 + 90)
            }
            CurvatureFigureKind::Surface => {
                let surface = self.c.figures.as_ref().map(|f| &f.surface);
                let rings = surface.and_then(|s| s.first()).map_or(1, |s| s.rings.len().max(1));
                let rows = surface.map_or(2, |s| s.len().max(1));
                (rings as u32 * 300 + 140, rows as u32 * 320 + 110)
            }
        }
    }
    fn draw_figure<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let c = self.c;
        let font = |own: u32| self.style.font(own, BASE_FONT);
        let data = c
            .figures
            .as_ref()
            .ok_or_else(|| Error::Input("no curvature figure data (the analysis stopped before the ring)".into()))?;
        root.fill(&WHITE).map_err(err)?;
        let mu = c.mu.as_ref().map_or("none".to_string(), |m| format!("{:.6}", m.modulus));
        // the class (the verdict) is in the table and the JSON, not drawn
        let title = self.style.title(format!(
            "{} n = {}: λ = {:.6}, |μ| = {mu}",
            c.scheme,
            c.valence,
            c.lambda.unwrap_or(f64::NAN)
        ));
        let title_height = title.as_ref().map_or(0, |_| font(24) as i32 + 16);
        let (top, rest) = root.split_vertically(title_height + font(16) as i32 + 30);
        if let Some(title) = title {
            top.draw(&Text::new(title, (20, 12), (FONT, font(24)).into_font())).map_err(err)?;
        }
        let subtitle_at = (20, title_height + 12);
        match self.kind {
            CurvatureFigureKind::CentralRing => {
                top.draw(&Text::new(
                    "central ring: μ-eigenfunctions as heights over the characteristic ring (blue < 0 < red)",
                    subtitle_at,
                    (FONT, font(16)).into_font(),
                ))
                .map_err(err)?;
                if data.mu_functions.is_empty() {
                    return Err(Error::Input("no μ-eigenfunction to draw".into()));
                }
                let (center, half) = window(data.triangles.iter().flatten().copied())
                    .ok_or_else(|| Error::Input("nothing to draw".into()))?;
                let cols = data.mu_functions.len().min(3);
                let rows = data.mu_functions.len().div_ceil(3);
                let panels = rest.split_evenly((rows, cols));
                for ((label, values), area) in data.mu_functions.iter().zip(panels.iter()) {
                    let top = values.iter().flatten().map(|v| v.abs()).fold(0.0, f64::max).max(1e-300);
                    let mut chart = ChartBuilder::on(area)
                        .margin(10)
                        .caption(label, (FONT, font(15)))
                        .x_label_area_size(25)
                        .y_label_area_size(40)
                        .build_cartesian_2d(center.0 - half..center.0 + half, center.1 - half..center.1 + half)
                        .map_err(err)?;
                    let span = 2.0 * half;
                    chart
                        .configure_mesh()
                        .disable_mesh()
                        .label_style((FONT, font(12)))
                        .x_label_formatter(&|v| tick_label(*v, span))
                        .y_label_formatter(&|v| tick_label(*v, span))
                        .draw()
                        .map_err(err)?;
                    chart
                        .draw_series(data.triangles.iter().zip(values).map(|(t, v)| {
                            let mean = (v[0] + v[1] + v[2]) / (3.0 * top);
                            let colour = diverging(mean);
                            Polygon::new(t.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>(), colour.filled())
                        }))
                        .map_err(err)?;
                }
            }
            CurvatureFigureKind::Surface => {
                top.draw(&Text::new(
                    "limit surface from sampled quadratics, ring k (scaled by 1/λ^k): sign of Gaussian curvature \
                     of a fitted quadratic (red > 0 elliptic, blue < 0 hyperbolic)",
                    subtitle_at,
                    (FONT, font(15)).into_font(),
                ))
                .map_err(err)?;
                if data.surface.is_empty() {
                    return Err(Error::Input("no limit-surface rings computed".into()));
                }
                let rows = data.surface.len();
                let cols = data.surface[0].rings.len().max(1);
                let (labels, grid) = rest.split_horizontally(140);
                let label_rows = labels.split_evenly((rows, 1));
                let panels = grid.split_evenly((rows, cols));
                for (r, s) in data.surface.iter().enumerate() {
                    // the input (t, θ) and its own sign, which a ring far from the centre shows
                    let own = match s.quadratic.sign() {
                        1 => "elliptic",
                        -1 => "hyperbolic",
                        _ => "parabolic",
                    };
                    for (i, line) in [
                        format!("t = {}", s.quadratic.t),
                        format!("θ = {}°", s.quadratic.theta_degrees),
                        format!("({own})"),
                    ]
                    .into_iter()
                    .enumerate()
                    {
                        label_rows[r]
                            .draw(&Text::new(line, (10, 130 + 22 * i as i32), (FONT, font(16)).into_font()))
                            .map_err(err)?;
                    }
                    for (k, ring) in s.rings.iter().enumerate() {
                        let area = &panels[r * cols + k];
                        let (center, half) = window(ring.iter().flat_map(|(p, _)| p.iter().copied()))
                            .ok_or_else(|| Error::Input("nothing to draw".into()))?;
                        let mut chart = ChartBuilder::on(area)
                            .margin(8)
                            .caption(format!("ring {k}"), (FONT, font(15)))
                            .build_cartesian_2d(center.0 - half..center.0 + half, center.1 - half..center.1 + half)
                            .map_err(err)?;
                        chart
                            .draw_series(ring.iter().map(|(p, sign)| {
                                let colour = match sign {
                                    1 => RGBColor(214, 96, 77),
                                    -1 => RGBColor(67, 147, 195),
                                    _ => RGBColor(200, 200, 200),
                                };
                                Polygon::new(p.iter().map(|q| (q[0], q[1])).collect::<Vec<_>>(), colour.filled())
                            }))
                            .map_err(err)?;
                    }
                }
            }
        }
        Ok(())
    }
}

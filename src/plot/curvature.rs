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

use super::layout::MARGIN;
use super::layout::{
    block_height, draw_lines, em, fit, plan_axes, region_area, text_width, title_lines, Axis, NoFit, Ticks,
};
use super::{err, square_window as window, tick_label, Figure, Style};
use crate::curvature::Curvature;
use crate::error::Error;
use plotters::style::text_anchor::HPos;

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
    fn data_csv(&self) -> Result<String, Error> {
        use super::{csv_field, csv_number};
        let data = self.c.figures.as_ref().ok_or_else(|| Error::Input("no curvature figure data".into()))?;
        let mut out = String::new();
        match self.kind {
            CurvatureFigureKind::CentralRing => {
                // each μ-eigenfunction's value at each corner of each triangle
                out += "function,triangle,corner,x,y,value\n";
                for (label, values) in &data.mu_functions {
                    for (i, (t, v)) in data.triangles.iter().zip(values).enumerate() {
                        for j in 0..3 {
                            let (x, y, z) = (csv_number(t[j][0]), csv_number(t[j][1]), csv_number(v[j]));
                            out += &format!("{},{i},{j},{x},{y},{z}\n", csv_field(label));
                        }
                    }
                }
            }
            CurvatureFigureKind::Surface => {
                // each ring's faces with the sign of K drawn for them
                out += "input,ring,face,vertex,x,y,sign\n";
                for s in &data.surface {
                    for (k, ring) in s.rings.iter().enumerate() {
                        for (f, (poly, sign)) in ring.iter().enumerate() {
                            for (v, q) in poly.iter().enumerate() {
                                let (x, y) = (csv_number(q[0]), csv_number(q[1]));
                                out += &format!("{},{k},{f},{v},{x},{y},{sign}\n", csv_field(&s.input));
                            }
                        }
                    }
                }
            }
        }
        Ok(out)
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
    fn subtitle(&self) -> &'static str {
        match self.kind {
            CurvatureFigureKind::CentralRing => {
                "central ring: μ-eigenfunctions as heights over the characteristic ring (blue < 0 < red)"
            }
            CurvatureFigureKind::Surface => {
                "limit surface from sampled quadratics, ring k (scaled by 1/λ^k): sign of Gaussian curvature \
                 of a fitted quadratic (red > 0 elliptic, blue < 0 hyperbolic)"
            }
        }
    }

    /// The text lines of a surface row: the input (t, θ) and its own sign,
    /// which a ring far from the centre shows.
    fn row_labels(s: &crate::curvature::SurfaceRows) -> Vec<String> {
        let own = match s.quadratic.sign() {
            1 => "elliptic",
            -1 => "hyperbolic",
            _ => "parabolic",
        };
        vec![format!("t = {}", s.quadratic.t), format!("θ = {}°", s.quadratic.theta_degrees), format!("({own})")]
    }

    /// Place everything at font scale `scale`: the header's lines, and each
    /// panel's caption lines, caption top, and square (x0, y0, side) in
    /// figure coordinates, with the panel's axes when it has them.
    fn plan(
        &self,
        scale: f64,
        data: &crate::curvature::FigureData,
        header: (Option<String>, &str),
    ) -> Result<Plan, NoFit> {
        let font = |own: u32| self.style.font(own, BASE_FONT) as f64 * scale;
        let (w, h) = self.size();
        let (w, h) = (w as f64, h as f64);
        let (title_size, sub_size) = (font(24), font(if self.kind == CurvatureFigureKind::Surface { 15 } else { 16 }));
        let title = match &header.0 {
            Some(t) => title_lines(t, title_size, w - 2.0 * MARGIN, 3)?,
            None => Vec::new(),
        };
        let subtitle = title_lines(header.1, sub_size, w - 2.0 * MARGIN, 5)?;
        let mut top = MARGIN;
        if !title.is_empty() {
            top += block_height(title.len(), title_size) + 0.3 * em(title_size);
        }
        let subtitle_top = top;
        top += block_height(subtitle.len(), sub_size) + 0.6 * em(sub_size);
        let caption_size = font(15);
        let mut panels = Vec::new();
        let mut row_labels = Vec::new();
        let (rows, cols, left) = match self.kind {
            CurvatureFigureKind::CentralRing => {
                let n = data.mu_functions.len();
                (n.div_ceil(3), n.min(3), MARGIN)
            }
            CurvatureFigureKind::Surface => {
                let label_size = font(16);
                let widest = data
                    .surface
                    .iter()
                    .flat_map(Self::row_labels)
                    .map(|l| text_width(&l, label_size))
                    .fold(0.0, f64::max);
                (
                    data.surface.len(),
                    data.surface.first().map_or(1, |s| s.rings.len().max(1)),
                    MARGIN + widest + em(label_size),
                )
            }
        };
        let (pw, ph) = ((w - left - MARGIN) / cols as f64, (h - top - MARGIN) / rows.max(1) as f64);
        if let CurvatureFigureKind::Surface = self.kind {
            let label_size = font(16);
            if block_height(3, label_size) > ph {
                return Err(NoFit("the row labels".into()));
            }
            for (r, s) in data.surface.iter().enumerate() {
                let y = top + r as f64 * ph + (ph - block_height(3, label_size)) / 2.0;
                row_labels.push((Self::row_labels(s), (MARGIN, y), label_size));
            }
        }
        let count = match self.kind {
            CurvatureFigureKind::CentralRing => data.mu_functions.len(),
            CurvatureFigureKind::Surface => rows * cols,
        };
        for k in 0..count {
            let (r, c) = (k / cols, k % cols);
            let (px, py) = (left + c as f64 * pw, top + r as f64 * ph);
            let inner = pw - 0.6 * em(caption_size);
            let caption = match self.kind {
                CurvatureFigureKind::CentralRing => data.mu_functions[k].0.clone(),
                CurvatureFigureKind::Surface => format!("ring {c}"),
            };
            let caption = title_lines(&caption, caption_size, inner, 3)?;
            let cap_h = block_height(caption.len(), caption_size) + 0.3 * em(caption_size);
            let avail = (inner, ph - cap_h - 0.4 * em(caption_size));
            if avail.1 < 10.0 || avail.0 < 10.0 {
                return Err(NoFit("the panels".into()));
            }
            panels.push(Panel {
                caption,
                caption_top: py,
                centre_x: px + pw / 2.0,
                area: (px + 0.3 * em(caption_size), py + cap_h, avail.0, avail.1),
            });
        }
        Ok(Plan {
            title,
            title_size,
            subtitle,
            subtitle_top,
            sub_size,
            caption_size,
            label_size: font(12),
            row_labels,
            panels,
        })
    }

    fn draw_figure<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let c = self.c;
        let data = c
            .figures
            .as_ref()
            .ok_or_else(|| Error::Input("no curvature figure data (the analysis stopped before the ring)".into()))?;
        match self.kind {
            CurvatureFigureKind::CentralRing if data.mu_functions.is_empty() => {
                return Err(Error::Input("no μ-eigenfunction to draw".into()))
            }
            CurvatureFigureKind::Surface if data.surface.is_empty() => {
                return Err(Error::Input("no limit-surface rings computed".into()))
            }
            _ => {}
        }
        root.fill(&WHITE).map_err(err)?;
        let mu = c.mu.as_ref().map_or("none".to_string(), |m| format!("{:.6}", m.modulus));
        // the class (the verdict) is in the table and the JSON, not drawn
        let title = self.style.title(format!(
            "{} n = {}: λ = {:.6}, |μ| = {mu}",
            c.scheme,
            c.valence,
            c.lambda.unwrap_or(f64::NAN)
        ));
        let (center, half) = match self.kind {
            CurvatureFigureKind::CentralRing => window(data.triangles.iter().flatten().copied()),
            CurvatureFigureKind::Surface => Some(((0.0, 0.0), 1.0)),
        }
        .ok_or_else(|| Error::Input("nothing to draw".into()))?;
        let (xr, yr) = ((center.0 - half, center.0 + half), (center.1 - half, center.1 + half));
        let span = 2.0 * half;
        let fmt = |v: f64| tick_label(v, span);
        let size = self.size();
        let header = (title, self.subtitle());
        let plan = fit(self.style.font(BASE_FONT, BASE_FONT) as f64, size, |scale| {
            let plan = self.plan(scale, data, (header.0.clone(), header.1))?;
            // the central ring's panels have axes: plan them now, so a
            // panel without room for its tick labels shrinks the text too
            let axes = match self.kind {
                CurvatureFigureKind::CentralRing => plan
                    .panels
                    .iter()
                    .map(|p| {
                        let x = Axis { range: xr, desc: None, ticks: Ticks::Auto(&fmt) };
                        let y = Axis { range: yr, desc: None, ticks: Ticks::Auto(&fmt) };
                        plan_axes((p.area.2, p.area.3), &x, &y, plan.label_size, plan.label_size, true).map(Some)
                    })
                    .collect::<Result<Vec<_>, NoFit>>()?,
                CurvatureFigureKind::Surface => plan.panels.iter().map(|_| None).collect(),
            };
            Ok((plan, axes))
        })?;
        let (plan, axes) = plan;
        draw_lines(root, &plan.title, plan.title_size, (MARGIN, MARGIN), HPos::Left)?;
        draw_lines(root, &plan.subtitle, plan.sub_size, (MARGIN, plan.subtitle_top), HPos::Left)?;
        for (lines, at, label_size) in &plan.row_labels {
            draw_lines(root, lines, *label_size, *at, HPos::Left)?;
        }
        let (w, h) = (size.0 as f64, size.1 as f64);
        for (k, (panel, axes)) in plan.panels.iter().zip(axes).enumerate() {
            draw_lines(root, &panel.caption, plan.caption_size, (panel.centre_x, panel.caption_top), HPos::Center)?;
            let (ax, ay, aw, ah) = panel.area;
            let margins = (ax, ay, w - ax - aw, h - ay - ah);
            let area = region_area(root, margins);
            match self.kind {
                CurvatureFigureKind::CentralRing => {
                    let Some(axes) = axes else { continue };
                    let values = &data.mu_functions[k].1;
                    axes.draw(&area, xr, yr, false)?;
                    let mut chart = axes.chart(&area, xr, yr)?;
                    let top = values.iter().flatten().map(|v| v.abs()).fold(0.0, f64::max).max(1e-300);
                    chart
                        .draw_series(data.triangles.iter().zip(values).map(|(t, v)| {
                            let mean = (v[0] + v[1] + v[2]) / (3.0 * top);
                            let colour = diverging(mean);
                            Polygon::new(t.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>(), colour.filled())
                        }))
                        .map_err(err)?;
                }
                CurvatureFigureKind::Surface => {
                    let cols = data.surface[0].rings.len().max(1);
                    let (r, col) = (k / cols, k % cols);
                    let Some(ring) = data.surface.get(r).and_then(|s| s.rings.get(col)) else { continue };
                    let (center, half) = window(ring.iter().flat_map(|(p, _)| p.iter().copied()))
                        .ok_or_else(|| Error::Input("nothing to draw".into()))?;
                    // a square of the panel, centred: equal scales
                    let side = aw.min(ah);
                    let sq = (ax + (aw - side) / 2.0, ay, side);
                    let square = region_area(root, (sq.0, sq.1, w - sq.0 - side, h - sq.1 - side));
                    let mut chart = ChartBuilder::on(&square)
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
        Ok(())
    }
}

/// A panel: its caption's lines, top and centre, and the area below the
/// caption (x, y, width, height) in figure coordinates.
struct Panel {
    caption: Vec<String>,
    caption_top: f64,
    centre_x: f64,
    area: (f64, f64, f64, f64),
}

/// The placed text of a curvature figure.
struct Plan {
    title: Vec<String>,
    title_size: f64,
    subtitle: Vec<String>,
    subtitle_top: f64,
    sub_size: f64,
    caption_size: f64,
    label_size: f64,
    row_labels: Vec<(Vec<String>, (f64, f64), f64)>,
    panels: Vec<Panel>,
}

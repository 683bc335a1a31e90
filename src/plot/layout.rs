//! Layout of a figure's text: every text is measured with the embedded
//! font's metrics (advance widths from plotters' ab_glyph backend; height
//! the font's ascent to descent) before anything is drawn, and placed so
//! that no text box overlaps another or leaves the canvas, whatever the
//! figure's size and font size.
//!
//! A figure lays itself out at its requested font size; when the content
//! does not fit (a legend wider than the canvas, tick labels with no room),
//! [`fit`] tries again with all text set smaller, step by step down to
//! [`MIN_BASE_FONT`], and only then refuses with a one-line error. Axes
//! (ticks, tick labels, axis descriptions) are drawn here, not by plotters'
//! mesh, whose label areas are fixed sizes that long labels overrun; the
//! number of ticks is the largest whose labels keep a gap between them.
//!
//! Metrics (DejaVu Sans): the SVG backend writes a plotters font size s as
//! `font-size` s / 1.24 (one em); a line of text spans the font's ascent
//! 0.928 em above the baseline to its descent 0.236 em below; a text drawn
//! with the top anchor has its baseline 0.76 em below the anchor (so its box
//! starts 0.17 em above it), with the centre anchor 0.25 em below.

use plotters::coord::ranged1d::Ranged;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::error::Error;

/// The family name figures use for text (the embedded font is registered
/// under it; `plot` re-exports it).
pub const FONT: &str = "sans-serif";

/// The outer margin of a figure, in points.
pub const MARGIN: f64 = 8.0;

/// A plotters error as one line (as `plot::err`; kept here so that this
/// file imports nothing of its folder).
fn err<E: std::fmt::Display>(e: E) -> Error {
    Error::Message(format!("cannot draw the figure: {e}"))
}

/// The smallest base font size the layout shrinks text to before refusing.
pub const MIN_BASE_FONT: f64 = 5.0;

/// The content did not fit at this font size (what, for the error).
#[derive(Debug)]
pub struct NoFit(pub String);

/// One em of a plotters font size `size`, in points.
pub fn em(size: f64) -> f64 {
    size / 1.24
}

/// Ascent to descent of the font, in ems.
const LINE: f64 = 0.928 + 0.236;
/// How far above a top-anchored text's anchor its box starts, in ems.
const ABOVE_TOP_ANCHOR: f64 = 0.928 - 0.76;

/// The height of a line of text's box.
pub fn line_box(size: f64) -> f64 {
    LINE * em(size)
}

/// The distance between lines of a block of text: the box and a gap.
pub fn line_step(size: f64) -> f64 {
    (LINE + 0.2) * em(size)
}

/// The width of `text` at `size`: the sum of the embedded font's advances
/// and kerning. Plotters scales the font to `size` as its ascent-to-descent
/// height, so this is 1.24 / 1.164 times the drawn width: an overestimate
/// of about 6 %, kept as a margin.
pub fn text_width(text: &str, size: f64) -> f64 {
    let font = FontDesc::new(FontFamily::Name(FONT), size, FontStyle::Normal);
    match font.box_size(text) {
        Ok((w, _)) => w as f64 + 1.0,
        // unknown font: a generous 0.7 em per character
        Err(_) => 0.7 * em(size) * text.chars().count() as f64,
    }
}

/// The text broken into lines at spaces so that each fits `width` (a word
/// wider than `width` on its own is broken between characters).
pub fn wrap(text: &str, size: f64, width: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let candidate = if line.is_empty() { word.to_string() } else { format!("{line} {word}") };
        if text_width(&candidate, size) <= width {
            line = candidate;
            continue;
        }
        if !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        // the word alone on a line, broken where it must be
        for c in word.chars() {
            line.push(c);
            if text_width(&line, size) > width && line.chars().count() > 1 {
                let last = line.pop().unwrap_or(' ');
                lines.push(std::mem::take(&mut line));
                line.push(last);
            }
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// The text drawn with its box's top-left corner (or top-centre) at (x, top).
pub fn draw_text<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
    (x, top): (f64, f64),
    h: HPos,
) -> Result<(), Error>
where
    DB::ErrorType: 'static,
{
    let style = TextStyle::from((FONT, size).into_font()).color(&BLACK).pos(Pos::new(h, VPos::Top));
    let y = top + ABOVE_TOP_ANCHOR * em(size);
    area.draw(&Text::new(text.to_string(), (x.round() as i32, y.ceil() as i32), style)).map_err(err)
}

/// Lines of text, one under the other, starting at `top`; the height used.
pub fn draw_lines<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    lines: &[String],
    size: f64,
    (x, top): (f64, f64),
    h: HPos,
) -> Result<f64, Error>
where
    DB::ErrorType: 'static,
{
    for (k, line) in lines.iter().enumerate() {
        draw_text(area, line, size, (x, top + k as f64 * line_step(size)), h)?;
    }
    Ok(block_height(lines.len(), size))
}

/// The height of `n` lines of text drawn by [`draw_lines`].
pub fn block_height(n: usize, size: f64) -> f64 {
    if n == 0 {
        0.0
    } else {
        (n - 1) as f64 * line_step(size) + line_box(size) + 1.0
    }
}

/// A figure's title (None: no title) wrapped to the figure's width less its
/// margins in at most three lines, and the height it takes with the gap
/// below it.
pub fn title_block(title: Option<String>, size: f64, figure_width: f64) -> Result<(Vec<String>, f64), NoFit> {
    let Some(t) = title else { return Ok((Vec::new(), 0.0)) };
    let lines = title_lines(&t, size, figure_width - 2.0 * MARGIN, 3)?;
    let height = if lines.is_empty() { 0.0 } else { block_height(lines.len(), size) + 0.4 * em(size) };
    Ok((lines, height))
}

/// A title (or subtitle) wrapped to `width`, or no fit when it would take
/// more than `max_lines` lines.
pub fn title_lines(text: &str, size: f64, width: f64, max_lines: usize) -> Result<Vec<String>, NoFit> {
    let lines = wrap(text, size, width);
    if lines.len() > max_lines {
        return Err(NoFit(format!("the title '{text}'")));
    }
    Ok(lines)
}

/// Try `layout` at the style's font sizes scaled by 1, 0.9, 0.81, … until it
/// fits, down to a base font size of [`MIN_BASE_FONT`] points.
pub fn fit<T>(base: f64, size: (u32, u32), layout: impl Fn(f64) -> Result<T, NoFit>) -> Result<T, Error> {
    let mut scale = 1.0;
    loop {
        match layout(scale) {
            Ok(t) => return Ok(t),
            Err(NoFit(what)) => {
                if base * scale * 0.9 < MIN_BASE_FONT {
                    return Err(Error::Input(format!(
                        "a {} × {} pt figure has no room for {what} even with {MIN_BASE_FONT} pt text; \
                         enlarge --width/--height or shorten the text",
                        size.0, size.1
                    )));
                }
                scale *= 0.9;
            }
        }
    }
}

/// A marker drawn at each data point of a curve (and in its legend entry).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    None,
    Circle,
    Square,
    TriangleUp,
    Diamond,
    TriangleDown,
    Cross,
}

/// What a legend entry shows before its text.
#[derive(Clone, Copy, Debug)]
pub enum Swatch {
    /// a line sample; `dash` (on, off) in points, a marker in its middle
    Line { colour: RGBColor, width: u32, dash: Option<(u32, u32)>, marker: Marker },
    /// a filled box with an outline
    Patch { fill: RGBColor, edge: RGBColor },
    /// a dot
    Dot(RGBColor),
}

/// A marker of `radius` at pixel (x, y) of `area`.
pub fn draw_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    marker: Marker,
    (x, y): (i32, i32),
    r: i32,
    colour: RGBColor,
) -> Result<(), Error>
where
    DB::ErrorType: 'static,
{
    let fill = colour.filled();
    let result = match marker {
        Marker::None => Ok(()),
        Marker::Circle => area.draw(&Circle::new((x, y), r, fill)),
        Marker::Square => area.draw(&Rectangle::new([(x - r, y - r), (x + r, y + r)], fill)),
        Marker::TriangleUp => {
            area.draw(&Polygon::new(vec![(x, y - r - 1), (x - r - 1, y + r), (x + r + 1, y + r)], fill))
        }
        Marker::TriangleDown => {
            area.draw(&Polygon::new(vec![(x, y + r + 1), (x - r - 1, y - r), (x + r + 1, y - r)], fill))
        }
        Marker::Diamond => {
            area.draw(&Polygon::new(vec![(x, y - r - 1), (x + r + 1, y), (x, y + r + 1), (x - r - 1, y)], fill))
        }
        Marker::Cross => area
            .draw(&PathElement::new(vec![(x - r, y - r), (x + r, y + r)], colour.stroke_width(2)))
            .and_then(|_| area.draw(&PathElement::new(vec![(x - r, y + r), (x + r, y - r)], colour.stroke_width(2)))),
    };
    result.map_err(err)
}

/// A dashed polyline (plotters' dashed series works in data coordinates;
/// this one in pixels, for legend samples).
fn dashed<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x0, x1, y): (i32, i32, i32),
    (on, off): (u32, u32),
    style: ShapeStyle,
) -> Result<(), Error>
where
    DB::ErrorType: 'static,
{
    let mut x = x0;
    while x < x1 {
        let end = (x + on as i32).min(x1);
        area.draw(&PathElement::new(vec![(x, y), (end, y)], style)).map_err(err)?;
        x = end + off as i32;
    }
    Ok(())
}

/// Where the legend goes: outside the plot (right of it or below it),
/// inside one of its corners, or nowhere.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LegendPosition {
    /// right of the plot when it fits there, else below it
    Auto,
    Right,
    Below,
    UpperRight,
    UpperLeft,
    LowerRight,
    LowerLeft,
    None,
}

impl LegendPosition {
    pub const NAMES: &'static str = "auto, right, below, upper-right, upper-left, lower-right, lower-left or none";
    pub fn parse(text: &str) -> Result<Self, Error> {
        Ok(match text.trim() {
            "auto" => Self::Auto,
            "right" => Self::Right,
            "below" | "bottom" => Self::Below,
            "upper-right" => Self::UpperRight,
            "upper-left" => Self::UpperLeft,
            "lower-right" => Self::LowerRight,
            "lower-left" => Self::LowerLeft,
            "none" => Self::None,
            other => return Err(Error::Input(format!("--legend '{other}': use {}", Self::NAMES))),
        })
    }
    pub fn inside(self) -> bool {
        matches!(self, Self::UpperRight | Self::UpperLeft | Self::LowerRight | Self::LowerLeft)
    }
}

/// A legend: entries (swatch and text, a text of several lines joined by
/// `\n`) in columns, measured before drawing.
pub struct Legend {
    pub entries: Vec<(Swatch, String)>,
    pub size: f64,
}

/// A legend's shape: columns, and its width and height including padding.
#[derive(Clone, Copy, Debug)]
pub struct LegendShape {
    pub columns: usize,
    pub width: f64,
    pub height: f64,
}

/// Most lines an entry's text is wrapped to.
const MAX_ENTRY_LINES: usize = 3;

impl Legend {
    fn swatch_width(&self) -> f64 {
        2.2 * em(self.size)
    }
    fn pad(&self) -> f64 {
        0.4 * em(self.size)
    }
    fn text_left(&self) -> f64 {
        self.swatch_width() + 0.4 * em(self.size)
    }
    fn column_width(&self) -> f64 {
        let widest =
            self.entries.iter().flat_map(|(_, t)| t.split('\n')).map(|t| text_width(t, self.size)).fold(0.0, f64::max);
        self.text_left() + widest
    }
    fn column_gap(&self) -> f64 {
        em(self.size)
    }
    fn lines(&self, k: usize) -> usize {
        self.entries[k].1.split('\n').count()
    }
    /// The top of each row (relative to the first) and the rows' total height.
    fn rows(&self, columns: usize) -> (Vec<f64>, f64) {
        let rows = self.entries.len().div_ceil(columns.max(1));
        let mut tops = Vec::with_capacity(rows);
        let mut y = 0.0;
        for r in 0..rows {
            tops.push(y);
            let lines = (r..self.entries.len()).step_by(rows.max(1)).map(|k| self.lines(k)).max().unwrap_or(1);
            y += block_height(lines, self.size) + 0.2 * em(self.size);
        }
        (tops, y)
    }
    /// The shape with `columns` columns.
    pub fn shape(&self, columns: usize) -> LegendShape {
        let columns = columns.clamp(1, self.entries.len().max(1));
        let (_, height) = self.rows(columns);
        LegendShape {
            columns,
            width: 2.0 * self.pad() + columns as f64 * self.column_width() + (columns - 1) as f64 * self.column_gap(),
            height: 2.0 * self.pad() + height,
        }
    }
    /// The fewest rows (most columns) that fit `width`; when not even one
    /// column does, the texts wrapped to fit (at most three lines each).
    pub fn shape_within(&mut self, width: f64) -> Result<LegendShape, NoFit> {
        let fits: Vec<LegendShape> =
            (1..=self.entries.len().max(1)).map(|c| self.shape(c)).filter(|s| s.width <= width).collect();
        if let Some(shape) = fits.last() {
            return Ok(*shape);
        }
        let text_width = width - 2.0 * self.pad() - self.text_left();
        if text_width < 4.0 * em(self.size) {
            return Err(NoFit("the legend".into()));
        }
        for entry in &mut self.entries {
            let lines = wrap(&entry.1.replace('\n', " "), self.size, text_width);
            if lines.len() > MAX_ENTRY_LINES {
                return Err(NoFit("the legend".into()));
            }
            entry.1 = lines.join("\n");
        }
        let shape = self.shape(1);
        if shape.width <= width {
            Ok(shape)
        } else {
            Err(NoFit("the legend".into()))
        }
    }
    /// Draw the legend with its top-left corner at (x, y), framed on a
    /// white background (it may sit over data).
    pub fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        shape: LegendShape,
        (x, y): (f64, f64),
    ) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let (x0, y0) = (x.round() as i32, y.round() as i32);
        let (x1, y1) = ((x + shape.width).round() as i32, (y + shape.height).round() as i32);
        area.draw(&Rectangle::new([(x0, y0), (x1, y1)], WHITE.filled())).map_err(err)?;
        area.draw(&Rectangle::new([(x0, y0), (x1, y1)], RGBColor(120, 120, 120).stroke_width(1))).map_err(err)?;
        let rows = self.entries.len().div_ceil(shape.columns);
        let (tops, _) = self.rows(shape.columns);
        let sw = self.swatch_width();
        for (k, (swatch, text)) in self.entries.iter().enumerate() {
            let (col, row) = (k / rows, k % rows);
            let left = x + self.pad() + col as f64 * (self.column_width() + self.column_gap());
            let top = y + self.pad() + tops[row];
            let mid = (top + line_box(self.size) / 2.0).round() as i32;
            let (l, r) = (left.round() as i32, (left + sw).round() as i32);
            let half = (0.35 * em(self.size)).round().max(2.0) as i32;
            match *swatch {
                Swatch::Line { colour, width, dash, marker } => {
                    let style = colour.stroke_width(width);
                    match dash {
                        Some(d) => dashed(area, (l, r, mid), d, style)?,
                        None => area.draw(&PathElement::new(vec![(l, mid), (r, mid)], style)).map_err(err)?,
                    }
                    draw_marker(area, marker, ((l + r) / 2, mid), half.min(4), colour)?;
                }
                Swatch::Patch { fill, edge } => {
                    // the edge is a box one point larger under the fill
                    let outer = [(l - 1, mid - half - 1), (r + 1, mid + half + 1)];
                    area.draw(&Rectangle::new(outer, edge.filled())).map_err(err)?;
                    area.draw(&Rectangle::new([(l, mid - half), (r, mid + half)], fill.filled())).map_err(err)?;
                }
                Swatch::Dot(colour) => {
                    area.draw(&Circle::new(((l + r) / 2, mid), half.min(4), colour.filled())).map_err(err)?
                }
            }
            let lines: Vec<String> = text.split('\n').map(str::to_string).collect();
            draw_lines(area, &lines, self.size, (left + self.text_left(), top), HPos::Left)?;
        }
        Ok(())
    }
}

/// A legend's shape and its top-left corner.
pub type Placed = (LegendShape, (f64, f64));

/// Where a legend outside the plot goes: the margins it takes from the
/// figure's area (left, top, right, bottom, grown) and its top-left corner.
/// `Auto`: right of the plot when one column takes at most 40 % of the
/// width, else below it.
pub fn place_outside(
    legend: &mut Legend,
    position: LegendPosition,
    (w, h): (f64, f64),
    region: &mut (f64, f64, f64, f64),
) -> Result<Option<Placed>, NoFit> {
    if legend.entries.is_empty() {
        return Ok(None);
    }
    let one_column = legend.shape(1);
    let inner_w = w - region.0 - region.2;
    let inner_h = h - region.1 - region.3;
    let fits_right = one_column.width <= 0.4 * inner_w && one_column.height <= inner_h;
    match position {
        LegendPosition::Right | LegendPosition::Auto if fits_right => {
            let at = (w - region.2 - one_column.width, region.1);
            region.2 += one_column.width + em(legend.size);
            Ok(Some((one_column, at)))
        }
        LegendPosition::Right => Err(NoFit("the legend".into())),
        LegendPosition::Auto | LegendPosition::Below => {
            let shape = legend.shape_within(inner_w)?;
            if shape.height > 0.45 * inner_h {
                return Err(NoFit("the legend".into()));
            }
            let at = (region.0 + (inner_w - shape.width) / 2.0, h - region.3 - shape.height);
            region.3 += shape.height + 0.5 * em(legend.size);
            Ok(Some((shape, at)))
        }
        _ => Ok(None),
    }
}

/// Where a legend inside the plot (`plot` in figure coordinates) goes.
pub fn place_inside(
    legend: &mut Legend,
    position: LegendPosition,
    (x0, y0, x1, y1): (f64, f64, f64, f64),
) -> Result<Option<Placed>, NoFit> {
    if !position.inside() || legend.entries.is_empty() {
        return Ok(None);
    }
    let pad = 0.5 * em(legend.size);
    let shape = legend.shape_within(x1 - x0 - 2.0 * pad)?;
    if shape.height > y1 - y0 - 2.0 * pad {
        return Err(NoFit("the legend".into()));
    }
    let x = match position {
        LegendPosition::UpperLeft | LegendPosition::LowerLeft => x0 + pad,
        _ => x1 - pad - shape.width,
    };
    let y = match position {
        LegendPosition::UpperLeft | LegendPosition::UpperRight => y0 + pad,
        _ => y1 - pad - shape.height,
    };
    Ok(Some((shape, (x, y))))
}

/// A plan's axes area as a drawing area: the figure less the margins.
pub fn region_area<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    (l, t, r, b): (f64, f64, f64, f64),
) -> DrawingArea<DB, Shift> {
    root.margin(t.round() as i32, b.round() as i32, l.round() as i32, r.round() as i32)
}

/// The ticks of an axis.
pub enum Ticks<'a> {
    /// "nice" values (plotters' key points), labelled by the formatter
    Auto(&'a dyn Fn(f64) -> String),
    /// whole numbers only, every one or every k-th
    Integers,
    /// no ticks or labels
    None,
}

/// One axis: its value range, its description and its ticks.
pub struct Axis<'a> {
    pub range: (f64, f64),
    pub desc: Option<String>,
    pub ticks: Ticks<'a>,
}

/// Where the plot goes inside an area and what its axes show: the plot's
/// pixel rectangle (relative to the area) and the ticks (value, label).
pub struct AxesPlan {
    pub plot: (f64, f64, f64, f64),
    pub x_ticks: Vec<(f64, String)>,
    pub y_ticks: Vec<(f64, String)>,
    pub label_size: f64,
    pub desc_size: f64,
    x_desc: Option<String>,
    y_desc: Option<String>,
}

/// The tick marks' length.
fn tick_len(label_size: f64) -> f64 {
    (0.4 * em(label_size)).max(3.0).round()
}

/// Candidate tick sets of an axis, most ticks first.
fn tick_candidates(axis: &Axis, most: usize) -> Vec<Vec<(f64, String)>> {
    let (a, b) = axis.range;
    match axis.ticks {
        Ticks::None => vec![Vec::new()],
        Ticks::Auto(fmt) => {
            let coord = RangedCoordf64::from(a..b);
            let mut out: Vec<Vec<(f64, String)>> = Vec::new();
            for n in (2..=most.max(2)).rev() {
                let points = coord.key_points(n);
                if out.last().is_some_and(|l: &Vec<(f64, String)>| l.len() == points.len()) {
                    continue;
                }
                let ticks: Vec<(f64, String)> = points.into_iter().map(|v| (v, fmt(v))).collect();
                // a label must read as its value: the formatter's decimals
                // (chosen for the range) may be too few for a fine step
                let exact = |(v, t): &(f64, String)| {
                    t.parse::<f64>().map_or(true, |x| (x - v).abs() <= 1e-9 * (b - a).abs().max(1e-300))
                };
                if ticks.iter().all(exact) {
                    out.push(ticks);
                }
            }
            if out.is_empty() {
                out.push(coord.key_points(2).into_iter().map(|v| (v, fmt(v))).collect());
            }
            out
        }
        Ticks::Integers => {
            let (lo, hi) = (a.ceil() as i64, b.floor() as i64);
            let count = (hi - lo + 1).max(1);
            [1, 2, 5, 10, 20, 50, 100]
                .iter()
                .filter(|&&k| k == 1 || k < count)
                .map(|&k| (lo..=hi).filter(|v| (v - lo) % k == 0).map(|v| (v as f64, v.to_string())).collect())
                .collect()
        }
    }
}

/// Everything a figure with axes places before drawing: the title's lines
/// and size, the legend and where it goes, the axes' area inside the figure
/// ((left, top, right, bottom) margins) and the axes.
pub struct AxesFigurePlan {
    pub title: Vec<String>,
    pub title_size: f64,
    pub legend: Option<PlacedLegend>,
    pub region: (f64, f64, f64, f64),
    pub axes: AxesPlan,
}

/// A legend with its place, as a figure draws it.
pub type PlacedLegend = (Legend, LegendShape, (f64, f64));

/// The layout every figure with axes and a legend shares: the legend outside
/// the plot where its position puts it (taking its margins from `region`,
/// which starts as the figure's margins below the title), the axes planned
/// in the area left, then the legend moved into the plot when its position
/// is an inside one. Returns the placed legend (none when it has no
/// entries), the final margins and the axes.
#[allow(clippy::too_many_arguments)]
pub fn plan_with_legend(
    mut legend: Legend,
    position: LegendPosition,
    (w, h): (f64, f64),
    mut region: (f64, f64, f64, f64),
    x: &Axis,
    y: &Axis,
    (label_size, desc_size): (f64, f64),
    square: bool,
) -> Result<(Option<PlacedLegend>, (f64, f64, f64, f64), AxesPlan), NoFit> {
    let mut placed = place_outside(&mut legend, position, (w, h), &mut region)?;
    let axes = plan_axes((w - region.0 - region.2, h - region.1 - region.3), x, y, label_size, desc_size, square)?;
    let (x0, y0, x1, y1) = axes.plot;
    if let Some(inside) =
        place_inside(&mut legend, position, (x0 + region.0, y0 + region.1, x1 + region.0, y1 + region.1))?
    {
        placed = Some(inside);
    }
    Ok((placed.map(|(s, at)| (legend, s, at)), region, axes))
}

/// Plan the axes of a chart filling an area of `w` × `h`: label areas wide
/// enough for the measured tick labels and descriptions, as many ticks as
/// fit with a gap between their labels, the plot square when `square`.
pub fn plan_axes(
    (w, h): (f64, f64),
    x: &Axis,
    y: &Axis,
    label_size: f64,
    desc_size: f64,
    square: bool,
) -> Result<AxesPlan, NoFit> {
    let (el, ed) = (em(label_size), em(desc_size));
    let dist = 2.0 * tick_len(label_size);
    let has_x_labels = !matches!(x.ticks, Ticks::None);
    let has_y_labels = !matches!(y.ticks, Ticks::None);
    // below the plot: tick labels, then the description
    let mut bottom = 2.0;
    if has_x_labels {
        bottom += dist + LINE * el;
    }
    if x.desc.is_some() {
        bottom += 0.3 * el + (LINE + 0.05) * ed;
    }
    // above: half a y tick label sticks out over the plot's top edge
    let top = if has_y_labels { 0.7 * el + 1.0 } else { 1.0 };
    // y tick labels: their count depends on the plot's height, their width
    // on the labels, so the widest candidate is measured first
    let avail_h = h - top - bottom;
    if avail_h < 2.0 * el.max(8.0) {
        return Err(NoFit("the plot".into()));
    }
    let y_cands = tick_candidates(y, (avail_h / (1.6 * el)) as usize + 1);
    let y_ticks = pick_ticks(&y_cands, y.range, avail_h, |t| LINE * el + 0.3 * el + 0.0 * t.len() as f64)
        .ok_or_else(|| NoFit("the y tick labels".into()))?;
    let y_label_w = y_ticks.iter().map(|(_, t)| text_width(t, label_size)).fold(0.0, f64::max);
    let mut left = 1.0 + if has_y_labels { dist + y_label_w } else { 0.0 };
    if y.desc.is_some() {
        left += 0.3 * el + (LINE + 0.2) * ed;
    }
    // the right edge: room for half of the last x tick label
    let x_guess = tick_candidates(x, 3);
    let half_last = x_guess.iter().flatten().map(|(_, t)| text_width(t, label_size) / 2.0).fold(0.0, f64::max);
    let right = half_last.max(4.0) + 2.0;
    let (mut pw, mut ph) = (w - left - right, avail_h);
    if pw < 2.0 * el.max(8.0) {
        return Err(NoFit("the plot".into()));
    }
    let (mut x0, y0) = (left, top);
    if square {
        let side = pw.min(ph);
        x0 += (pw - side) / 2.0;
        pw = side;
        ph = side;
    }
    // the y ticks again for the final height (a square plot may be lower)
    let y_ticks = if square {
        let y_cands = tick_candidates(y, (ph / (1.6 * el)) as usize + 1);
        pick_ticks(&y_cands, y.range, ph, |_| LINE * el + 0.3 * el).ok_or_else(|| NoFit("the y tick labels".into()))?
    } else {
        y_ticks
    };
    let x_cands = tick_candidates(x, (pw / (1.5 * el)) as usize + 2);
    let x_ticks = pick_x_ticks(&x_cands, x.range, pw, label_size).ok_or_else(|| NoFit("the x tick labels".into()))?;
    // the descriptions must fit along their axes
    if let Some(d) = &x.desc {
        // centred under the plot: half on either side of its middle, inside the area
        let middle = x0 + pw / 2.0;
        if text_width(d, desc_size) > 2.0 * middle.min(w - middle) {
            return Err(NoFit(format!("the axis description '{d}'")));
        }
    }
    if let Some(d) = &y.desc {
        if text_width(d, desc_size) > ph {
            return Err(NoFit(format!("the axis description '{d}'")));
        }
    }
    Ok(AxesPlan {
        plot: (x0, y0, x0 + pw, y0 + ph),
        x_ticks,
        y_ticks,
        label_size,
        desc_size,
        x_desc: x.desc.clone(),
        y_desc: y.desc.clone(),
    })
}

/// The densest candidate whose labels (`extent` each along the axis) keep
/// apart over `length` pixels.
fn pick_ticks(
    cands: &[Vec<(f64, String)>],
    (a, b): (f64, f64),
    length: f64,
    extent: impl Fn(&str) -> f64,
) -> Option<Vec<(f64, String)>> {
    let span = (b - a).abs().max(1e-300);
    cands
        .iter()
        .find(|ticks| {
            ticks.windows(2).all(|w| {
                let gap = (w[1].0 - w[0].0).abs() / span * length;
                gap >= (extent(&w[0].1) + extent(&w[1].1)) / 2.0
            })
        })
        .cloned()
}

fn pick_x_ticks(cands: &[Vec<(f64, String)>], range: (f64, f64), length: f64, size: f64) -> Option<Vec<(f64, String)>> {
    pick_ticks(cands, range, length, |t| text_width(t, size) + 0.8 * em(size))
}

impl AxesPlan {
    /// The plot rectangle as whole pixels (x0, y0, x1, y1).
    pub fn pixels(&self) -> (i32, i32, i32, i32) {
        let (x0, y0, x1, y1) = self.plot;
        (x0.round() as i32, y0.round() as i32, x1.round() as i32, y1.round() as i32)
    }
    /// A chart over the plot rectangle of `area` with the axes' ranges
    /// (nothing of plotters' own mesh is drawn).
    pub fn chart<'a, DB: DrawingBackend>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
        x: (f64, f64),
        y: (f64, f64),
    ) -> Result<ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>, Error>
    where
        DB::ErrorType: 'static,
    {
        let (w, h) = area.dim_in_pixel();
        let (x0, y0, x1, y1) = self.pixels();
        ChartBuilder::on(area)
            .margin_left(x0.max(0) as u32)
            .margin_top(y0.max(0) as u32)
            .margin_right((w as i32 - x1).max(0) as u32)
            .margin_bottom((h as i32 - y1).max(0) as u32)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(err)
    }
    /// Draw the axes (left and bottom lines, ticks, tick labels, the
    /// descriptions) and, with `grid`, light lines at the ticks.
    pub fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        x: (f64, f64),
        y: (f64, f64),
        grid: bool,
    ) -> Result<(), Error>
    where
        DB::ErrorType: 'static,
    {
        let (x0, y0, x1, y1) = self.pixels();
        let px = |v: f64| x0 as f64 + (v - x.0) / (x.1 - x.0) * (x1 - x0) as f64;
        let py = |v: f64| y1 as f64 - (v - y.0) / (y.1 - y.0) * (y1 - y0) as f64;
        let el = em(self.label_size);
        let tick = tick_len(self.label_size) as i32;
        if grid {
            let light = RGBColor(225, 225, 225).stroke_width(1);
            for (v, _) in &self.x_ticks {
                let p = px(*v).round() as i32;
                area.draw(&PathElement::new(vec![(p, y0), (p, y1)], light)).map_err(err)?;
            }
            for (v, _) in &self.y_ticks {
                let p = py(*v).round() as i32;
                area.draw(&PathElement::new(vec![(x0, p), (x1, p)], light)).map_err(err)?;
            }
        }
        let axis = BLACK.stroke_width(1);
        area.draw(&PathElement::new(vec![(x0, y0), (x0, y1), (x1, y1)], axis)).map_err(err)?;
        let label = TextStyle::from((FONT, self.label_size).into_font()).color(&BLACK);
        for (v, t) in &self.x_ticks {
            let p = px(*v).round() as i32;
            area.draw(&PathElement::new(vec![(p, y1), (p, y1 + tick)], axis)).map_err(err)?;
            draw_text(area, t, self.label_size, (p as f64, y1 as f64 + 2.0 * tick as f64), HPos::Center)?;
        }
        let mut label_left = x0 as f64;
        for (v, t) in &self.y_ticks {
            let p = py(*v).round() as i32;
            area.draw(&PathElement::new(vec![(x0 - tick, p), (x0, p)], axis)).map_err(err)?;
            let style = label.pos(Pos::new(HPos::Right, VPos::Center));
            area.draw(&Text::new(t.clone(), (x0 - 2 * tick, p), style)).map_err(err)?;
            label_left = label_left.min(x0 as f64 - 2.0 * tick as f64 - text_width(t, self.label_size));
        }
        let ed = em(self.desc_size);
        if let Some(d) = &self.x_desc {
            let below = if self.x_ticks.is_empty() { 2.0 } else { 2.0 * tick as f64 + LINE * el + 0.3 * el };
            draw_text(area, d, self.desc_size, ((x0 + x1) as f64 / 2.0, y1 as f64 + below), HPos::Center)?;
        }
        if let Some(d) = &self.y_desc {
            // rotated a quarter turn: the text's top faces left; its box
            // spans LINE ems to the left of `right`
            let right = label_left - 0.3 * el;
            let baseline_x = right - 0.236 * ed;
            let style = TextStyle::from((FONT, self.desc_size).into_font())
                .color(&BLACK)
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Center, VPos::Top));
            // a top-anchored text's baseline is 0.76 em below its anchor
            let anchor = (baseline_x - 0.76 * ed).round() as i32;
            area.draw(&Text::new(d.clone(), (anchor, (y0 + y1) / 2), style)).map_err(err)?;
        }
        Ok(())
    }
}

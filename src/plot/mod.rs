//! Figures: SVG and PDF for papers (vector, text as the embedded font's
//! glyphs), PNG at a chosen resolution.
//!
//! Text is laid out with an embedded font (DejaVu Sans, `assets/fonts/`,
//! licence next to it) registered with plotters' ab_glyph backend, so no
//! system font is needed: without a registered font the PNG backend panics at
//! the first label. PDF is the SVG converted in-process (usvg + svg2pdf) with
//! the same font, which the PDF embeds (subset), so neither a system font nor
//! an external converter is needed; one SVG pixel is one PDF point. PNG is
//! the same SVG rasterised (resvg) at `Style::dpi`, so a PNG looks like the
//! PDF at that resolution: a figure's size is in points, and the PNG has
//! size × dpi / 72 pixels. Files are written atomically (`io::write_atomic`).
//!
//! The same figure is the same bytes in every run and at every thread count
//! (SVG as drawn; PDF with its resource dictionaries in a fixed order, see
//! `sort_resource_entries`). Text XML cannot carry (control characters in a
//! title) is shown escaped (`xml_safe`).

pub mod charmap;
pub mod compare;
pub mod curvature;
pub mod layout;
pub mod lines;
pub mod region;
pub mod shape_chart;
pub mod spectrum;
pub mod sweep;

use std::path::Path;
use std::sync::Once;

use crate::error::Error;
use plotters::coord::Shift;
use plotters::prelude::*;

pub use layout::FONT;
static FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

fn register_font() -> Result<(), Error> {
    let mut result = Ok(());
    REGISTER.call_once(|| {
        if plotters::style::register_font(FONT, FontStyle::Normal, FONT_BYTES).is_err() {
            result = Err(Error::Message("the embedded font could not be loaded".to_string()));
        }
    });
    result
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Pdf,
    Png,
}

/// The figure format from the file extension (`.svg`, `.pdf` or `.png`, any case).
pub fn format_of(path: &Path) -> Result<Format, Error> {
    match path.extension().and_then(|e| e.to_str()).map(|e| e.to_ascii_lowercase()).as_deref() {
        Some("svg") => Ok(Format::Svg),
        Some("pdf") => Ok(Format::Pdf),
        Some("png") => Ok(Format::Png),
        Some(other) => Err(Error::Input(format!(
            "unknown figure extension '.{other}' in {}; use .svg, .pdf or .png",
            path.display()
        ))),
        None => Err(Error::Input(format!("{} has no extension; use .svg, .pdf or .png", path.display()))),
    }
}

/// A figure that can draw itself on any plotters backend.
pub trait Figure {
    /// width and height in points
    fn size(&self) -> (u32, u32);
    /// the resolution of the figure as a PNG (None: [`DEFAULT_DPI`])
    fn dpi(&self) -> Option<f64> {
        None
    }
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static;
    /// The plotted numbers as CSV: a header line, then one row per drawn
    /// point (`--data`).
    fn data_csv(&self) -> Result<String, Error> {
        Err(Error::Input("this figure has no --data export".into()))
    }
}

/// A CSV field: quoted when it holds a comma, a quote or a line break.
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// A CSV number: shortest round-trip form (`{}`), so the file holds the
/// plotted values exactly.
pub fn csv_number(v: f64) -> String {
    format!("{v}")
}

/// Write the figure's plotted numbers to `path` (a `.csv`), atomically.
pub fn save_data<F: Figure>(fig: &F, path: Option<&Path>) -> Result<(), Error> {
    match path {
        Some(path) => crate::io::write_atomic(path, fig.data_csv()?.as_bytes()),
        None => Ok(()),
    }
}

/// The SVG text of a figure.
pub fn render_svg<F: Figure>(fig: &F) -> Result<String, Error> {
    register_font()?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, fig.size()).into_drawing_area();
        fig.draw(&root)?;
        root.present().map_err(|e| Error::Message(format!("cannot draw the figure: {e}")))?;
    }
    Ok(xml_safe(svg))
}

/// The SVG of a figure as it is saved: every text drawn as the embedded
/// font's glyph outlines (paths), as in the PDF, so the figure looks the same
/// in every viewer whatever fonts it has. Each text stays in the file beside
/// its outlines as an invisible `<text>` (fill opacity 0), so the figure can
/// still be searched, its text selected and read by screen readers and
/// scripts; everything else is the SVG as drawn.
pub fn render_svg_outlined<F: Figure>(fig: &F) -> Result<String, Error> {
    outline_text(&render_svg(fig)?)
}

/// An SVG text (as figures render it) with each `<text>` element preceded by
/// its glyph outlines and made invisible (see [`render_svg_outlined`]).
pub fn outline_text(svg: &str) -> Result<String, Error> {
    let head_end = svg.find('>').ok_or_else(|| Error::Message("the figure's SVG has no root element".into()))?;
    let head = &svg[..=head_end];
    let mut out = String::with_capacity(svg.len() * 4);
    let mut rest = svg;
    while let Some(start) = rest.find("<text") {
        let Some(len) = rest[start..].find("</text>") else { break };
        let end = start + len + "</text>".len();
        let text = &rest[start..end];
        out += &rest[..start];
        out += &glyph_outlines(head, text)?;
        out += "<text fill-opacity=\"0\"";
        out += &text["<text".len()..];
        rest = &rest[end..];
    }
    out += rest;
    Ok(out)
}

/// The paths of one `<text>` element's glyphs, laid out by usvg with the
/// embedded font in a document of the figure's size (`head`: the figure's
/// `<svg ...>` start tag), as SVG elements to put where the text was.
fn glyph_outlines(head: &str, text: &str) -> Result<String, Error> {
    use svg2pdf::usvg::WriteOptions;
    let tree = svg_tree(&format!("{head}{text}</svg>"))?;
    // the writer turns text into paths (WriteOptions::preserve_text is false)
    // a thousandth of a point is far below what any viewer or printer shows
    let options = WriteOptions {
        indent: svg2pdf::usvg::Indent::None,
        coordinates_precision: 3,
        transforms_precision: 4,
        ..WriteOptions::default()
    };
    let written = tree.to_string(&options);
    let body_start = written.find('>').map_or(0, |i| i + 1);
    let body_end = written.rfind("</svg>").unwrap_or(written.len());
    Ok(written[body_start..body_end].replace("<defs/>", "").trim().to_string() + "\n")
}

/// Whether XML 1.0 can carry `c` at all (its `Char` production): not the
/// C0 controls other than tab, line feed and carriage return, nor U+FFFE
/// and U+FFFF, even escaped as `&#1;`.
fn is_xml_char(c: char) -> bool {
    matches!(c, '\t' | '\n' | '\r' | '\u{20}'..='\u{d7ff}' | '\u{e000}'..='\u{fffd}' | '\u{10000}'..)
}

/// The SVG with every character XML cannot carry shown as its escape
/// (`\u{1b}`, as in error messages). Only text can hold one (a title, a
/// scheme name, a reference expression: the user's), and plotters already
/// escapes `&<>"'` in it but not these, so the whole document is filtered
/// here, once, for every text of every figure and format.
fn xml_safe(svg: String) -> String {
    if svg.chars().all(is_xml_char) {
        return svg;
    }
    svg.chars().map(|c| if is_xml_char(c) { c.to_string() } else { c.escape_unicode().to_string() }).collect()
}

/// The family name of the embedded font, as its name table gives it.
const FONT_FAMILY: &str = "DejaVu Sans";

/// The PDF of a figure: its SVG, parsed with the embedded font as the only
/// font (every family the SVG names resolves to it), converted to PDF.
pub fn render_pdf<F: Figure>(fig: &F) -> Result<Vec<u8>, Error> {
    svg_to_pdf(&render_svg(fig)?)
}

/// An SVG text (as figures render it) as usvg's tree, with the embedded font
/// as the only font: the one reading of the SVG that PDF and PNG share.
fn svg_tree(svg: &str) -> Result<svg2pdf::usvg::Tree, Error> {
    use svg2pdf::usvg;
    let mut options = usvg::Options { font_family: FONT_FAMILY.to_string(), ..usvg::Options::default() };
    {
        let fonts = options.fontdb_mut();
        fonts.load_font_data(FONT_BYTES.to_vec());
        fonts.set_sans_serif_family(FONT_FAMILY);
        fonts.set_serif_family(FONT_FAMILY);
        fonts.set_monospace_family(FONT_FAMILY);
    }
    usvg::Tree::from_str(svg, &options).map_err(|e| Error::Message(format!("cannot read the figure's SVG: {e}")))
}

/// An SVG text (as figures render it) to a PDF document of one page.
pub fn svg_to_pdf(svg: &str) -> Result<Vec<u8>, Error> {
    let tree = svg_tree(svg)?;
    svg2pdf::to_pdf(&tree, svg2pdf::ConversionOptions::default(), svg2pdf::PageOptions::default())
        .map(|pdf| sort_resource_entries(&pdf))
        .map_err(|e| Error::Message(format!("cannot convert the figure to PDF: {e}")))
}

/// The resource dictionaries whose entries svg2pdf writes in the order of a
/// `HashMap` (a new random order in every process).
const RESOURCE_DICTIONARIES: [&[u8]; 6] =
    [b"/XObject <<", b"/ExtGState <<", b"/Pattern <<", b"/Shading <<", b"/Font <<", b"/ColorSpace <<"];

/// The PDF with the entries of every resource dictionary sorted, so the same
/// figure is the same bytes in every run. svg2pdf writes one entry per line
/// (`/xo12 30 0 R`); sorting permutes whole lines inside the dictionary, so
/// no byte offset changes and the cross-reference table stays right. Streams
/// (binary) are skipped; a dictionary whose lines are not all single entries
/// is left as it is.
fn sort_resource_entries(pdf: &[u8]) -> Vec<u8> {
    let lines: Vec<&[u8]> = pdf.split(|&b| b == b'\n').collect();
    let single_entry = |l: &[u8]| {
        let l = l.trim_ascii();
        l.starts_with(b"/") && !l.windows(2).any(|w| w == b"<<" || w == b">>")
    };
    let mut sorted: Vec<&[u8]> = Vec::with_capacity(lines.len());
    let (mut k, mut in_stream) = (0, false);
    while k < lines.len() {
        let line = lines[k];
        sorted.push(line);
        k += 1;
        if in_stream {
            in_stream = line != b"endstream";
        } else if line == b"stream" {
            in_stream = true;
        } else if RESOURCE_DICTIONARIES.contains(&line.trim_ascii()) {
            let Some(len) = lines[k..].iter().position(|l| l.trim_ascii() == b">>") else { continue };
            let mut entries = lines[k..k + len].to_vec();
            if entries.iter().all(|l| single_entry(l)) {
                entries.sort_unstable();
            }
            sorted.extend(entries);
            k += len;
        }
    }
    sorted.join(&b'\n')
}

/// Most pixels of a PNG (a bound on memory: four bytes each).
pub const MAX_PNG_PIXELS: u64 = 100_000_000;

/// The pixel size of a figure of `size` points at `dpi` dots per inch (a
/// point is 1/72 inch), refused above [`MAX_PNG_PIXELS`].
pub fn png_size(size: (u32, u32), dpi: f64) -> Result<(u32, u32), Error> {
    let px = |pt: u32| ((pt as f64) * dpi / 72.0).round().max(1.0);
    let (w, h) = (px(size.0), px(size.1));
    if w * h > MAX_PNG_PIXELS as f64 {
        return Err(Error::Input(format!(
            "a {} × {} pt figure at {dpi} dpi is {w} × {h} pixels, above {} million; lower --dpi or the size",
            size.0,
            size.1,
            MAX_PNG_PIXELS / 1_000_000
        )));
    }
    Ok((w as u32, h as u32))
}

/// The PNG of a figure: its SVG rasterised at `dpi` (the figure's own
/// sizes are points), on white.
pub fn render_png<F: Figure>(fig: &F, dpi: f64) -> Result<Vec<u8>, Error> {
    let (w, h) = png_size(fig.size(), dpi)?;
    let tree = svg_tree(&render_svg(fig)?)?;
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h)
        .ok_or_else(|| Error::Input(format!("cannot make a {w} × {h} pixel image")))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let (sx, sy) = (w as f32 / tree.size().width(), h as f32 / tree.size().height());
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(sx, sy), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| Error::Message(format!("cannot encode the PNG: {e}")))
}

/// Draw `fig` into `path` (format from the extension), atomically; a PNG
/// at the figure's resolution.
pub fn save<F: Figure>(fig: &F, path: &Path) -> Result<(), Error> {
    let bytes = match format_of(path)? {
        Format::Svg => render_svg_outlined(fig)?.into_bytes(),
        Format::Pdf => render_pdf(fig)?,
        Format::Png => render_png(fig, fig.dpi().unwrap_or(DEFAULT_DPI))?,
    };
    crate::io::write_atomic(path, &bytes)
}

/// What a user may change in a figure: its title (`None`: the figure's
/// own; an empty text: no title), its size in points (SVG user units, PDF
/// points), the base font size the figure's text scales with (points), and
/// the resolution of a PNG.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Style {
    pub title: Option<String>,
    pub width: Option<u32>,
    pub height: Option<u32>,
    pub font_size: Option<u32>,
    /// dots per inch of a PNG (None: [`DEFAULT_DPI`]); SVG and PDF are vector
    pub dpi: Option<f64>,
    /// where the legend goes (None: the figure's own choice, `Auto`)
    pub legend: Option<layout::LegendPosition>,
    /// the x and y axes' ranges (None: the data's); numeric axes only
    pub xlim: Option<(f64, f64)>,
    pub ylim: Option<(f64, f64)>,
    /// legend texts of the curves in order, replacing their own (valence charts)
    pub labels: Vec<String>,
}

/// An axis range `A:B` (`--xlim`, `--ylim`): two finite numbers, A < B.
pub fn parse_limits(flag: &str, text: &str) -> Result<(f64, f64), Error> {
    let bad = || Error::Input(format!("{flag} '{text}': give A:B, two numbers with A < B, e.g. 0:1.5"));
    let (a, b) = text.split_once(':').ok_or_else(bad)?;
    let (a, b): (f64, f64) = (a.trim().parse().map_err(|_| bad())?, b.trim().parse().map_err(|_| bad())?);
    if a.is_finite() && b.is_finite() && a < b {
        Ok((a, b))
    } else {
        Err(bad())
    }
}

/// The PNG resolution when none is given: sharp on screen and in print drafts.
pub const DEFAULT_DPI: f64 = 150.0;
/// Resolutions accepted for PNG: below 36 dpi text is unreadable, above
/// 1200 no printer resolves the difference.
pub const DPI_RANGE: std::ops::RangeInclusive<f64> = 36.0..=1200.0;

/// Sizes accepted for `Style`: a figure smaller than this has no room for
/// its axes even with the smallest text (`layout::fit`), a larger one is not
/// a figure of a paper. 160 pt high is a one-column figure's usual height.
pub const SIZE_RANGE: std::ops::RangeInclusive<u32> = 120..=6000;
pub const FONT_RANGE: std::ops::RangeInclusive<u32> = 6..=72;

impl Style {
    /// Out-of-range sizes are input errors, named.
    pub fn checked(self) -> Result<Style, Error> {
        for (name, v, range) in [
            ("--width", self.width, &SIZE_RANGE),
            ("--height", self.height, &SIZE_RANGE),
            ("--font-size", self.font_size, &FONT_RANGE),
        ] {
            if let Some(v) = v.filter(|v| !range.contains(v)) {
                return Err(Error::Input(format!(
                    "{name} must be between {} and {}, got {v}",
                    range.start(),
                    range.end()
                )));
            }
        }
        if let Some(dpi) = self.dpi.filter(|d| !DPI_RANGE.contains(d)) {
            // NaN is in no range, so it lands here too
            return Err(Error::Input(format!(
                "--dpi must be between {} and {}, got {dpi}",
                DPI_RANGE.start(),
                DPI_RANGE.end()
            )));
        }
        Ok(self)
    }
    /// The title to draw: the user's, none, or the figure's own.
    pub fn title(&self, own: String) -> Option<String> {
        match &self.title {
            Some(t) if t.is_empty() => None,
            Some(t) => Some(t.clone()),
            None => Some(own),
        }
    }
    pub fn size(&self, own: (u32, u32)) -> (u32, u32) {
        (self.width.unwrap_or(own.0), self.height.unwrap_or(own.1))
    }
    /// A font size of the figure, `own` at its default base size `base`,
    /// scaled to the user's base size.
    pub fn font(&self, own: u32, base: u32) -> u32 {
        self.font_size.map_or(own, |f| (own * f).div_ceil(base).max(1))
    }
}

/// A tick label with as many decimals as a `span` of values needs, and no
/// "-0" (a tick at a tiny negative value rounds to zero and reads "0").
pub fn tick_label(v: f64, span: f64) -> String {
    let decimals =
        if span > 0.0 && span.is_finite() { (1.0 - span.log10().floor()).clamp(0.0, 8.0) as usize } else { 2 };
    let s = format!("{v:.decimals$}");
    if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        "0".to_string()
    } else {
        s
    }
}

/// A square window around the finite points, as (centre, half side), with
/// a 4 % margin: equal scales on both axes for plane figures.
pub(crate) fn square_window(points: impl Iterator<Item = [f64; 2]>) -> Option<((f64, f64), f64)> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points.filter(|p| p[0].is_finite() && p[1].is_finite()) {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if !lo[0].is_finite() {
        return None;
    }
    let half = 0.52 * (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
    Some((((lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0), half))
}

/// A plotters error as one line.
pub(crate) fn err<E: std::fmt::Display>(e: E) -> Error {
    Error::Message(format!("cannot draw the figure: {e}"))
}

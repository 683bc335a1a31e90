//! Figures: SVG and PDF for papers (vector, text as the embedded font's
//! glyphs), PNG for quick looks.
//!
//! Text is laid out with an embedded font (DejaVu Sans, `assets/fonts/`,
//! licence next to it) registered with plotters' ab_glyph backend, so no
//! system font is needed: without a registered font the PNG backend panics at
//! the first label. PDF is the SVG converted in-process (usvg + svg2pdf) with
//! the same font, which the PDF embeds (subset), so neither a system font nor
//! an external converter is needed; one SVG pixel is one PDF point. Files are
//! written atomically (temporary file in the target's directory, then rename).

pub mod charmap;
pub mod curvature;
pub mod spectrum;
pub mod sweep;

use std::path::Path;
use std::sync::Once;

use crate::error::Error;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The family name figures use for text.
pub const FONT: &str = "sans-serif";
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
    fn size(&self) -> (u32, u32);
    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), Error>
    where
        DB::ErrorType: 'static;
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
    Ok(svg)
}

/// The family name of the embedded font, as its name table gives it.
const FONT_FAMILY: &str = "DejaVu Sans";

/// The PDF of a figure: its SVG, parsed with the embedded font as the only
/// font (every family the SVG names resolves to it), converted to PDF.
pub fn render_pdf<F: Figure>(fig: &F) -> Result<Vec<u8>, Error> {
    svg_to_pdf(&render_svg(fig)?)
}

/// An SVG text (as figures render it) to a PDF document of one page.
pub fn svg_to_pdf(svg: &str) -> Result<Vec<u8>, Error> {
    use svg2pdf::usvg;
    let mut options = usvg::Options { font_family: FONT_FAMILY.to_string(), ..usvg::Options::default() };
    {
        let fonts = options.fontdb_mut();
        fonts.load_font_data(FONT_BYTES.to_vec());
        fonts.set_sans_serif_family(FONT_FAMILY);
        fonts.set_serif_family(FONT_FAMILY);
        fonts.set_monospace_family(FONT_FAMILY);
    }
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|e| Error::Message(format!("cannot read the figure's SVG: {e}")))?;
    svg2pdf::to_pdf(&tree, svg2pdf::ConversionOptions::default(), svg2pdf::PageOptions::default())
        .map_err(|e| Error::Message(format!("cannot convert the figure to PDF: {e}")))
}

/// Draw `fig` into `path` (format from the extension), atomically.
pub fn save<F: Figure>(fig: &F, path: &Path) -> Result<(), Error> {
    let format = format_of(path)?;
    register_font()?;
    let size = fig.size();
    match format {
        Format::Svg => crate::io::write_atomic(path, render_svg(fig)?.as_bytes()),
        Format::Pdf => crate::io::write_atomic(path, &render_pdf(fig)?),
        Format::Png => {
            let dir = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
            let tmp = tempfile::Builder::new()
                .suffix(".png")
                .tempfile_in(dir)
                .map_err(|e| Error::Write { path: format!("in {}", dir.display()), reason: e.to_string() })?;
            {
                let root = BitMapBackend::new(tmp.path(), size).into_drawing_area();
                fig.draw(&root)?;
                root.present().map_err(|e| Error::Write { path: path.display().to_string(), reason: e.to_string() })?;
            }
            // a failed rename: not the "cannot write" form, so an untyped message
            tmp.persist(path).map_err(|e| Error::Message(format!("cannot replace {}: {}", path.display(), e.error)))?;
            Ok(())
        }
    }
}

/// A plotters error as one line.
pub(crate) fn err<E: std::fmt::Display>(e: E) -> Error {
    Error::Message(format!("cannot draw the figure: {e}"))
}

//! Figure formats chosen by extension: the same figure as SVG, PDF and PNG,
//! each parsed back (SVG size and text, PDF header, page count, page size and
//! embedded font, PNG signature and size), and an unknown extension refused;
//! hostile titles and run-to-run determinism.

use crate::common;
use common::{fails, subdlab};

/// (width, height) from the `<svg width=".." height="..">` header.
fn svg_size(svg: &str) -> (u32, u32) {
    let head = &svg[..svg.find('>').expect("an svg element")];
    let attr = |name: &str| -> u32 {
        let at = head.find(&format!(" {name}=\"")).unwrap_or_else(|| panic!("no {name} in {head}")) + name.len() + 3;
        head[at..].split('"').next().unwrap().parse().unwrap()
    };
    (attr("width"), attr("height"))
}

/// The number of page objects, the MediaBox of the (only) page and the base
/// font names of a PDF, read from its uncompressed object dictionaries.
fn pdf_outline(pdf: &[u8]) -> (usize, Vec<f64>, Vec<String>) {
    let text = String::from_utf8_lossy(pdf);
    let pages = text.match_indices("/Type /Page").filter(|(i, _)| !text[i + 11..].starts_with('s')).count();
    let media = text.find("/MediaBox [").map(|i| {
        let rest = &text[i + 11..];
        rest[..rest.find(']').unwrap()].split_whitespace().map(|x| x.parse::<f64>().unwrap()).collect()
    });
    let fonts = text
        .match_indices("/BaseFont /")
        .map(|(i, _)| {
            text[i + 11..].split(|c: char| c.is_whitespace() || c == '/' || c == '>').next().unwrap().to_string()
        })
        .collect();
    (pages, media.unwrap_or_default(), fonts)
}

#[test]
fn one_figure_in_svg_pdf_and_png() {
    let dir = tempfile::tempdir().unwrap();
    let path = |ext: &str| dir.path().join(format!("ring.{ext}"));
    for ext in ["svg", "pdf", "png"] {
        let file = path(ext);
        let out = subdlab(&["charmap", "catmull-clark", "--valence", "5", "--out", file.to_str().unwrap()]);
        assert!(out.status.success(), "{ext}: {}", String::from_utf8_lossy(&out.stderr));
    }
    let svg = std::fs::read_to_string(path("svg")).unwrap();
    let (w, h) = svg_size(&svg);
    assert!(w >= 300 && h >= 300, "a legible size: {w}x{h}");
    assert!(svg.contains("Catmull") || svg.contains("catmull"), "the figure names its scheme");

    // the PDF is the same page: one page of w x h points, text in the
    // embedded font, nothing left to a system font
    let pdf = std::fs::read(path("pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-1."), "PDF header");
    assert!(String::from_utf8_lossy(&pdf[pdf.len().saturating_sub(32)..]).contains("%%EOF"), "PDF trailer");
    let (pages, media, fonts) = pdf_outline(&pdf);
    assert_eq!(pages, 1);
    assert_eq!(media, vec![0.0, 0.0, w as f64, h as f64], "page size in points = SVG size in pixels");
    assert!(!fonts.is_empty(), "the labels are text in an embedded font");
    assert!(fonts.iter().all(|f| f.ends_with("+DejaVuSans")), "only the embedded font (a subset): {fonts:?}");
    assert!(String::from_utf8_lossy(&pdf).contains("/FontFile"), "the font program is in the file");

    // the PNG is the same page at the default 150 dpi: w x h points of
    // 1/72 inch are w·150/72 x h·150/72 pixels
    let png = std::fs::read(path("png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |k: usize| u32::from_be_bytes(png[k..k + 4].try_into().unwrap());
    let at_150 = |pt: u32| (pt as f64 * 150.0 / 72.0).round() as u32;
    assert_eq!((be(16), be(20)), (at_150(w), at_150(h)), "PNG IHDR size");
}

#[test]
fn pdf_of_the_spectrum_plot() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("moduli.pdf");
    let out = subdlab(&["plot", "spectrum", "loop", "--valences", "3..8", "--out", file.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let pdf = std::fs::read(&file).unwrap();
    let (pages, media, fonts) = pdf_outline(&pdf);
    assert_eq!(pages, 1);
    assert_eq!(media.len(), 4);
    assert!(media[2] > 0.0 && media[3] > 0.0);
    assert!(!fonts.is_empty());
}

#[test]
fn an_unknown_figure_extension_is_a_one_line_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("ring.eps");
    let err = fails(&["charmap", "catmull-clark", "--valence", "5", "--out", file.to_str().unwrap()]);
    assert!(err.contains(".eps") && err.contains(".pdf"), "{err}");
    assert!(!file.exists(), "nothing written");
}

/// The texts of an SVG's `<text>` elements.
fn svg_texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| Some(t[t.find('>')? + 1..t.find("</text>")?].trim().to_string()))
        .collect()
}

/// The most frequent `font-size` of an SVG (its tick labels).
fn tick_font(svg: &str) -> f64 {
    let mut counts = std::collections::BTreeMap::new();
    for part in svg.split("font-size=\"").skip(1) {
        *counts.entry(part.split('"').next().unwrap().to_string()).or_insert(0) += 1;
    }
    counts.into_iter().max_by_key(|c| c.1).expect("text in the figure").0.trim_end_matches("px").parse().unwrap()
}

#[test]
fn ring_figure_title_size_font_legend_and_ticks() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("ring.svg");
    let run = |extra: &[&str]| {
        let mut args = vec!["charmap", "non-box", "-n", "5", "--out", file.to_str().unwrap()];
        args.extend_from_slice(extra);
        let out = subdlab(&args);
        assert!(out.status.success(), "{extra:?}: {}", String::from_utf8_lossy(&out.stderr));
        std::fs::read_to_string(&file).unwrap()
    };
    // the default: the scheme's own title, no verdict in the figure, a
    // legend for the two colours and the control net, ticks without "-0"
    let svg = run(&[]);
    let texts = svg_texts(&svg);
    assert!(texts.iter().any(|t| t.starts_with("non-box n = 5: characteristic rings")), "{texts:?}");
    assert!(!texts.iter().any(|t| t.contains("regular") || t.contains("injective")), "no verdict: {texts:?}");
    for entry in ["ring, copies scaled by", "copies scaled by λ₁, λ₁³", "control net"] {
        assert!(texts.iter().any(|t| t.contains(entry)), "legend entry '{entry}' in {texts:?}");
    }
    let ticks: Vec<f64> = texts.iter().filter_map(|t| t.parse::<f64>().ok()).collect();
    assert!(ticks.len() >= 8, "numeric tick labels: {texts:?}");
    assert!(!texts.iter().any(|t| t == "-0" || t.starts_with("-0.0") && t.parse::<f64>() == Ok(0.0)), "{texts:?}");
    assert!(texts.iter().any(|t| t == "0"), "a zero tick reads 0: {texts:?}");

    // a title of the user's, a size, a larger font; and no title at all
    let svg = run(&["--title", "Figure 3", "--width", "640", "--height", "480", "--font-size", "24"]);
    assert_eq!(svg_size(&svg), (640, 480));
    let texts = svg_texts(&svg);
    assert!(texts.iter().any(|t| t == "Figure 3") && !texts.iter().any(|t| t.contains("characteristic rings")));
    // the tick labels (the most frequent size) scale from the default 16 to 24
    let (default_size, size) = (tick_font(&run(&[])), tick_font(&svg));
    assert!((size / default_size - 1.5).abs() < 0.1, "tick font {default_size} -> {size}");
    let svg = run(&["--title", ""]);
    let texts = svg_texts(&svg);
    assert!(!texts.iter().any(|t| t.contains("characteristic rings")), "{texts:?}");

    // out of range: a one-line input error before any work
    let err = fails(&["charmap", "non-box", "-n", "5", "--out", file.to_str().unwrap(), "--font-size", "200"]);
    assert!(err.contains("--font-size must be between 6 and 72, got 200"), "{err}");
}

#[test]
fn every_figure_command_takes_the_same_style_flags() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("f.svg");
    let f = file.to_str().unwrap();
    let style = ["--title", "My figure", "--width", "720", "--height", "540", "--font-size", "12"];
    let commands: [Vec<&str>; 6] = [
        vec!["charmap", "loop", "-n", "7", "--out", f],
        vec!["charmap", "loop", "-n", "7", "--wedge", "--out", f],
        vec!["plot", "spectrum", "loop", "--valences", "3..8", "--out", f],
        vec!["plot", "compare", "--curve", "loop", "--valences", "3..8", "--out", f],
        vec!["curvature", "loop", "-n", "7", "--out", f],
        vec!["sweep", "non-box", "--valences", "3..5", "--param", "a=0:1:1/4", "--plot", f],
    ];
    for args in commands {
        let args: Vec<&str> = args.into_iter().chain(style).collect();
        let out = subdlab(&args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let svg = std::fs::read_to_string(&file).unwrap();
        assert_eq!(svg_size(&svg), (720, 540), "{args:?}");
        let texts = svg_texts(&svg);
        assert!(texts.iter().any(|t| t == "My figure"), "{args:?}: {texts:?}");
        // numeric labels never read "-0"
        assert!(!texts.iter().any(|t| t.starts_with("-0") && t.parse::<f64>() == Ok(0.0)), "{args:?}: {texts:?}");
        // the curvature class (a verdict) is not drawn
        assert!(!texts.iter().any(|t| t.contains("unbounded") || t.contains("bounded")), "{args:?}: {texts:?}");
    }
}

/// The spectrum plot follows branches (Fourier block, rank in the block),
/// not ranks overall: Loop's block k carries 3/8 + cos(2πk/n)/4 (the
/// eigenvalue of its 1-ring rule's Fourier symbol), which is the largest of
/// block k for 2k < n (the other values of the 2-ring blocks are 1/8 and
/// below), so each branch is that closed form at every valence.
#[test]
fn spectrum_plot_branches_follow_fourier_blocks() {
    use subdlab::plot::spectrum::{leading_moduli, Branch, SpectrumFigure};
    let loop_scheme = subdlab::schemes::build("loop", &[]).unwrap();
    let rows = leading_moduli(loop_scheme.as_ref(), 5..=12).unwrap();
    let closed = |k: usize, n: usize| 0.375 + (2.0 * std::f64::consts::PI * k as f64 / n as f64).cos() / 4.0;
    for (n, points) in &rows {
        for k in [1usize, 2] {
            let got = points.iter().find(|p| p.0 == Branch { block: k, rank: 0 }).map(|p| p.1);
            assert!(
                got.is_some_and(|g| approx::abs_diff_eq!(g, closed(k, *n), epsilon = 1e-10)),
                "n = {n}, block {k}: {got:?} vs {}",
                closed(k, *n)
            );
        }
    }
    let fig =
        SpectrumFigure { scheme: "loop".into(), rows, count: 2, references: Vec::new(), style: Default::default() };
    let drawn: Vec<Branch> = fig.branches().into_iter().map(|b| b.0).collect();
    assert_eq!(drawn, vec![Branch { block: 1, rank: 0 }, Branch { block: 2, rank: 0 }]);
    let svg = subdlab::plot::render_svg(&fig).unwrap();
    let texts = svg_texts(&svg);
    assert!(texts.iter().any(|t| t == "block 1 (λ1)") && texts.iter().any(|t| t == "block 2"), "{texts:?}");
}

// ---------------------------------------------------------------------------
// Reading figures back: the SVG as XML, the axes from the tick labels, each
// curve from its legend entry, so a test compares what is drawn (in data
// units) with values it derives itself.

/// An SVG figure read as XML.
struct Drawn {
    texts: Vec<(f64, f64, String, String)>,
    /// (stroke colour, points) of every polyline
    lines: Vec<(String, Vec<(f64, f64)>)>,
    /// (fill colour, points) of every polygon
    polygons: Vec<(String, Vec<(f64, f64)>)>,
    /// (fill colour, x, y, width, height) of every rect
    rects: Vec<(String, f64, f64, f64, f64)>,
    size: (f64, f64),
}

fn points_of(text: &str) -> Vec<(f64, f64)> {
    text.split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

fn read_svg(svg: &str) -> Drawn {
    let doc = roxmltree::Document::parse(svg).expect("the figure is well-formed XML");
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    let num = |n: &roxmltree::Node, a: &str| n.attribute(a).unwrap_or("0").parse::<f64>().unwrap();
    let mut d = Drawn {
        texts: Vec::new(),
        lines: Vec::new(),
        polygons: Vec::new(),
        rects: Vec::new(),
        size: (num(&root, "width"), num(&root, "height")),
    };
    for n in doc.descendants().filter(|n| n.is_element()) {
        match n.tag_name().name() {
            "text" => d.texts.push((
                num(&n, "x"),
                num(&n, "y"),
                n.attribute("text-anchor").unwrap_or("").to_string(),
                n.text().unwrap_or("").trim().to_string(),
            )),
            "polyline" => {
                d.lines.push((n.attribute("stroke").unwrap().to_string(), points_of(n.attribute("points").unwrap())))
            }
            "polygon" => {
                d.polygons.push((n.attribute("fill").unwrap().to_string(), points_of(n.attribute("points").unwrap())))
            }
            "rect" => d.rects.push((
                n.attribute("fill").unwrap_or("").to_string(),
                num(&n, "x"),
                num(&n, "y"),
                num(&n, "width"),
                num(&n, "height"),
            )),
            _ => {}
        }
    }
    d
}

/// Least-squares line v = a + b·p through (pixel, value) pairs.
fn fit(pairs: &[(f64, f64)]) -> impl Fn(f64) -> f64 {
    assert!(pairs.len() >= 2, "at least two tick labels: {pairs:?}");
    let k = pairs.len() as f64;
    let (mp, mv) = (pairs.iter().map(|p| p.0).sum::<f64>() / k, pairs.iter().map(|p| p.1).sum::<f64>() / k);
    let b = pairs.iter().map(|p| (p.0 - mp) * (p.1 - mv)).sum::<f64>()
        / pairs.iter().map(|p| (p.0 - mp).powi(2)).sum::<f64>();
    move |p| mv + b * (p - mp)
}

impl Drawn {
    fn has_text(&self, t: &str) -> bool {
        self.texts.iter().any(|x| x.3 == t)
    }
    /// Pixel → data maps of the x axis (centred tick labels) and the y axis
    /// (right-aligned tick labels).
    fn axes(&self) -> (impl Fn(f64) -> f64, impl Fn(f64) -> f64) {
        let ticks = |anchor: &str, x: bool| -> Vec<(f64, f64)> {
            self.texts
                .iter()
                .filter(|t| t.2 == anchor)
                .filter_map(|t| Some((if x { t.0 } else { t.1 }, t.3.parse::<f64>().ok()?)))
                .collect()
        };
        (fit(&ticks("middle", true)), fit(&ticks("end", false)))
    }
    /// The stroke colour of the legend entry `label`: its sample line, the
    /// horizontal polyline just left of the text at its height.
    fn legend_colour(&self, label: &str) -> String {
        let t = self.texts.iter().find(|t| t.3 == label).unwrap_or_else(|| panic!("no legend entry '{label}'"));
        self.lines
            .iter()
            .filter(|(_, p)| p.len() == 2 && p[0].1 == p[1].1 && p[1].0 <= t.0 && p[1].0 > t.0 - 40.0)
            .min_by(|a, b| (a.1[0].1 - t.1).abs().total_cmp(&(b.1[0].1 - t.1).abs()))
            .unwrap_or_else(|| panic!("no legend sample for '{label}'"))
            .0
            .clone()
    }
    /// Whether a polyline is a legend sample: horizontal, just left of a
    /// left-aligned text at its height.
    fn is_legend_sample(&self, p: &[(f64, f64)]) -> bool {
        p.len() == 2
            && p[0].1 == p[1].1
            && self
                .texts
                .iter()
                .any(|t| t.2 == "start" && p[1].0 <= t.0 && p[1].0 > t.0 - 40.0 && (p[0].1 - t.1).abs() < 20.0)
    }
    /// Every point of the polylines of `colour` (legend samples left out), in data units.
    fn curve(&self, colour: &str, long_only: bool) -> Vec<(f64, f64)> {
        let (fx, fy) = self.axes();
        self.lines
            .iter()
            .filter(|(c, p)| c == colour && (!long_only || p.len() > 2) && !self.is_legend_sample(p))
            .flat_map(|(_, p)| p.iter().map(|&(x, y)| (fx(x), fy(y))))
            .collect()
    }
    /// Data units per pixel on (x, y).
    fn units_per_pixel(&self) -> (f64, f64) {
        let (fx, fy) = self.axes();
        ((fx(1.0) - fx(0.0)).abs(), (fy(1.0) - fy(0.0)).abs())
    }
}

/// Asserts every drawn point (n, v) lies on the piecewise-linear curve
/// through `want(k)` at the integers k (within two pixels).
fn assert_on_curve(drawn: &Drawn, pts: &[(f64, f64)], want: impl Fn(usize) -> f64, what: &str) {
    assert!(!pts.is_empty(), "{what}: nothing drawn");
    let (ux, uy) = drawn.units_per_pixel();
    for &(n, v) in pts {
        let (k0, t) = (n.floor().max(3.0), n - n.floor().max(3.0));
        let (a, b) = (want(k0 as usize), want(k0 as usize + 1));
        let expected = a + (b - a) * t.clamp(0.0, 1.0);
        let slope = (b - a).abs();
        assert!(
            (v - expected).abs() <= 2.0 * uy + 2.0 * ux * slope,
            "{what}: drawn ({n:.3}, {v:.5}), closed form {expected:.5}"
        );
    }
}

fn cc_lambda1(n: usize) -> f64 {
    // Catmull–Clark's subdominant eigenvalue (Doo–Sabin / Ball–Storry)
    let c = (2.0 * std::f64::consts::PI / n as f64).cos();
    let h = (std::f64::consts::PI / n as f64).cos();
    (5.0 + c + h * (18.0 + 2.0 * c).sqrt()) / 16.0
}

fn loop_lambda1(n: usize) -> f64 {
    0.375 + (2.0 * std::f64::consts::PI / n as f64).cos() / 4.0
}

fn png_size(bytes: &[u8]) -> (u32, u32) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let reader = decoder.read_info().expect("a PNG");
    let info = reader.info();
    (info.width, info.height)
}

#[test]
fn png_resolution_follows_dpi() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("ring.png");
    let f = file.to_str().unwrap();
    for (dpi, want) in [("72", (400, 300)), ("144", (800, 600)), ("300", (1667, 1250))] {
        let out = subdlab(&["charmap", "loop", "-n", "5", "-o", f, "--width", "400", "--height", "300", "--dpi", dpi]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let bytes = std::fs::read(&file).unwrap();
        assert_eq!(png_size(&bytes), want, "400 x 300 pt at {dpi} dpi");
        // the page is drawn: a white background and dark text and lines
        let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes)).read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let frame = reader.next_frame(&mut buf).unwrap();
        let px = &buf[..frame.buffer_size()];
        let channels = frame.color_type.samples();
        let dark = px.chunks(channels).filter(|c| c[..3].iter().all(|&v| v < 80)).count();
        let white = px.chunks(channels).filter(|c| c[..3].iter().all(|&v| v == 255)).count();
        assert!(dark > 100 && white > px.len() / channels / 3, "{dpi} dpi: {dark} dark, {white} white pixels");
    }
    for bad in ["0", "NaN", "-72", "1e9", "inf"] {
        let flag = format!("--dpi={bad}");
        let err = fails(&["charmap", "loop", "-n", "5", "-o", f, &flag]);
        assert!(err.contains("--dpi must be between 36 and 1200"), "{bad}: {err}");
    }
    // too many pixels: refused, nothing written
    std::fs::remove_file(&file).unwrap();
    let err = fails(&["charmap", "loop", "-n", "5", "-o", f, "--dpi", "1200", "--width", "6000", "--height", "6000"]);
    assert!(err.contains("lower --dpi"), "{err}");
    assert!(!file.exists());
}

#[test]
fn spectrum_plot_draws_labelled_dashed_reference_curves() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.svg");
    let f = file.to_str().unwrap();
    let expr = "3/8 + cos(2 pi / n)/4";
    let out = subdlab(&[
        "plot",
        "spectrum",
        "loop",
        "--valences",
        "3..12",
        "--reference",
        expr,
        "--reference",
        "1/2",
        "-o",
        f,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let d = read_svg(&std::fs::read_to_string(&file).unwrap());
    assert!(
        d.has_text("loop: leading eigenvalue moduli against valence") && d.has_text("valence n") && d.has_text("|λ|")
    );
    // the reference is drawn dashed: short pieces, each on Loop's λ1
    let colour = d.legend_colour(&format!("reference {expr}"));
    let dashes: Vec<_> = d.lines.iter().filter(|(c, p)| *c == colour && p.len() == 2).collect();
    assert!(dashes.len() > 20, "dashes, not one line: {}", dashes.len());
    let pts = d.curve(&colour, false);
    assert!(pts.iter().all(|p| p.0 >= 3.0 - 0.01 && p.0 <= 12.0 + 0.01), "from n = 3 to 12: {pts:?}");
    assert_on_curve(&d, &pts, loop_lambda1, "reference");
    let half = d.legend_colour("reference 1/2");
    assert_on_curve(&d, &d.curve(&half, false), |_| 0.5, "1/2");
    // the branch λ1 is the same closed form (for n ≥ 3 block 1 is Loop's λ1)
    let branch = d.legend_colour("block 1 (λ1)");
    assert_on_curve(&d, &d.curve(&branch, true), loop_lambda1, "block 1");
    // a bad expression: one line naming it
    let err = fails(&["plot", "spectrum", "loop", "--valences", "3..5", "--reference", "1/(n-4)", "-o", f]);
    assert!(err.contains("1/(n-4)") && err.contains("n = 4"), "{err}");
}

#[test]
fn comparison_figure_draws_each_scheme_with_its_legend() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("c.svg");
    let f = file.to_str().unwrap();
    let out = subdlab(&[
        "plot",
        "compare",
        "--curve",
        "catmull-clark",
        "--scheme",
        "loop",
        "--curve",
        "sqrt3",
        "--curve",
        "unified-sqrt3:alpha=0",
        "--valences",
        "3..14",
        "--quantity",
        "lambda1",
        "-o",
        f,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let d = read_svg(&std::fs::read_to_string(&file).unwrap());
    assert!(d.has_text("|λ1| against valence") && d.has_text("valence n") && d.has_text("|λ1|"));
    let cc = d.legend_colour("catmull-clark");
    assert_on_curve(&d, &d.curve(&cc, true), cc_lambda1, "catmull-clark");
    let lp = d.legend_colour("loop");
    assert_on_curve(&d, &d.curve(&lp, true), loop_lambda1, "loop");
    assert_ne!(cc, lp, "each curve its own colour");
    // Lin–Luo's α = 0 is Kobbelt's sqrt(3): the two curves coincide
    let (kobbelt, unified) =
        (d.curve(&d.legend_colour("sqrt3"), true), d.curve(&d.legend_colour("unified-sqrt3 (alpha = 0)"), true));
    assert_eq!(kobbelt.len(), 12);
    let (_, uy) = d.units_per_pixel();
    for (a, b) in kobbelt.iter().zip(&unified) {
        assert!((a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() <= uy, "{a:?} vs {b:?}");
    }
    // a ratio: |λ2| / |λ1| is 1 for the double subdominant pair of Catmull–Clark
    let out = subdlab(&[
        "plot",
        "compare",
        "--curve",
        "catmull-clark",
        "--quantity",
        "lambda2/lambda1",
        "--valences",
        "3..8",
        "-o",
        f,
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let d = read_svg(&std::fs::read_to_string(&file).unwrap());
    assert!(d.has_text("|λ2| / |λ1|"));
    assert_on_curve(&d, &d.curve(&d.legend_colour("catmull-clark"), true), |_| 1.0, "ratio");
    // bad requests: one line each
    for (args, want) in [
        (vec!["--curve", "loop", "--quantity", "lambda7"], "lambdaK"),
        (vec!["--curve", "loop:alpha"], "NAME=VALUE"),
        (vec!["--curve", "no-such-scheme"], "no-such-scheme"),
        (vec!["--curve", "loop", "--valences", "3..2"], "3..2"),
    ] {
        let mut all = vec!["plot", "compare", "-o", f];
        all.extend(args);
        let err = fails(&all);
        assert!(err.contains(want), "{all:?}: {err}");
    }
}

#[test]
fn sector_colouring_follows_the_angle() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("r.svg");
    let f = file.to_str().unwrap();
    for n in [5usize, 6, 11] {
        let out = subdlab(&["charmap", "catmull-clark", "-n", &n.to_string(), "--sectors", "--rings", "2", "-o", f]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let d = read_svg(&std::fs::read_to_string(&file).unwrap());
        // the ring is n-fold symmetric about the centre: the mean of its
        // vertices is the centre
        let all: Vec<(f64, f64)> = d.polygons.iter().flat_map(|p| p.1.iter().copied()).collect();
        let k = all.len() as f64;
        let c = all.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / k, a.1 + p.1 / k));
        let width = 2.0 * std::f64::consts::PI / n as f64;
        let mut colour_of: std::collections::BTreeMap<usize, String> = Default::default();
        for (fill, p) in &d.polygons {
            let m = p.len() as f64;
            let (x, y) = p.iter().fold((0.0, 0.0), |a, q| (a.0 + q.0 / m, a.1 + q.1 / m));
            // pixel y grows downwards
            let angle = (-(y - c.1)).atan2(x - c.0).rem_euclid(2.0 * std::f64::consts::PI);
            let t = angle / width;
            if (t - t.round()).abs() < 0.05 {
                continue; // on a spoke, within pixel rounding
            }
            let sector = t.floor() as usize;
            let known = colour_of.entry(sector).or_insert_with(|| fill.clone());
            assert_eq!(known, fill, "n = {n}: sector {sector} in one colour");
        }
        assert_eq!(colour_of.len(), n, "n = {n}: every sector drawn");
        for s in 0..n {
            assert_ne!(colour_of[&s], colour_of[&((s + 1) % n)], "n = {n}: sectors {s} and {} differ", (s + 1) % n);
        }
        if n <= 5 {
            for s in 0..n {
                assert!(d.has_text(&format!("sector {s}")), "n = {n}: legend entry for sector {s}");
            }
        }
        assert!(d.has_text("control net (subdominant eigenvectors)"));
    }
    let err = fails(&["charmap", "catmull-clark", "-n", "5", "--sectors", "--wedge", "-o", f]);
    assert!(err.contains("--sectors"), "{err}");
}

#[test]
fn sweep_figure_takes_the_style_flags_and_draws_the_computed_points() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("w.svg");
    let f = file.to_str().unwrap();
    let args = ["sweep", "non-box", "--valences", "3..6", "--param", "a=0:1:1/10"];
    let out = subdlab(&[&args[..], &["--json"]].concat());
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let style = ["--title", "Admissible a", "--width", "640", "--height", "480", "--font-size", "12", "--plot", f];
    let out = subdlab(&[&args[..], &style[..]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let svg = std::fs::read_to_string(&file).unwrap();
    let d = read_svg(&svg);
    assert_eq!(d.size, (640.0, 480.0));
    assert!(d.has_text("Admissible a") && d.has_text("parameter a") && d.has_text("valence n"));
    assert!((tick_font(&svg) - 12.0 * 96.0 / 96.0).abs() < 2.5, "tick font {}", tick_font(&svg));
    // the legend: each status's swatch colour, by its text
    let swatch = |label: &str| -> String {
        let t = d.texts.iter().find(|t| t.3 == label).unwrap_or_else(|| panic!("no legend entry '{label}'"));
        d.rects
            .iter()
            .filter(|r| r.1 < t.0 && (r.2 - t.1).abs() < 20.0)
            // nearest on the left, and of those at the same distance the
            // one at the text's height (legend rows may be under 20 apart)
            .min_by(|a, b| (t.0 - a.1).total_cmp(&(t.0 - b.1)).then((a.2 - t.1).abs().total_cmp(&(b.2 - t.1).abs())))
            .unwrap()
            .0
            .clone()
    };
    // each cell: its centre in data units is (a, n), its colour the status
    // the sweep computed for that point
    let (fx, fy) = d.axes();
    let cells: Vec<(f64, f64, String)> = d
        .rects
        .iter()
        .filter(|r| r.0 != "#FFFFFF" && r.4 > 5.0 && r.3 < 100.0)
        .map(|r| (fx(r.1 + r.3 / 2.0), fy(r.2 + r.4 / 2.0), r.0.clone()))
        .filter(|c| c.1 > 2.5)
        .collect();
    let points = json["points"].as_array().unwrap();
    assert_eq!(points.len(), 4 * 11);
    for p in points {
        let (n, a) = (p["valence"].as_u64().unwrap() as f64, p["param"].as_str().unwrap());
        let a: f64 = match a.split_once('/') {
            Some((x, y)) => x.parse::<f64>().unwrap() / y.parse::<f64>().unwrap(),
            None => a.parse().unwrap(),
        };
        let label = match (p["convergent"].as_bool().unwrap(), p["c1_spectral"].as_bool().unwrap()) {
            (_, true) => "spectral C¹",
            (true, false) => "converges, fails the spectral C¹ test",
            (false, false) => "does not converge (λ0 = 1 not simple and dominant)",
        };
        let cell = cells
            .iter()
            .find(|c| (c.0 - a).abs() < 0.03 && (c.1 - n).abs() < 0.2)
            .unwrap_or_else(|| panic!("no cell at a = {a}, n = {n}"));
        assert_eq!(cell.2, swatch(label), "a = {a}, n = {n}: {label}");
    }
    // style flags without a figure: one line
    let err = fails(&["sweep", "non-box", "--valences", "3..4", "--title", "x"]);
    assert!(err.contains("--plot"), "{err}");
}

#[test]
fn wedge_figure_has_a_legend_and_the_style_flags() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("w.svg");
    let f = file.to_str().unwrap();
    let out = subdlab(&[
        "charmap", "loop", "-n", "9", "--wedge", "-o", f, "--title", "", "--width", "500", "--height", "500",
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let d = read_svg(&std::fs::read_to_string(&file).unwrap());
    assert_eq!(d.size, (500.0, 500.0));
    assert!(d.has_text("sector 0 of the ring, angles stretched by n/4"));
    assert!(!d.texts.iter().any(|t| t.3.contains("characteristic wedge")), "no title");
    // the normalised wedge of sector [0, 2π/9) fills the quarter plane:
    // every drawn corner has x, y ≥ 0 (up to a pixel)
    let (fx, fy) = d.axes();
    let (ux, uy) = d.units_per_pixel();
    for (_, p) in &d.polygons {
        for &(x, y) in p {
            assert!(fx(x) >= -2.0 * ux && fy(y) >= -2.0 * uy, "({}, {}) outside the quarter plane", fx(x), fy(y));
        }
    }
}

/// Control characters in a title (XML 1.0 cannot carry them, even as
/// `&#1;`) are shown as their escapes, and `&<>"'` are escaped: every figure
/// command writes well-formed SVG, read back by an XML parser with the title
/// intact; PDF and PNG are made from the same SVG.
#[test]
fn titles_with_markup_and_control_characters_give_well_formed_figures() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("f.svg");
    let f = file.to_str().unwrap();
    let title = "a<b>&\"c'd\u{1}e\u{1b}[31m\u{7}\tf";
    let shown = "a<b>&\"c'd\\u{1}e\\u{1b}[31m\\u{7}\tf";
    let commands: [Vec<&str>; 6] = [
        vec!["charmap", "loop", "-n", "7", "--out", f],
        vec!["charmap", "loop", "-n", "7", "--wedge", "--out", f],
        vec!["plot", "spectrum", "loop", "--valences", "3..6", "--out", f],
        vec!["plot", "compare", "--curve", "loop", "--valences", "3..6", "--out", f],
        vec!["curvature", "loop", "-n", "7", "--out", f],
        vec!["sweep", "non-box", "--valences", "3..4", "--param", "a=0:1:1/2", "--plot", f],
    ];
    for args in commands {
        let args: Vec<&str> = args.into_iter().chain(["--title", title]).collect();
        let out = subdlab(&args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let svg = std::fs::read_to_string(&file).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{args:?}: not well-formed: {e}"));
        let texts: Vec<String> = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .map(|n| n.text().unwrap_or("").trim().to_string())
            .collect();
        assert!(texts.iter().any(|t| t == shown), "{args:?}: {texts:?}");
    }
    for ext in ["pdf", "png"] {
        let file = dir.path().join(format!("f.{ext}"));
        let out = subdlab(&["charmap", "loop", "-n", "7", "--title", title, "--out", file.to_str().unwrap()]);
        assert!(out.status.success(), "{ext}: {}", String::from_utf8_lossy(&out.stderr));
    }
}

/// The same figure is the same bytes: two processes (hash maps seeded
/// differently) with one and two worker threads write identical SVG and PDF.
#[test]
fn figures_are_byte_identical_across_runs_and_thread_counts() {
    let dir = tempfile::tempdir().unwrap();
    for ext in ["svg", "pdf"] {
        let figures: [&[&str]; 2] = [
            &["plot", "spectrum", "loop", "--valences", "3..8"],
            &["plot", "compare", "--curve", "loop", "--curve", "catmull-clark", "--valences", "3..8"],
        ];
        for args in figures {
            let bytes: Vec<Vec<u8>> = ["1", "2", "1"]
                .iter()
                .enumerate()
                .map(|(k, threads)| {
                    let file = dir.path().join(format!("f{k}.{ext}"));
                    let out = std::process::Command::new(env!("CARGO_BIN_EXE_subdlab"))
                        .args(args)
                        .args(["-o", file.to_str().unwrap()])
                        .env("RAYON_NUM_THREADS", threads)
                        .output()
                        .unwrap();
                    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
                    std::fs::read(file).unwrap()
                })
                .collect();
            assert!(bytes[0] == bytes[1] && bytes[1] == bytes[2], "{args:?} {ext}: runs differ");
        }
    }
}

//! Figure formats chosen by extension: the same figure as SVG, PDF and PNG,
//! each parsed back (SVG size and text, PDF header, page count, page size and
//! embedded font, PNG signature and size), and an unknown extension refused.

mod common;
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

    // the PNG has the same pixel size
    let png = std::fs::read(path("png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |k: usize| u32::from_be_bytes(png[k..k + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (w, h), "PNG IHDR size");
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
    let commands: [Vec<&str>; 3] = [
        vec!["charmap", "loop", "-n", "7", "--out", f],
        vec!["plot", "spectrum", "loop", "--valences", "3..8", "--out", f],
        vec!["curvature", "loop", "-n", "7", "--out", f],
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
    let fig = SpectrumFigure { scheme: "loop".into(), rows, count: 2, style: Default::default() };
    let drawn: Vec<Branch> = fig.branches().into_iter().map(|b| b.0).collect();
    assert_eq!(drawn, vec![Branch { block: 1, rank: 0 }, Branch { block: 2, rank: 0 }]);
    let svg = subdlab::plot::render_svg(&fig).unwrap();
    let texts = svg_texts(&svg);
    assert!(texts.iter().any(|t| t == "block 1 (λ1)") && texts.iter().any(|t| t == "block 2"), "{texts:?}");
}

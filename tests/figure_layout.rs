//! Figures that survive a paper's column: every figure type drawn at a grid
//! of sizes (240 × 160 to 1600 × 1200 points) and base font sizes (6 to 24
//! points), each SVG read back with usvg — which lays the text out itself
//! with the embedded font, independently of the figure code's own
//! measurements — and every text element's box (the font's advance widths
//! and its ascent to descent, in canvas coordinates, rotation included)
//! checked: no box overlaps another and none leaves the canvas. The data of
//! each figure is computed once; only the drawing is repeated.

use subdlab::charmap::{check_map, CharMapOptions};
use subdlab::curvature::{curvature_of_analysis, CurvatureOptions};
use subdlab::neighbourhood::{Configuration, NeighbourhoodKind};
use subdlab::plot::charmap::RingFigure;
use subdlab::plot::compare::{compare_lines, CompareFigure, CurveSpec, Quantity};
use subdlab::plot::curvature::{CurvatureFigure, CurvatureFigureKind};
use subdlab::plot::spectrum::{leading_moduli, SpectrumFigure};
use subdlab::plot::sweep::{Bound, SweepFigure};
use subdlab::plot::{render_svg, Figure, Style};
use subdlab::spectrum::{analyse, Options};

use resvg::usvg;

/// A text element of a drawn figure: its text and its box (x0, y0, x1, y1).
#[derive(Debug)]
struct TextBox {
    text: String,
    rect: (f32, f32, f32, f32),
}

/// The text boxes of an SVG as usvg lays them out with DejaVu Sans (the
/// figures' font; every family name resolves to it).
fn text_boxes(svg: &str) -> (Vec<TextBox>, (f32, f32)) {
    let font = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf")).unwrap();
    let mut options = usvg::Options { font_family: "DejaVu Sans".into(), ..usvg::Options::default() };
    options.fontdb_mut().load_font_data(font);
    options.fontdb_mut().set_sans_serif_family("DejaVu Sans");
    let tree = usvg::Tree::from_str(svg, &options).expect("the figure's SVG parses");
    fn walk(group: &usvg::Group, out: &mut Vec<TextBox>) {
        for node in group.children() {
            match node {
                usvg::Node::Group(g) => walk(g, out),
                usvg::Node::Text(t) => {
                    let text: String = t.chunks().iter().map(|c| c.text()).collect();
                    if text.trim().is_empty() {
                        continue;
                    }
                    let r = t.abs_bounding_box();
                    out.push(TextBox { text, rect: (r.left(), r.top(), r.right(), r.bottom()) });
                }
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    walk(tree.root(), &mut out);
    (out, (tree.size().width(), tree.size().height()))
}

/// What is wrong with a figure's text layout: boxes leaving the canvas and
/// pairs of overlapping boxes (a shared edge or a sliver under half a point
/// is not an overlap: box edges are rounded to whole points).
fn layout_faults(svg: &str) -> Vec<String> {
    const SLACK: f32 = 0.5;
    let (boxes, (w, h)) = text_boxes(svg);
    let mut faults = Vec::new();
    for b in &boxes {
        let (x0, y0, x1, y1) = b.rect;
        if x0 < -SLACK || y0 < -SLACK || x1 > w + SLACK || y1 > h + SLACK {
            faults.push(format!("'{}' {:?} leaves the {w} × {h} canvas", b.text, b.rect));
        }
    }
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            let dx = a.rect.2.min(b.rect.2) - a.rect.0.max(b.rect.0);
            let dy = a.rect.3.min(b.rect.3) - a.rect.1.max(b.rect.1);
            if dx > SLACK && dy > SLACK {
                faults.push(format!("'{}' {:?} overlaps '{}' {:?}", a.text, a.rect, b.text, b.rect));
            }
        }
    }
    faults
}

fn style(width: u32, height: u32, font: u32) -> Style {
    Style { width: Some(width), height: Some(height), font_size: Some(font), ..Style::default() }
}

/// The grid: the corners of the range, the README's column recipe, a one-
/// and a two-column figure, and a tall and a wide one.
const SIZES: [(u32, u32); 7] = [(240, 160), (240, 180), (480, 320), (500, 320), (1600, 1200), (240, 1200), (1600, 160)];
const FONTS: [u32; 5] = [6, 9, 12, 20, 24];

/// Every figure of `make` on the grid: the faults of each cell that drew,
/// and the cells that refused with their one-line errors.
fn check_grid<F: Figure>(name: &str, make: &dyn Fn(Style) -> F) -> Vec<String> {
    let mut faults = Vec::new();
    for (w, h) in SIZES {
        for f in FONTS {
            let fig = make(style(w, h, f));
            match render_svg(&fig) {
                Ok(svg) => {
                    // the checker must see the figure's text, or it checks nothing
                    assert!(text_boxes(&svg).0.len() >= 3, "{name} {w}×{h} font {f}: no text found");
                    for fault in layout_faults(&svg) {
                        faults.push(format!("{name} {w}×{h} font {f}: {fault}"));
                    }
                }
                Err(e) => faults.push(format!("{name} {w}×{h} font {f}: refused: {e}")),
            }
        }
    }
    faults
}

fn assert_clean(faults: Vec<String>) {
    assert!(faults.is_empty(), "{} layout faults, e.g.\n{}", faults.len(), faults[..faults.len().min(12)].join("\n"));
}

#[test]
fn ring_wedge_and_sector_figures_fit_every_size() {
    let scheme = subdlab::schemes::build("catmull-clark", &[]).unwrap();
    let config = Configuration::regular(scheme.as_ref(), 5).unwrap();
    let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
    let analysis = analyse(scheme.as_ref(), &config, &opts).unwrap();
    let map_opts = CharMapOptions { levels: 3, resolution: 256, display_levels: Some(3) };
    let map = check_map(scheme.as_ref(), &analysis, &map_opts).unwrap();
    let mut faults = Vec::new();
    for (copies, wedge, sectors) in [(3, false, false), (2, false, true), (1, true, false)] {
        faults.extend(check_grid("ring", &|style| RingFigure { map: &map, copies, wedge, sectors, style }));
    }
    assert_clean(faults);
}

#[test]
fn spectrum_and_comparison_figures_fit_every_size() {
    let scheme = subdlab::schemes::build("loop", &[]).unwrap();
    let rows = leading_moduli(scheme.as_ref(), 3..=12).unwrap();
    let valences: Vec<usize> = (3..=12).collect();
    let references = || Bound::over(&["3/8 + cos(2 pi/n)/4".to_string()], &[], &valences).unwrap();
    let mut faults = check_grid("spectrum", &|style| SpectrumFigure {
        scheme: "loop".into(),
        rows: rows.clone(),
        count: 6,
        references: references(),
        style,
    });
    let specs: Vec<CurveSpec> = ["catmull-clark", "loop", "loop", "unified-sqrt3:alpha=1"]
        .iter()
        .map(|s| CurveSpec::parse(s).unwrap())
        .collect();
    let quantity = Quantity::parse("lambda1").unwrap();
    let lines = compare_lines(&specs, "3..12", quantity, 1).unwrap();
    faults.extend(check_grid("compare", &|style| CompareFigure {
        quantity,
        lines: lines
            .iter()
            .map(|l| subdlab::plot::lines::Line { label: l.label.clone(), points: l.points.clone() })
            .collect(),
        references: references(),
        valences: (3, 12),
        style,
    }));
    assert_clean(faults);
}

#[test]
fn sweep_figure_fits_every_size() {
    let params = vec![("a".to_string(), "0:1:1/20".to_string())];
    let grid = subdlab::sweep::Grid::parse("non-box", "3..10", None, &params, false).unwrap();
    let points = subdlab::sweep::run_on(&grid, 1, &|_, _| {}).unwrap();
    let bounds = || Bound::all_of(&grid, &["1/4 - cos(2 pi / n)/4".to_string()]).unwrap();
    let faults = check_grid("sweep", &|style| {
        let mut fig = SweepFigure::new("non-box", Some("a"), &points, false, bounds()).unwrap();
        fig.style = style;
        fig
    });
    assert_clean(faults);
}

#[test]
fn curvature_figures_fit_every_size() {
    let mut faults = Vec::new();
    for (name, n, kind, rings) in
        [("loop", 7, CurvatureFigureKind::CentralRing, 0), ("catmull-clark", 5, CurvatureFigureKind::Surface, 3)]
    {
        let scheme = subdlab::schemes::build(name, &[]).unwrap();
        let config = Configuration::regular(scheme.as_ref(), n).unwrap();
        let opts = Options { neighbourhood: NeighbourhoodKind::Analysis, method: None, exact: false };
        let analysis = analyse(scheme.as_ref(), &config, &opts).unwrap();
        let copts =
            CurvatureOptions { figures: true, surface_rings: rings, exact: false, ..CurvatureOptions::default() };
        let c = curvature_of_analysis(scheme.as_ref(), &analysis, &copts).unwrap();
        faults.extend(check_grid(name, &|style| CurvatureFigure { c: &c, kind, style }));
    }
    assert_clean(faults);
}

#[test]
fn shape_chart_figures_fit_every_size() {
    use subdlab::plot::shape_chart::{HeatMap, ThetaChart};
    use subdlab::shape_chart::{chart, ChartOptions, ShapeChart};
    let scheme = subdlab::schemes::build("catmull-clark", &[]).unwrap();
    let opts = ChartOptions {
        ts: (0..9).map(|i| -1.0 + i as f64 / 4.0).collect(),
        thetas: 3,
        steps: vec![0, 3],
        levels: 1,
        iterated: None,
    }
    .checked()
    .unwrap();
    let valences: Vec<_> = (3..=6)
        .map(|n| chart(scheme.as_ref(), &Configuration::regular(scheme.as_ref(), n).unwrap(), &opts).unwrap())
        .collect();
    let sc = ShapeChart {
        scheme: "catmull-clark".into(),
        params: Default::default(),
        ts: opts.ts.clone(),
        steps: opts.steps.clone(),
        levels: opts.levels,
        theta_chart: None,
        valences,
    };
    let mut faults = check_grid("shape chart", &|style| HeatMap { chart: &sc, style });
    faults.extend(check_grid("t × θ chart", &|style| ThetaChart { chart: &sc, valence: &sc.valences[2], style }));
    assert_clean(faults);
}

/// The pixels of an SVG rasterised by resvg at 1 px per point, with the
/// embedded font or with no font at all (a viewer that has none of ours).
fn raster(svg: &str, with_font: bool) -> Vec<u8> {
    let mut options = usvg::Options::default();
    if with_font {
        let font = std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/assets/fonts/DejaVuSans.ttf")).unwrap();
        options.fontdb_mut().load_font_data(font);
        options.fontdb_mut().set_sans_serif_family("DejaVu Sans");
    }
    let tree = usvg::Tree::from_str(svg, &options).unwrap();
    let (w, h) = (tree.size().width().ceil() as u32, tree.size().height().ceil() as u32);
    let mut pixmap = resvg::tiny_skia::Pixmap::new(w, h).unwrap();
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, resvg::tiny_skia::Transform::identity(), &mut pixmap.as_mut());
    pixmap.data().to_vec()
}

/// How many pixels differ by more than a faint anti-aliasing step.
fn differing_pixels(a: &[u8], b: &[u8]) -> usize {
    assert_eq!(a.len(), b.len());
    a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| p.iter().zip(q.iter()).any(|(x, y)| x.abs_diff(*y) > 48)).count()
}

/// A saved SVG draws its text as the embedded font's glyph outlines: a
/// viewer with no font at all shows it as the plain SVG looks with the
/// embedded font. The control: the plain SVG (text elements only) in that
/// viewer loses its text, so the comparison can fail.
#[test]
fn saved_svg_text_is_outlined_and_looks_the_same_without_any_font() {
    let scheme = subdlab::schemes::build("loop", &[]).unwrap();
    let rows = leading_moduli(scheme.as_ref(), 3..=9).unwrap();
    let fig = SpectrumFigure { scheme: "loop".into(), rows, count: 4, references: Vec::new(), style: Style::default() };
    let plain = render_svg(&fig).unwrap();
    let saved = subdlab::plot::render_svg_outlined(&fig).unwrap();
    let reference = raster(&plain, true);
    let text_pixels = differing_pixels(&raster(&plain, false), &reference);
    assert!(text_pixels > 2000, "the control: without a font the plain SVG loses its text ({text_pixels} pixels)");
    let off = differing_pixels(&raster(&saved, false), &reference);
    assert!(off * 100 < text_pixels, "the outlined SVG without a font differs in {off} pixels (text: {text_pixels})");
    // every text is still there, invisible, for search and scripts, and
    // laid out as before
    let texts = |svg: &str| svg.matches("<text").count();
    assert_eq!(texts(&saved), texts(&plain));
    assert_eq!(saved.matches("<text fill-opacity=\"0\"").count(), texts(&plain));
    assert!(texts(&plain) >= 10);
    assert!(layout_faults(&saved).is_empty() && text_boxes(&saved).0.len() == text_boxes(&plain).0.len());
}

/// The checker itself: two texts drawn on top of each other, and one past
/// the right edge, are caught; two texts side by side are not.
#[test]
fn the_checker_sees_overlaps_and_clipping() {
    let svg = |body: &str| {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"100\" viewBox=\"0 0 200 100\">{body}</svg>"
        )
    };
    let text = |x: i32, y: i32, s: &str| {
        format!("<text x=\"{x}\" y=\"{y}\" font-family=\"sans-serif\" font-size=\"10\">{s}</text>")
    };
    // "abc" at 10 px is about 18 px wide (DejaVu's advances 0.61, 0.63, 0.55 em)
    assert!(layout_faults(&svg(&(text(10, 20, "abc") + &text(40, 20, "abc")))).is_empty());
    assert_eq!(layout_faults(&svg(&(text(10, 20, "abc") + &text(20, 22, "abc")))).len(), 1);
    assert_eq!(layout_faults(&svg(&text(190, 50, "abc"))).len(), 1);
    // rotated by 270° about its anchor, a text at the left edge reaches above it
    let rotated = "<text x=\"20\" y=\"5\" transform=\"rotate(270, 20, 5)\" font-family=\"sans-serif\" font-size=\"10\">abc</text>";
    assert_eq!(layout_faults(&svg(rotated)).len(), 1);
}

/// Any SVG files (paths separated by `:` in SUBDLAB_LAYOUT_SVGS) checked the
/// same way: how a figure drawn by another build (e.g. main's, at the
/// README's recipe) was found to fail. Without the variable: nothing.
#[test]
fn svg_files_named_in_the_environment() {
    let Ok(paths) = std::env::var("SUBDLAB_LAYOUT_SVGS") else { return };
    let mut faults = Vec::new();
    for path in paths.split(':').filter(|p| !p.is_empty()) {
        let svg = std::fs::read_to_string(path).unwrap();
        faults.extend(layout_faults(&svg).into_iter().map(|f| format!("{path}: {f}")));
    }
    assert_clean(faults);
}

/// `--data` writes the plotted numbers: two identical Loop curves (drawn
/// with different line styles and markers, so both stay visible) whose
/// values are Loop's closed-form λ1 = 3/8 + cos(2π/n)/4, and `--label`
/// names them in the CSV as in the legend.
#[test]
fn data_export_of_two_identical_curves_and_their_labels() {
    let dir = tempfile::tempdir().unwrap();
    let (svg, csv) = (dir.path().join("c.svg"), dir.path().join("c.csv"));
    let out = crate::common::subdlab(&[
        "plot",
        "compare",
        "--curve",
        "loop",
        "--curve",
        "loop",
        "--label",
        "first",
        "--label",
        "second",
        "--valences",
        "3..8",
        "--width",
        "240",
        "--height",
        "160",
        "--font-size",
        "8",
        "-o",
        svg.to_str().unwrap(),
        "--data",
        csv.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("kind,series,valence,value"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 12, "6 valences × 2 curves");
    for (k, label) in ["first", "second"].iter().enumerate() {
        for (i, n) in (3..=8).enumerate() {
            let row = &rows[6 * k + i];
            assert_eq!((row[0], row[1], row[2]), ("curve", *label, n.to_string().as_str()));
            let closed = 3.0 / 8.0 + (2.0 * std::f64::consts::PI / n as f64).cos() / 4.0;
            let v: f64 = row[3].parse().unwrap();
            assert!((v - closed).abs() < 1e-10, "n = {n}: {v} vs {closed}");
        }
    }
    let drawn = std::fs::read_to_string(&svg).unwrap();
    assert!(drawn.contains("\nfirst\n") && drawn.contains("\nsecond\n"), "the labels are the legend's");
    assert!(layout_faults(&drawn).is_empty());
}

/// Bad values of the new flags: one line on stderr, non-zero exit.
#[test]
fn bad_legend_limits_labels_and_data_are_one_line_errors() {
    let out = |ext: &str| std::env::temp_dir().join(format!("subdlab-layout-never-written.{ext}"));
    let svg = out("svg");
    let svg = svg.to_str().unwrap();
    for (extra, needle) in [
        (vec!["--legend", "sideways"], "--legend"),
        (vec!["--xlim", "5:3"], "--xlim"),
        (vec!["--ylim", "0:nan"], "--ylim"),
        (vec!["--label", "a", "--label", "b"], "--label"),
        (vec!["--data", "numbers.txt"], ".csv"),
    ] {
        let mut args = vec!["plot", "compare", "--curve", "loop", "--valences", "3..5", "-o", svg];
        args.extend(extra.iter());
        let err = crate::common::fails(&args);
        assert!(err.contains(needle), "{extra:?}: {err}");
    }
    let err = crate::common::fails(&["curvature", "loop", "-n", "7", "-o", svg, "--xlim", "0:1"]);
    assert!(err.contains("--xlim"), "{err}");
}

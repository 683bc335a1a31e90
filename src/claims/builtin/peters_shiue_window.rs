//! Peters–Shiue's regular 4-3 rules on a lattice window (section 3.1,
//! `claims/peters-shiue.toml`): polynomial reproduction, the box spline the
//! rules subdivide, and the checkerboard in the kernel.

use num_traits::Zero;

use crate::claims::builtin::data::{
    field, int_in, ints_of, lattice_node, small_window, window_evidence, MAX_DATA_WINDOW,
};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::numeric::exact::q;
use crate::numeric::Rational;

/// The samples of the polynomials of total degree ≤ `degree` on a lattice
/// window span a space that S maps into itself (S: coarse points of the
/// window to the refined points at the same positions, fine units): the
/// scheme maps polynomial data of that degree to polynomial data of that
/// degree, so its limits of such data are those polynomials' space (the
/// regular box-spline schemes "reproduce all polynomials of degree ≤ d").
/// Also reports the first degree that is not kept.
pub fn window_polynomials(data: &toml::Value) -> Result<Finding, Error> {
    use crate::spectrum::strip::{action_on, window_matrices};
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    // a polynomial of degree ≤ d + 1 is determined by its samples only while
    // d + 1 is below the window's width and height
    let side = (w[1] - w[0]).min(w[3] - w[2]);
    let degree = int_in(data, "degree", 0, (side - 1).max(0))? as u32;
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let samples = |d: u32| -> Vec<Vec<Rational>> {
        (0..=d)
            .flat_map(|t| (0..=t).map(move |b| (t - b, b)))
            .map(|(a, b)| window.iter().map(|p| Rational::from_integer((p[0].pow(a) * p[1].pow(b)).into())).collect())
            .collect()
    };
    let kept = |d: u32| action_on(&s, &samples(d)).is_some();
    let holds = kept(degree);
    let next = (degree + 1..=degree + 3).find(|&d| !kept(d));
    Ok(Finding::new(
        holds,
        format!("polynomial data of degree ≤ {degree} stay polynomial of degree ≤ {degree}"),
        format!(
            "degree ≤ {degree}: {}; first degree not kept: {}",
            if holds { "kept" } else { "not kept" },
            next.map(|d| d.to_string()).unwrap_or_else(|| format!("above {}", degree + 3))
        ),
        window_evidence(data, &w, window.len())?,
    ))
}

/// The rules on a regular window are subdivision of the box spline with the
/// given `directions` (chart coordinates), and that box spline has the stated
/// `degree` and smoothness C^`smoothness`. The mask is the box spline's own:
/// symbol 4 Π_ξ (1 + z^ξ)/2, centred (primal); row p of S (fine position p)
/// must hold mask(p − 2q) on the coarse point q, exactly. Degree and
/// smoothness follow from the directions alone (de Boor–Höllig–Riemenschneider,
/// *Box Splines*, ch. I): m directions in the plane give degree m − 2, and the
/// box spline is C^(r−2) where r is the fewest directions whose removal leaves
/// a set that does not span the plane (all but the most populous line).
pub fn window_box_spline(data: &toml::Value) -> Result<Finding, Error> {
    use crate::spectrum::strip::window_matrices;
    use std::collections::HashMap;
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    let directions: Vec<[i64; 2]> = field(data, "directions")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.directions: a list of [x, y]".into()))?
        .iter()
        .map(|d| match ints_of(d, "data.directions")?.as_slice() {
            [x, y] if (x.abs() <= 4 && y.abs() <= 4) && (*x, *y) != (0, 0) => Ok([*x, *y]),
            _ => Err(Error::Claim("data.directions: non-zero [x, y] with entries in -4..4".into())),
        })
        .collect::<Result<_, _>>()?;
    if !(3..=12).contains(&directions.len()) {
        return Err(Error::Claim("data.directions: 3 to 12 directions".into()));
    }
    let stated_degree = int_in(data, "degree", 0, 20)?;
    let stated_smoothness = int_in(data, "smoothness", -1, 20)?;
    // the mask: coefficients of Π (1 + z^ξ), centred, over 2^m / 4
    let mut poly: HashMap<[i64; 2], i64> = HashMap::from([([0, 0], 1)]);
    for d in &directions {
        let mut next = poly.clone();
        for (p, c) in &poly {
            *next.entry([p[0] + d[0], p[1] + d[1]]).or_insert(0) += c;
        }
        poly = next;
    }
    let sum = directions.iter().fold([0, 0], |a, d| [a[0] + d[0], a[1] + d[1]]);
    if sum[0] % 2 != 0 || sum[1] % 2 != 0 {
        return Err(Error::Claim("the directions sum to an odd vector: not a primal box spline".into()));
    }
    let den = (1i64 << directions.len()) / 4;
    let mask = |p: [i64; 2]| q(*poly.get(&[p[0] + sum[0] / 2, p[1] + sum[1] / 2]).unwrap_or(&0), den);
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let mut differ = Vec::new();
    for (r, p) in window.iter().enumerate() {
        for (c, qq) in window.iter().enumerate() {
            let want = mask([p[0] - 2 * qq[0], p[1] - 2 * qq[1]]);
            if s[r][c] != want {
                differ.push(format!("fine {p:?} on coarse {qq:?}: rules {}, mask {want}", s[r][c]));
            }
        }
    }
    // smoothness: directions grouped by the line they span
    let mut lines: Vec<([i64; 2], usize)> = Vec::new();
    for d in &directions {
        match lines.iter_mut().find(|(l, _)| l[0] * d[1] - l[1] * d[0] == 0) {
            Some((_, k)) => *k += 1,
            None => lines.push((*d, 1)),
        }
    }
    let most = lines.iter().map(|l| l.1).max().unwrap_or(0);
    let (degree, smoothness) = (directions.len() as i64 - 2, (directions.len() - most) as i64 - 2);
    let holds = differ.is_empty() && degree == stated_degree && smoothness == stated_smoothness;
    Ok(Finding::new(
        holds,
        format!("the rules are the box spline of {directions:?}: degree {stated_degree}, C^{stated_smoothness}"),
        format!(
            "{}; degree {degree}, C^{smoothness} ({} directions on {} lines, at most {most} on one)",
            if differ.is_empty() {
                "every weight is the box-spline mask's".to_string()
            } else {
                format!(
                    "{} weights differ from the mask: {}",
                    differ.len(),
                    differ.iter().take(3).cloned().collect::<Vec<_>>().join("; ")
                )
            },
            directions.len(),
            lines.len()
        ),
        window_evidence(data, &w, window.len())?,
    ))
}

/// Section 3.1 of the 4-3 paper: the ±1 checkerboard coefficient sequence
/// "generates the zero function" (the A_4 box splines are linearly
/// dependent). One step of the node's rules on a lattice window maps the
/// samples (−1)^(x + y) to zero exactly; then every later net is zero, and so
/// is the limit.
pub fn window_checkerboard_kernel(data: &toml::Value) -> Result<Finding, Error> {
    use crate::spectrum::strip::window_matrices;
    let (scheme, config, spokes) = lattice_node(data)?;
    let w = small_window(data, MAX_DATA_WINDOW)?;
    let window: Vec<[i64; 2]> = (w[2]..=w[3]).flat_map(|y| (w[0]..=w[1]).map(move |x| [x, y])).collect();
    let s = window_matrices(scheme.as_ref(), &config, &spokes, &window, &[[0, 0]])?.pop().expect("one matrix");
    let c: Vec<Rational> =
        window.iter().map(|p| if (p[0] + p[1]).rem_euclid(2) == 0 { q(1, 1) } else { q(-1, 1) }).collect();
    let image: Vec<Rational> =
        s.iter().map(|row| row.iter().zip(&c).fold(q(0, 1), |a, (x, y)| a + x.clone() * y.clone())).collect();
    let nonzero: Vec<String> = window
        .iter()
        .zip(&image)
        .filter(|(_, v)| !v.is_zero())
        .take(4)
        .map(|(p, v)| format!("{v} at ({}, {})", p[0], p[1]))
        .collect();
    let count = image.iter().filter(|v| !v.is_zero()).count();
    Ok(Finding::new(
        count == 0,
        "one step maps the checkerboard (−1)^(x + y) to zero (it generates the zero function)".into(),
        if count == 0 {
            "zero at every refined point of the window".into()
        } else {
            format!("{count} refined points non-zero, e.g. {}", nonzero.join(", "))
        },
        window_evidence(data, &w, window.len())?,
    ))
}

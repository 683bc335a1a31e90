//! Khan–Mustafa's lattice schemes (`claims/khan-mustafa.toml`): the printed
//! masks against the exact least-squares fit they are derived from.

use crate::claims::builtin::data::{field, int, int_in};
use crate::claims::verdict::Finding;
use crate::error::Error;
use crate::numeric::exact::q;
use crate::numeric::Rational;

// ---------------------------------------------------------------- Khan–Mustafa: rules from a fit

/// The printed rules against the exact least-squares fit of span{x^a y^b}
/// (`monomials`) to the grid {lo..hi}², evaluated at the new points (α/2, β/2).
/// `rules` lists the four printed masks in the order p_{2i,2j}, p_{2i+1,2j},
/// p_{2i,2j+1}, p_{2i+1,2j+1}; mask[r − lo][s − lo] is the numerator (over
/// `denominator`) of the weight of p_{i+r, j+s}.
pub fn lattice_fit_masks(data: &toml::Value) -> Result<Finding, Error> {
    use crate::lattice::fit::{derive_masks, grid, least_squares};
    let monomials: Vec<(u32, u32)> = field(data, "monomials")?
        .as_array()
        .ok_or_else(|| Error::Claim("data.monomials: a list of [a, b] exponents".into()))?
        .iter()
        .map(|m| {
            let e =
                m.as_array().filter(|e| e.len() == 2).ok_or_else(|| Error::Claim("each monomial is [a, b]".into()))?;
            let exponent = |v: &toml::Value| match int(v, "an exponent")? {
                x @ 0..=6 => Ok(x as u32),
                x => Err(Error::Claim(format!("monomial exponent {x} is outside the supported range 0..6"))),
            };
            Ok((exponent(&e[0])?, exponent(&e[1])?))
        })
        .collect::<Result<_, Error>>()?;
    let (lo, hi) = (int_in(data, "lo", -4, 4)?, int_in(data, "hi", -4, 4)?);
    if lo >= hi {
        return Err(Error::Claim(format!("data.lo = {lo} must be below data.hi = {hi}")));
    }
    let den = int(field(data, "denominator")?, "data.denominator")?;
    if den == 0 {
        return Err(Error::Claim("data.denominator must not be 0".into()));
    }
    let den = Rational::from_integer(den.into());
    let rules = field(data, "rules")?
        .as_array()
        .filter(|r| r.len() == 4)
        .ok_or_else(|| Error::Claim("data.rules: four masks".into()))?;
    let size = (hi - lo + 1) as usize;
    let derived = derive_masks(&monomials, &grid(lo, hi), &q(1, 1))?;
    let samples: Vec<(Rational, Rational)> = grid(lo, hi)
        .iter()
        .map(|&(r, s)| (Rational::from_integer(r.into()), Rational::from_integer(s.into())))
        .collect();
    let interpolates = least_squares(&monomials, &samples)?.interpolates();
    let names = ["p_{2i,2j}", "p_{2i+1,2j}", "p_{2i,2j+1}", "p_{2i+1,2j+1}"];
    let mut diffs = Vec::new();
    for (k, &(a, b)) in [(0usize, 0usize), (1, 0), (0, 1), (1, 1)].iter().enumerate() {
        let rows = rules[k]
            .as_array()
            .filter(|r| r.len() == size)
            .ok_or_else(|| Error::Claim("each mask is a square grid".into()))?;
        for (ri, row) in rows.iter().enumerate() {
            let row = row
                .as_array()
                .filter(|r| r.len() == size)
                .ok_or_else(|| Error::Claim("each mask is a square grid".into()))?;
            for (si, x) in row.iter().enumerate() {
                let printed = Rational::from_integer(int(x, "a mask entry")?.into()) / &den;
                let (r, s) = (lo + ri as i64, lo + si as i64);
                let fit = derived[a][b].iter().find(|e| e.0 == (r, s)).map(|e| e.1.clone()).unwrap_or_default();
                if printed != fit {
                    diffs.push(format!("{}: p_{{i{r:+},j{s:+}}} printed {printed}, fit {fit}", names[k]));
                }
            }
        }
    }
    Ok(Finding::new(
        diffs.is_empty(),
        format!("4 printed masks on the {size}×{size} grid"),
        if diffs.is_empty() {
            "every weight is the least-squares fit's".into()
        } else {
            format!("{} weights differ from the least-squares fit", diffs.len())
        },
        format!(
            "exact least squares of {} monomials on {} points ({}); {}",
            monomials.len(),
            size * size,
            if interpolates { "the fit interpolates" } else { "more points than monomials: a fit, not an interpolant" },
            if diffs.is_empty() { "all weights agree".into() } else { diffs.join("; ") }
        ),
    ))
}

//! Recognising small rationals in floating-point results, so that 0.25 is shown
//! as 1/4 the way papers print it. A recognised value is a reading aid, not a
//! proof: exact claims come from the exact path (`numeric::exact`).

/// The continued-fraction convergents p/q of x with q ≤ `max_den`: its best
/// rational approximations, in order of growing denominator.
pub fn convergents(x: f64, max_den: i64) -> Vec<(i64, i64)> {
    let mut out = Vec::new();
    if !x.is_finite() || x.abs() > 1e9 {
        return out;
    }
    let (mut h0, mut h1) = (0i64, 1i64);
    let (mut k0, mut k1) = (1i64, 0i64);
    let mut r = x;
    for _ in 0..64 {
        let a = r.floor();
        if a.abs() > 1e12 {
            break;
        }
        let a = a as i64;
        let (Some(h2), Some(k2)) =
            (a.checked_mul(h1).and_then(|t| t.checked_add(h0)), a.checked_mul(k1).and_then(|t| t.checked_add(k0)))
        else {
            break;
        };
        if k2 > max_den || k2 <= 0 {
            break;
        }
        out.push((h2, k2));
        (h0, h1, k0, k1) = (h1, h2, k1, k2);
        let frac = r - a as f64;
        if frac.abs() < 1e-300 {
            break;
        }
        r = 1.0 / frac;
    }
    out
}

/// The fraction p/q with the smallest q ≤ `max_den` within `tol` of x.
pub fn small_rational(x: f64, max_den: i64, tol: f64) -> Option<(i64, i64)> {
    convergents(x, max_den).into_iter().find(|&(p, q)| (x - p as f64 / q as f64).abs() <= tol)
}

pub fn format_ratio(p: i64, q: i64) -> String {
    if q == 1 {
        format!("{p}")
    } else {
        format!("{p}/{q}")
    }
}

/// "1/4" for 0.25 (tolerance scaled to the value), else None.
pub fn recognise(x: f64) -> Option<String> {
    small_rational(x, 1024, 1e-10 * x.abs().max(1.0)).map(|(p, q)| format_ratio(p, q))
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn recognises_paper_fractions() {
        assert_eq!(recognise(0.25).as_deref(), Some("1/4"));
        assert_eq!(recognise(0.375).as_deref(), Some("3/8"));
        assert_eq!(recognise(1.0 / 24.0).as_deref(), Some("1/24"));
        assert_eq!(recognise(-1.0 / 12.0).as_deref(), Some("-1/12"));
        assert_eq!(recognise(0.0).as_deref(), Some("0"));
        assert_eq!(recognise(std::f64::consts::PI / 10.0), None);
    }
}

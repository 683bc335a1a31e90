//! Reif's spectral conditions for C^1 (with the characteristic map test done
//! separately): λ0 = 1 simple; λ1 = λ2 real, positive, non-defective, with
//! multiplicity exactly two; every other eigenvalue strictly smaller in modulus.

use serde::Serialize;

use super::eigenvalue::{fmt_f, Eigenvalue};

const TOL: f64 = 1e-9;

#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    /// which criterion: "reif" (an interior point: λ1 = λ2 double) or
    /// "sector" (a tagged vertex: see [`sector`])
    pub criterion: &'static str,
    pub c1_spectral: bool,
    /// λ0 = 1 simple and strictly dominant: the spectral condition for the
    /// scheme to converge at the extraordinary point
    pub convergent: bool,
    pub reasons: Vec<String>,
    /// the reasons that fail the criterion (a subset of `reasons`, in the
    /// same order; empty when it passes): what a sweep prints as the
    /// failing condition
    pub failures: Vec<String>,
    /// the subdominant eigenvalue λ1 (when λ0 = 1 is found)
    pub subdominant: Option<f64>,
    /// Fourier blocks holding the subdominant pair
    pub subdominant_blocks: Vec<usize>,
    /// modulus of the next eigenvalue after the subdominant one
    pub sub_subdominant: Option<f64>,
    /// |λ3| / λ1^2: < 1 bounded curvature tends to zero, = 1 bounded, > 1 unbounded
    pub lambda3_over_lambda1_squared: Option<f64>,
}

/// The reasons of a verdict as they are found, each marked as passing or
/// failing (the failing ones are also [`Verdict::failures`]).
#[derive(Default)]
struct Reasons {
    all: Vec<String>,
    failed: Vec<String>,
}

impl Reasons {
    fn push(&mut self, why: String) {
        self.all.push(why);
    }
    fn fail(&mut self, why: String) {
        self.failed.push(why.clone());
        self.all.push(why);
    }
    fn into_verdict(self, v: &mut Verdict) {
        v.reasons = self.all;
        v.failures = self.failed;
    }
}

/// λ0 = 1 and simple (the first eigenvalue, by modulus), with the reason.
fn dominant_one(eigs: &[Eigenvalue], reasons: &mut Reasons) -> bool {
    let Some(l0) = eigs.first() else {
        reasons.fail("empty spectrum".into());
        return false;
    };
    if (l0.re - 1.0).abs() > TOL || l0.im.abs() > TOL {
        reasons.fail(format!("dominant eigenvalue is {} (modulus {:.6}), not 1", l0.display(), l0.modulus));
        false
    } else if l0.algebraic_multiplicity != 1 {
        reasons.fail(format!("eigenvalue 1 has multiplicity {}, not 1", l0.algebraic_multiplicity));
        false
    } else {
        reasons.push("λ0 = 1 is simple".into());
        true
    }
}

pub fn reif(eigs: &[Eigenvalue]) -> Verdict {
    let mut reasons = Reasons::default();
    let mut ok = true;
    let mut v = Verdict {
        criterion: "reif",
        c1_spectral: false,
        convergent: false,
        reasons: Vec::new(),
        failures: Vec::new(),
        subdominant: None,
        subdominant_blocks: Vec::new(),
        sub_subdominant: None,
        lambda3_over_lambda1_squared: None,
    };
    if eigs.is_empty() {
        v.reasons.push("empty spectrum".into());
        v.failures.push("empty spectrum".into());
        return v;
    }
    ok &= dominant_one(eigs, &mut reasons);
    let dominant_one = ok;
    v.convergent = dominant_one && eigs.get(1).is_none_or(|l1| l1.modulus < 1.0 - TOL);
    let Some(l1) = eigs.get(1) else {
        reasons.fail("no subdominant eigenvalue".into());
        reasons.into_verdict(&mut v);
        return v;
    };
    v.subdominant = Some(l1.re);
    v.subdominant_blocks = l1.blocks.clone();
    if !l1.is_real() {
        ok = false;
        reasons.fail(format!("subdominant eigenvalue {} is not real", l1.display()));
    } else if l1.re <= 0.0 {
        ok = false;
        reasons.fail(format!("subdominant eigenvalue {} is not positive", l1.display()));
    }
    if l1.algebraic_multiplicity != 2 {
        ok = false;
        reasons.fail(format!(
            "subdominant eigenvalue {} has algebraic multiplicity {}, not 2",
            l1.display(),
            l1.algebraic_multiplicity
        ));
    } else if l1.geometric_multiplicity != 2 {
        ok = false;
        reasons.fail(format!(
            "subdominant eigenvalue {} is defective (geometric multiplicity {})",
            l1.display(),
            l1.geometric_multiplicity
        ));
    }
    if ok {
        reasons.push(format!("λ1 = λ2 = {} real, positive, double, non-defective", l1.display()));
    }
    if let Some(l3) = eigs.get(2) {
        v.sub_subdominant = Some(l3.modulus);
        if l1.re > 0.0 {
            v.lambda3_over_lambda1_squared = Some(l3.modulus / (l1.re * l1.re));
        }
        if l3.modulus >= l1.modulus * (1.0 - TOL) {
            ok = false;
            reasons.fail(format!("|λ3| = {:.12} is not below λ1 = {:.12}", l3.modulus, l1.modulus));
        } else {
            reasons.push(format!("|λ3| = {} < λ1", fmt_f(l3.modulus)));
        }
    }
    v.c1_spectral = ok;
    reasons.into_verdict(&mut v);
    v
}

/// The spectral part of the C¹ criterion at a tagged (boundary, corner,
/// crease or dart) vertex (Zorin 2000, "A method for analysis of
/// C¹-continuity of subdivision surfaces", for piecewise smooth surfaces;
/// Biermann–Levin–Zorin 2000; Biermann–Grundel–Zorin 2015): λ0 = 1 simple
/// and dominant; two real positive subdominant eigenvalues λ1 ≥ λ2,
/// non-defective, which need not be equal (the characteristic map
/// (φ1, φ2) is then scaled by λ1 and λ2 separately); every other eigenvalue
/// strictly smaller in modulus than λ2. The characteristic map's regularity
/// and injectivity on the sectors, the other half of the criterion, is
/// not decided here.
pub fn sector(eigs: &[Eigenvalue]) -> Verdict {
    let mut v = reif(eigs);
    v.criterion = "sector";
    v.subdominant_blocks.clear();
    v.lambda3_over_lambda1_squared = None;
    let mut reasons = Reasons::default();
    let mut ok = dominant_one(eigs, &mut reasons);
    let Some(l1) = eigs.get(1) else {
        reasons.fail("no subdominant eigenvalue".into());
        v.c1_spectral = false;
        reasons.into_verdict(&mut v);
        return v;
    };
    // the subdominant pair: λ1 twice, or λ1 > λ2 once each
    let (pair, next): (Vec<&Eigenvalue>, Option<&Eigenvalue>) = match l1.algebraic_multiplicity {
        2 => (vec![l1], eigs.get(2)),
        1 => (eigs.get(2).into_iter().chain([l1]).collect(), eigs.get(3)),
        m => {
            ok = false;
            reasons.fail(format!("subdominant eigenvalue {} has algebraic multiplicity {m}, not 1 or 2", l1.display()));
            (vec![l1], None)
        }
    };
    for e in &pair {
        if !e.is_real() || e.re <= 0.0 {
            ok = false;
            reasons.fail(format!("subdominant eigenvalue {} is not real and positive", e.display()));
        } else if e.geometric_multiplicity != e.algebraic_multiplicity {
            ok = false;
            reasons.fail(format!("subdominant eigenvalue {} is defective", e.display()));
        }
    }
    let l2 = pair.iter().map(|e| e.modulus).fold(f64::INFINITY, f64::min);
    if l1.algebraic_multiplicity == 1 && pair.len() == 2 && pair[0].algebraic_multiplicity != 1 {
        ok = false;
        reasons.fail(format!(
            "λ2 = {} has multiplicity {}: no single second subdominant eigenvalue",
            pair[0].display(),
            pair[0].algebraic_multiplicity
        ));
    }
    if ok {
        reasons.push(match pair[..] {
            [e] => format!("λ1 = λ2 = {} real, positive, non-defective", e.display()),
            _ => format!("λ1 = {} > λ2 = {} real, positive, simple", l1.display(), fmt_f(l2)),
        });
    }
    v.sub_subdominant = next.map(|e| e.modulus);
    match next {
        Some(e) if e.modulus >= l2 * (1.0 - TOL) => {
            ok = false;
            reasons.fail(format!("|λ3| = {:.12} is not below λ2 = {:.12}", e.modulus, l2));
        }
        Some(e) => reasons.push(format!("|λ3| = {} < λ2", fmt_f(e.modulus))),
        None => {}
    }
    reasons.push("not decided here: the characteristic map's regularity and injectivity on the sectors".into());
    v.c1_spectral = ok;
    reasons.into_verdict(&mut v);
    v
}

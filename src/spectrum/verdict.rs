//! Reif's spectral conditions for C^1 (with the characteristic map test done
//! separately): λ0 = 1 simple; λ1 = λ2 real, positive, non-defective, with
//! multiplicity exactly two; every other eigenvalue strictly smaller in modulus.

use serde::Serialize;

use super::eigenvalue::{fmt_f, Eigenvalue};

const TOL: f64 = 1e-9;

#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    pub c1_spectral: bool,
    /// λ0 = 1 simple and strictly dominant: the spectral condition for the
    /// scheme to converge at the extraordinary point
    pub convergent: bool,
    pub reasons: Vec<String>,
    /// the subdominant eigenvalue λ1 (when λ0 = 1 is found)
    pub subdominant: Option<f64>,
    /// Fourier blocks holding the subdominant pair
    pub subdominant_blocks: Vec<usize>,
    /// modulus of the next eigenvalue after the subdominant one
    pub sub_subdominant: Option<f64>,
    /// |λ3| / λ1^2: < 1 bounded curvature tends to zero, = 1 bounded, > 1 unbounded
    pub lambda3_over_lambda1_squared: Option<f64>,
}

pub fn reif(eigs: &[Eigenvalue]) -> Verdict {
    let mut reasons = Vec::new();
    let mut ok = true;
    let mut v = Verdict {
        c1_spectral: false,
        convergent: false,
        reasons: Vec::new(),
        subdominant: None,
        subdominant_blocks: Vec::new(),
        sub_subdominant: None,
        lambda3_over_lambda1_squared: None,
    };
    let Some(l0) = eigs.first() else {
        v.reasons.push("empty spectrum".into());
        return v;
    };
    if (l0.re - 1.0).abs() > TOL || l0.im.abs() > TOL {
        ok = false;
        reasons.push(format!("dominant eigenvalue is {} (modulus {:.6}), not 1", l0.display(), l0.modulus));
    } else if l0.algebraic_multiplicity != 1 {
        ok = false;
        reasons.push(format!("eigenvalue 1 has multiplicity {}, not 1", l0.algebraic_multiplicity));
    } else {
        reasons.push("λ0 = 1 is simple".into());
    }
    let dominant_one = ok;
    v.convergent = dominant_one && eigs.get(1).is_none_or(|l1| l1.modulus < 1.0 - TOL);
    let Some(l1) = eigs.get(1) else {
        reasons.push("no subdominant eigenvalue".into());
        v.reasons = reasons;
        return v;
    };
    v.subdominant = Some(l1.re);
    v.subdominant_blocks = l1.blocks.clone();
    if !l1.is_real() {
        ok = false;
        reasons.push(format!("subdominant eigenvalue {} is not real", l1.display()));
    } else if l1.re <= 0.0 {
        ok = false;
        reasons.push(format!("subdominant eigenvalue {} is not positive", l1.display()));
    }
    if l1.algebraic_multiplicity != 2 {
        ok = false;
        reasons.push(format!(
            "subdominant eigenvalue {} has algebraic multiplicity {}, not 2",
            l1.display(),
            l1.algebraic_multiplicity
        ));
    } else if l1.geometric_multiplicity != 2 {
        ok = false;
        reasons.push(format!(
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
            reasons.push(format!("|λ3| = {:.12} is not below λ1 = {:.12}", l3.modulus, l1.modulus));
        } else {
            reasons.push(format!("|λ3| = {} < λ1", fmt_f(l3.modulus)));
        }
    }
    v.c1_spectral = ok;
    v.reasons = reasons;
    v
}

//! Non-box subdivision on the regular lattice against the vector-valued mask
//! A of eq. (3) of Huang's paper ((S_A Λ)_α = Σ_β A^T_{α−2β} Λ_β).
//!
//! Independent necessary condition: integrating the refinement equation
//! Φ = Σ_α A_α Φ(2· − α) over R² gives ∫Φ = (1/4) Σ_α A_α ∫Φ, so for a function
//! vector with non-zero integral (the S_3^1 generators are non-negative) the
//! total mask Σ_α A_α has the eigenvalue 4. This holds whatever index
//! convention the printed grid of 2×2 matrices uses.
//!
//! Findings: the rules of section 3.2.2, read as a vector mask (component 1 =
//! FCVs, component 2 = vertices), have total mask with eigenvalues {4, 1}. The
//! printed grid sums to [[3, 2], [1/2, 3/2]] with eigenvalues {7/2, 1}: it
//! cannot be the mask of the non-box splines as printed (the claims registry
//! records it as refuted). Its vertex-to-vertex entries are also not the
//! symmetric pattern any four-directional symmetric scheme must have.

use subdlab::mesh::LatticeCoord;
use subdlab::neighbourhood::{build_patch, Configuration};
use subdlab::numeric::exact::{q, QMatrix};
use subdlab::numeric::Rational;
use subdlab::schemes::{self, SchemeWeight};

/// The printed mask, row by row, each cell [[a11, a12], [a21, a22]] in eighths.
fn printed_cells() -> Vec<[[i64; 2]; 2]> {
    vec![
        [[1, 0], [0, 1]],
        [[1, 0], [0, 1]],
        [[0, 0], [2, 1]],
        [[1, 1], [0, 0]],
        [[4, 2], [0, 2]],
        [[4, 1], [0, 1]],
        [[1, 0], [2, 2]],
        [[1, 2], [0, 0]],
        [[4, 4], [0, 1]],
        [[4, 2], [0, 2]],
        [[1, 0], [0, 1]],
        [[0, 1], [0, 0]],
        [[1, 2], [0, 0]],
        [[1, 1], [0, 0]],
    ]
}

fn eigen_2x2_has(m: [[Rational; 2]; 2], lambda: &Rational) -> bool {
    let mut a = QMatrix::zeros(2);
    for (i, row) in m.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            a.set(i, j, x.clone());
        }
    }
    a.charpoly().eval(lambda) == q(0, 1)
}

#[test]
fn total_mask_of_the_rules_has_the_refinement_eigenvalue_4() {
    // new points of one coarse cell (4 vertices, 4 FCVs) from a valence-4
    // patch, exact stencils of the scheme itself
    let scheme = schemes::build("non-box", &[]).unwrap();
    let config = Configuration::regular(scheme.as_ref(), 4).unwrap();
    let (patch, _) = build_patch(&config, 4);
    let refined = scheme.topology().refine(&patch).unwrap();
    let c1 = refined.mesh.chart.as_ref().unwrap();
    let fcv0: std::collections::HashSet<usize> = patch.face_points.iter().flatten().copied().collect();
    let fcv1: std::collections::HashSet<usize> = refined.mesh.face_points.iter().flatten().copied().collect();
    // T[i][j]: total weight that new points of type i (0 = FCV, 1 = vertex) of
    // one cell put on old points of type j
    let mut t = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    let mut count = [0, 0];
    for (v, &o) in refined.vertex_origins.iter().enumerate() {
        // fine half-unit coordinates in chart 0; one cell = [4, 8) x [4, 8)
        let c: LatticeCoord = c1.vertex_coords[v];
        let (x, y) = c1.in_chart(c, 0);
        if !(4..8).contains(&x) || !(4..8).contains(&y) {
            continue;
        }
        let i = if fcv1.contains(&v) { 0 } else { 1 };
        count[i] += 1;
        let st = <Rational as SchemeWeight>::stencil(scheme.as_ref(), &patch, o).unwrap().unwrap();
        for (u, w) in st.terms {
            let j = if fcv0.contains(&u) { 0 } else { 1 };
            t[i][j] = &t[i][j] + &w;
        }
    }
    assert_eq!(count, [4, 4], "one cell holds four new FCVs and four new vertices");
    // [[F←F, F←V], [V←F, V←V]] = [[3, 1], [2, 2]]: derived from the rules in
    // section 3.2.2 by hand (NFCV: 1/2 + 2/8 on FCVs, 1/4 on a vertex, ...)
    assert_eq!(t, [[q(3, 1), q(1, 1)], [q(2, 1), q(2, 1)]]);
    assert!(eigen_2x2_has(t.clone(), &q(4, 1)));
    assert!(eigen_2x2_has(t, &q(1, 1)));
}

#[test]
fn printed_mask_violates_the_refinement_condition() {
    let mut sum = [[q(0, 1), q(0, 1)], [q(0, 1), q(0, 1)]];
    for cell in printed_cells() {
        for i in 0..2 {
            for j in 0..2 {
                sum[i][j] = &sum[i][j] + q(cell[i][j], 8);
            }
        }
    }
    assert_eq!(sum, [[q(3, 1), q(2, 1)], [q(1, 2), q(3, 2)]]);
    // eigenvalues 7/2 and 1; 4 is not one of them, whatever the index convention
    assert!(!eigen_2x2_has(sum.clone(), &q(4, 1)));
    assert!(eigen_2x2_has(sum.clone(), &q(7, 2)));
    assert!(eigen_2x2_has(sum, &q(1, 1)));
}

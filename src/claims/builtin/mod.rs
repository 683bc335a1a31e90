//! Named checks for statements that need a bespoke computation (the
//! `builtin` check kind, `check = "builtin"` with `name` and `data`), one
//! file per paper; `data` holds the shared readers of the claim's printed
//! values and the shapes several papers' checks share. Printed values come
//! in `data`, from the claim file, never from here.
//!
//! Adding a built-in: its function in its paper's file (taking the claim's
//! `data`, returning a [`Finding`] or an error: `Error::Undecided` where the
//! computation does not decide, `Error::Claim` for malformed data) and its
//! line in [`run`]'s table.

pub mod data;
pub mod huang_nonbox;
pub mod khan_mustafa;
pub mod lin_luo;
pub mod peters_shiue;
pub mod peters_shiue_strip;
pub mod peters_shiue_window;

use crate::claims::verdict::Finding;
use crate::error::Error;

use data::need;

/// The built-in named `name`, on the claim's `data`.
pub fn run(name: &str, data: Option<&toml::Value>) -> Result<Finding, Error> {
    match name {
        "nonbox.vector-mask" => {
            huang_nonbox::nonbox_vector_mask(data.ok_or_else(|| Error::Claim("needs data.cells".into()))?)
        }
        "nonbox.negative-eigenvalues" => huang_nonbox::nonbox_negative_eigenvalues(),
        "matrix.nonnegative" => huang_nonbox::matrix_nonnegative(need(data)?),
        "lattice.fit-masks" => khan_mustafa::lattice_fit_masks(need(data)?),
        "linluo.section6" => lin_luo::linluo_section6(data),
        "curve.relation3" => lin_luo::curve_relation3(),
        "curve.c1-laurent" => lin_luo::curve_c1_laurent(need(data)?),
        "strip.defective" => peters_shiue_strip::strip_defective(need(data)?),
        "strip.structure" => peters_shiue_strip::strip_structure(need(data)?),
        "strip.shifted-eigenvectors" => peters_shiue_strip::strip_shifted_eigenvectors(need(data)?),
        "strip.jsr" => peters_shiue_strip::strip_jsr(need(data)?),
        "window.polynomials" => peters_shiue_window::window_polynomials(need(data)?),
        "window.box-spline" => peters_shiue_window::window_box_spline(need(data)?),
        "window.checkerboard-kernel" => peters_shiue_window::window_checkerboard_kernel(need(data)?),
        "fourthree.lemma3.4" => peters_shiue::fourthree_lemma_3_4(need(data)?),
        "fourthree.step-two-weights" => peters_shiue::fourthree_step_two(need(data)?),
        "fourthree.convex-hull" => peters_shiue::fourthree_convex_hull(need(data)?),
        "fourthree.node-counts" => peters_shiue::fourthree_node_counts(need(data)?),
        "fourthree.step-two-bound" => peters_shiue::fourthree_step_two_bound(need(data)?),
        "fourthree.ripple-free-unique" => peters_shiue::fourthree_ripple_free_unique(need(data)?),
        other => Err(Error::Claim(format!("no built-in check named '{other}'"))),
    }
}

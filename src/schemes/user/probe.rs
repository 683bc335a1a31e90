//! Which weight fields of a scheme file a rule evaluation reads at one
//! valence: the evidence `every_valence` needs that the rows of S away from
//! the centre do not depend on the centre's valence.
//!
//! A scheme file's rules reach their weights only through
//! `Mask::weight` (`rules.rs`), which reads field (rule, family) at the slot's
//! n (the valence of the vertex the slot concerns, or a face's corner count).
//! In the neighbourhood of a centre of valence N ≥ 7 every other vertex is
//! regular and every face a triangle or quad, so a read at n = N concerns the
//! centre. If every such read made while the rows of the vertices away from
//! the centre are assembled is of an expression in neither n nor j, those
//! rows are the same numbers at every N (the rules are local functions of
//! their slots; the other reads are at regular n). Built-in schemes weigh
//! in compiled code that this probe cannot see: it then records no read at
//! all, and the caller must not conclude anything.
//!
//! Thread-local on purpose: row assembly runs on the calling thread, and two
//! computations in parallel threads (tests) must not see each other's reads.

use std::cell::RefCell;

use crate::numeric::expr::{Env, Expr};

/// One read of a field at the watched valence.
#[derive(Clone, Debug)]
pub struct FieldRead {
    pub rule: &'static str,
    pub family: &'static str,
    /// the field's expression and the parameters' values it is read with
    pub expr: Expr,
    pub env: Env,
    /// the field's expression has a variable (n, j, m or a parameter, whose
    /// value may change with the centre's valence or the slot's position);
    /// false: the expression is one constant
    pub varies: bool,
}

/// What one watched computation read.
#[derive(Clone, Debug, Default)]
pub struct Reads {
    /// every field read, at any n (0: no scheme-file weight was read)
    pub total: usize,
    /// the distinct fields read at the watched valence
    pub at_valence: Vec<FieldRead>,
}

struct Watch {
    valence: usize,
    reads: Reads,
    /// the weights given to fields read at the watched valence instead of
    /// their own (None: their own)
    values: Option<Substitution>,
}

/// Weights given to the fields read at the watched valence: each listed
/// (rule, family) weighs its integer; any other field weighs `others`
/// (None: its own value).
#[derive(Clone, Debug, Default)]
pub struct Substitution {
    pub fields: Vec<((String, String), i64)>,
    pub others: Option<i64>,
}

thread_local! {
    static WATCH: RefCell<Option<Watch>> = const { RefCell::new(None) };
}

/// Runs `f` and returns what scheme-file weights it read, with the reads at
/// n = `valence` listed. Not reentrant: a watch inside a watch is refused
/// by returning no reads for the inner one (treated as "nothing known").
pub fn watch<T>(valence: usize, f: impl FnOnce() -> T) -> (T, Reads) {
    watch_with(valence, None, f)
}

/// `watch` in indicator mode: while `f` runs, a field read at n = `valence`
/// weighs 1 when it is `field` (rule, family) and 0 otherwise, so a row
/// assembled by `f` counts the slots of that field per target (with the
/// rule's scale).
pub fn watch_indicator<T>(valence: usize, field: (&str, &str), f: impl FnOnce() -> T) -> (T, Reads) {
    let values = Substitution { fields: vec![((field.0.to_string(), field.1.to_string()), 1)], others: Some(0) };
    watch_with(valence, Some(values), f)
}

/// `watch` with the fields read at n = `valence` weighing as `values` says
/// (composite schemes: the rows of S are polynomials in those weights, read
/// off by evaluating them at several integers, `every_valence::composite`).
pub fn watch_substituted<T>(valence: usize, values: Substitution, f: impl FnOnce() -> T) -> (T, Reads) {
    watch_with(valence, Some(values), f)
}

fn watch_with<T>(valence: usize, values: Option<Substitution>, f: impl FnOnce() -> T) -> (T, Reads) {
    let started = WATCH.with(|w| {
        let mut w = w.borrow_mut();
        if w.is_some() {
            return false;
        }
        *w = Some(Watch { valence, reads: Reads::default(), values });
        true
    });
    let out = f();
    let reads = if started {
        WATCH.with(|w| w.borrow_mut().take()).map(|w| w.reads).unwrap_or_default()
    } else {
        Reads::default()
    };
    (out, reads)
}

/// Called by `Mask::weight` of a scheme file for every field it reads:
/// `field` gives (has variables, expression, parameters). Returns the
/// substituted weight (an integer) at the watched valence when the watch
/// substitutes this field, else None (the field's own value is used).
pub(super) fn record(
    rule: &'static str,
    family: &'static str,
    n: usize,
    field: impl FnOnce() -> (bool, Expr, Env),
) -> Option<i64> {
    WATCH.with(|w| {
        let mut w = w.borrow_mut();
        let w = w.as_mut()?;
        w.reads.total += 1;
        if n != w.valence {
            return None;
        }
        if !w.reads.at_valence.iter().any(|r| r.rule == rule && r.family == family) {
            let (varies, expr, env) = field();
            w.reads.at_valence.push(FieldRead { rule, family, expr, env, varies });
        }
        let values = w.values.as_ref()?;
        values.fields.iter().find(|((r, f), _)| r == rule && f == family).map(|(_, v)| *v).or(values.others)
    })
}

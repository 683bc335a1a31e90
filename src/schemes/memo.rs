//! Weights a scheme derives once per weight type and key (a valence, or
//! nothing), instead of at every slot of every stencil.
//!
//! A rule's weights are functions of a few scheme constants (TPS's 1-D
//! weights from e; PGS's w1, w2, α from μ, λ and cos 2π/n). Derived anew at
//! each weight they dominate the exact paths: in a cyclotomic field the
//! division by 2 + cos 2π/n is an inverse in Q(ζ_n), and the certificate
//! asks for thousands of stencils per valence. The memo keeps, per weight
//! type W and key, the result (an `Err(Inexact)` too, so a type that cannot
//! represent the weights is not asked again).

use crate::mesh::IdMap;
use crate::numeric::{Inexact, Weight};
use std::any::{Any, TypeId};
use std::sync::{Arc, Mutex};

type Made = Arc<dyn Any + Send + Sync>;

/// Asked at every slot of every stencil, so keyed with the fast integer
/// hasher (SipHash was a tenth of stencil weighing).
#[derive(Default)]
pub struct WeightMemo {
    made: Mutex<IdMap<(TypeId, i64), Made>>,
}

impl WeightMemo {
    pub fn new() -> Self {
        Self::default()
    }

    /// The value `make` gives for weight type W at `key`, made once.
    pub fn get<W: Weight, T: Send + Sync + 'static>(
        &self,
        key: i64,
        make: impl FnOnce() -> Result<T, Inexact>,
    ) -> Result<Arc<T>, Inexact> {
        let id = (TypeId::of::<W>(), key);
        let known = |m: &Made| m.clone().downcast::<Result<Arc<T>, Inexact>>().ok();
        if let Some(found) = self.made.lock().unwrap_or_else(|e| e.into_inner()).get(&id).and_then(known) {
            return found.as_ref().clone();
        }
        // made outside the lock: two threads may both make it, and they
        // make the same value
        let value = make().map(Arc::new);
        self.made.lock().unwrap_or_else(|e| e.into_inner()).insert(id, Arc::new(value.clone()));
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::Rational;

    #[test]
    fn a_value_is_made_once_per_type_and_key() {
        let memo = WeightMemo::new();
        let calls = std::sync::atomic::AtomicUsize::new(0);
        let make = |x: i64| {
            calls.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
            Ok(x * 10)
        };
        assert_eq!(*memo.get::<f64, i64>(3, || make(3)).unwrap(), 30);
        assert_eq!(*memo.get::<f64, i64>(3, || make(99)).unwrap(), 30, "the second call reuses the first value");
        assert_eq!(*memo.get::<Rational, i64>(3, || make(4)).unwrap(), 40, "another weight type is its own entry");
        assert_eq!(*memo.get::<f64, i64>(5, || make(5)).unwrap(), 50, "another key is its own entry");
        assert_eq!(calls.load(std::sync::atomic::Ordering::SeqCst), 3);
        assert_eq!(memo.get::<Rational, u8>(7, || Err(Inexact)), Err(Inexact));
        assert_eq!(memo.get::<Rational, u8>(7, || Ok(1)), Err(Inexact), "an Inexact result is kept too");
    }
}

//! A process-wide memo for results that many callers ask for again with the
//! same inputs: `subdlab verify` decides 185 claims, and dozens of them
//! analyse the same scheme at the same valence (a spectral claim, a
//! certificate, a curvature class and a characteristic map of one paper), and
//! large valences probe the same small configuration to size their patch.
//!
//! Entries are shared (`Arc`), never handed out twice as owned values, so a
//! result with lazily filled parts (`OnceLock`s) is filled once for everyone.
//! The key must name every input the value depends on; callers build it from
//! the scheme's identity (`Scheme::identity`, which for a scheme file
//! includes a fingerprint of its rules), its parameters and the
//! configuration. Errors are not kept: a failed computation is tried again
//! by the next caller. The memo is bounded by an estimate of the bytes its
//! values hold: past the budget it is emptied (values in use stay alive in
//! their `Arc`s), so a sweep over thousands of valences cannot grow it
//! without bound. Two threads asking for one key at once may both compute
//! it; the results are equal (the computations are deterministic) and the
//! first one stored is kept.

use std::any::{Any, TypeId};
use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex};

/// A bounded map from keys to shared values.
pub struct Memo<V> {
    inner: Mutex<Entries<V>>,
    budget_bytes: usize,
}

struct Entries<V> {
    map: BTreeMap<String, Arc<V>>,
    bytes: usize,
}

impl<V> Memo<V> {
    /// An empty memo that holds at most about `budget_bytes`, as estimated by
    /// the `bytes` function passed to [`Memo::get_or_try_insert`].
    pub const fn new(budget_bytes: usize) -> Memo<V> {
        Memo { inner: Mutex::new(Entries { map: BTreeMap::new(), bytes: 0 }), budget_bytes }
    }

    /// The value stored under `key`, or `compute()`'s, stored when it
    /// succeeds. `bytes` estimates what a value holds.
    pub fn get_or_try_insert<E>(
        &self,
        key: String,
        compute: impl FnOnce() -> Result<V, E>,
        bytes: impl Fn(&V) -> usize,
    ) -> Result<Arc<V>, E> {
        if let Some(v) = self.lock().map.get(&key) {
            return Ok(Arc::clone(v));
        }
        // computed outside the lock: computations nest (a discovery probes
        // a smaller configuration through the same memo)
        let value = Arc::new(compute()?);
        let size = bytes(&value);
        let mut entries = self.lock();
        if let Some(v) = entries.map.get(&key) {
            return Ok(Arc::clone(v));
        }
        if entries.bytes + size > self.budget_bytes {
            entries.map.clear();
            entries.bytes = 0;
        }
        if size <= self.budget_bytes {
            entries.bytes += size;
            entries.map.insert(key, Arc::clone(&value));
        }
        Ok(value)
    }

    /// Number of values held (for tests).
    pub fn len(&self) -> usize {
        self.lock().map.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Entries<V>> {
        // a panic while the lock was held cannot leave the map inconsistent
        // (every update is one insert or one clear), so poisoning is ignored
        self.inner.lock().unwrap_or_else(|p| p.into_inner())
    }
}

/// Values derived from one owner (a discovery, an analysis) and nothing
/// else but a small key, made once for everyone who holds the owner: keyed by
/// the value's type and a number the deriving stage chooses (a level count).
/// Type-erased, because the stages that derive them sit above the owner's
/// layer. A failure is not kept.
#[derive(Default)]
pub struct Derived {
    values: Mutex<HashMap<(TypeId, u64), Arc<dyn Any + Send + Sync>>>,
}

impl Derived {
    pub fn get_or_try_insert<T: Any + Send + Sync, E>(
        &self,
        key: u64,
        make: impl FnOnce() -> Result<T, E>,
    ) -> Result<Arc<T>, E> {
        let id = (TypeId::of::<T>(), key);
        let lock = || self.values.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(v) = lock().get(&id) {
            return Ok(Arc::clone(v).downcast::<T>().expect("keyed by its type"));
        }
        // made outside the lock: making one value may derive another
        let value: Arc<dyn Any + Send + Sync> = Arc::new(make()?);
        let stored = Arc::clone(lock().entry(id).or_insert(value));
        Ok(stored.downcast::<T>().expect("keyed by its type"))
    }
}

#[cfg(test)]
mod tests {
    use super::{Derived, Memo};
    use std::cell::Cell;

    #[test]
    fn derived_values_are_keyed_by_type_and_key() {
        let d = Derived::default();
        let a = d.get_or_try_insert(1, || Ok::<u32, ()>(10)).unwrap();
        let b = d.get_or_try_insert(1, || Ok::<u32, ()>(11)).unwrap();
        assert_eq!((*a, *b), (10, 10));
        // the same key for another type is another value
        let c = d.get_or_try_insert(1, || Ok::<i64, ()>(-5)).unwrap();
        assert_eq!(*c, -5);
        assert_eq!(*d.get_or_try_insert(2, || Ok::<u32, ()>(12)).unwrap(), 12);
        assert!(d.get_or_try_insert(3, || Err::<u32, &str>("no")).is_err());
        assert_eq!(*d.get_or_try_insert(3, || Ok::<u32, &str>(13)).unwrap(), 13);
    }

    #[test]
    fn computes_once_per_key_and_not_on_error() {
        let memo: Memo<u32> = Memo::new(1000);
        let calls = Cell::new(0);
        let compute = |v: u32| {
            calls.set(calls.get() + 1);
            Ok::<u32, ()>(v)
        };
        assert_eq!(*memo.get_or_try_insert("a".into(), || compute(1), |_| 1).unwrap(), 1);
        assert_eq!(*memo.get_or_try_insert("a".into(), || compute(2), |_| 1).unwrap(), 1);
        assert_eq!(calls.get(), 1);
        assert!(memo.get_or_try_insert("b".into(), || Err::<u32, ()>(()), |_| 1).is_err());
        assert_eq!(*memo.get_or_try_insert("b".into(), || compute(3), |_| 1).unwrap(), 3);
        assert_eq!(calls.get(), 2);
    }

    #[test]
    fn the_budget_bounds_what_is_kept() {
        let memo: Memo<u32> = Memo::new(10);
        for k in 0..25u32 {
            memo.get_or_try_insert(k.to_string(), || Ok::<u32, ()>(k), |_| 4).unwrap();
            assert!(memo.len() * 4 <= 10, "{} values of 4 bytes in a budget of 10", memo.len());
        }
        // a value larger than the whole budget is returned but not kept
        let big = memo.get_or_try_insert("big".into(), || Ok::<u32, ()>(7), |_| 11).unwrap();
        assert_eq!(*big, 7);
        assert!(memo.get_or_try_insert("big".into(), || Ok::<u32, ()>(8), |_| 11).is_ok_and(|v| *v == 8));
    }
}

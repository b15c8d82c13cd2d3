//! A bounded memo shared by plans: answers that are worked out once and asked again and again (profiles
//! of names, rankings, per-knowledge-base answers). Full, it starts over, so that hostile queries or a far
//! larger knowledge base cannot grow it without limit.

use rustc_hash::FxHashMap as HashMap;
use std::borrow::Borrow;
use std::hash::Hash;
use std::sync::{Mutex, MutexGuard, PoisonError};

/// At most `LIMIT` answers per key.
#[derive(Debug)]
pub(crate) struct Memo<K, V, const LIMIT: usize>(Mutex<HashMap<K, V>>);

impl<K: Eq + Hash, V: Clone, const LIMIT: usize> Memo<K, V, LIMIT> {
    /// A panic elsewhere cannot leave the map half-written: an answer goes in whole, so they stay sound.
    fn map(&self) -> MutexGuard<'_, HashMap<K, V>> {
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// The answer remembered for `key`, looked up without owning a key.
    pub(crate) fn get<Q: Eq + Hash + ?Sized>(&self, key: &Q) -> Option<V>
    where
        K: Borrow<Q>,
    {
        self.map().get(key).cloned()
    }

    pub(crate) fn insert(&self, key: K, value: V) {
        let mut map = self.map();
        if map.len() >= LIMIT {
            map.clear();
        }
        map.insert(key, value);
    }

    /// The answer for `key`, worked out by `answer` the first time it is asked (unlocked: plans on other
    /// threads are not held up).
    pub(crate) fn get_or_insert_with(&self, key: K, answer: impl FnOnce() -> V) -> V {
        if let Some(v) = self.get(&key) {
            return v;
        }
        let v = answer();
        self.insert(key, v.clone());
        v
    }
}

impl<K, V, const LIMIT: usize> Default for Memo<K, V, LIMIT> {
    fn default() -> Self {
        Memo(Mutex::new(HashMap::default()))
    }
}

impl<K: Clone, V: Clone, const LIMIT: usize> Clone for Memo<K, V, LIMIT> {
    fn clone(&self) -> Self {
        let map = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        Memo(Mutex::new(map.clone()))
    }
}

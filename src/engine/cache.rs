//! A small least-recently-used cache of the engine's stages.

use std::collections::VecDeque;

/// A cache of the latest `capacity` values by key: a hit moves its entry to the front, a new
/// entry pushes out the least recently used one.
pub(super) struct Cache<K, V> {
    entries: VecDeque<(K, V)>,
    capacity: usize,
}

impl<K: PartialEq, V> Cache<K, V> {
    pub(super) fn new(capacity: usize) -> Self {
        Cache {
            entries: VecDeque::with_capacity(capacity + 1),
            capacity,
        }
    }

    /// The entry of `key`, moved to the front.
    pub(super) fn get_mut(&mut self, key: &K) -> Option<&mut V> {
        let i = self.entries.iter().position(|(k, _)| k == key)?;
        let entry = self.entries.remove(i)?;
        self.entries.push_front(entry);
        self.entries.front_mut().map(|(_, v)| v)
    }

    /// Puts a value at the front, pushing out the least recently used entry when full.
    pub(super) fn insert(&mut self, key: K, value: V) -> &mut V {
        self.entries.push_front((key, value));
        self.entries.truncate(self.capacity);
        &mut self.entries.front_mut().expect("just pushed").1
    }
}

impl<K: PartialEq, V: Clone> Cache<K, V> {
    /// A copy of the value of `key`, if cached.
    pub(super) fn get(&mut self, key: &K) -> Option<V> {
        self.get_mut(key).map(|v| v.clone())
    }

    /// The value of `key`, computed (and `counter` incremented) when not cached.
    pub(super) fn get_or(&mut self, key: K, counter: &mut usize, compute: impl FnOnce() -> V) -> V {
        if let Some(v) = self.get(&key) {
            return v;
        }
        *counter += 1;
        let v = compute();
        self.insert(key, v.clone());
        v
    }
}

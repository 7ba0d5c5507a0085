//! A small least-recently-used cache of the engine's stages, bounded both in entries and in the
//! bytes its values hold ([`Footprint`]).

use std::collections::VecDeque;
use std::mem::size_of;

use crate::engine::footprint::Footprint;

/// The bytes each cache of the engine's stages holds at most, the running-ins apart: two spatial
/// states of a 512-point grid (6 MB each) fit, and a value larger than this is recomputed when
/// asked again rather than kept.
pub const STAGE_BYTES: usize = 16 << 20;
/// The bytes the running-ins kept on the period cell hold at most: two at their largest, each
/// with about 34 MiB of snapshots (`running_in::SNAPSHOT_VALUES` shape values, with their
/// previous shapes and contact sets, before the thinning halves them), 11 MB of samples
/// (`running_in::MAX_STEPS` of 112 bytes) and its setup. A running-in is extended in place, so it
/// must fit whole: the older one goes first.
pub const RUN_BYTES: usize = 128 << 20;

/// A value, its key and the bytes it was measured to hold.
struct Entry<K, V> {
    key: K,
    value: V,
    bytes: usize,
}

/// A cache of at most `capacity` values by key, holding at most `budget` bytes: a hit moves its
/// entry to the front, a new entry pushes out the least recently used ones until both bounds
/// hold (an entry larger than the budget alone is not kept).
pub(super) struct Cache<K, V> {
    entries: VecDeque<Entry<K, V>>,
    capacity: usize,
    budget: usize,
    held: usize,
}

impl<K: PartialEq, V: Footprint> Cache<K, V> {
    /// An empty cache of at most `capacity` entries and `budget` bytes.
    pub(super) fn new(capacity: usize, budget: usize) -> Self {
        Cache {
            entries: VecDeque::with_capacity(capacity + 1),
            capacity,
            budget,
            held: 0,
        }
    }

    /// The bytes of one entry: its key and value inline, and what the value holds on the heap.
    fn measure(value: &V) -> usize {
        size_of::<Entry<K, V>>() + value.bytes()
    }

    /// The bytes the cache holds (by the last measure of each entry).
    #[cfg(test)]
    pub(super) fn held(&self) -> usize {
        self.held
    }

    /// The entries kept.
    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        self.entries.len()
    }

    /// The entry of `key`, moved to the front.
    pub(super) fn get_mut(&mut self, key: &K) -> Option<&mut V> {
        let i = self.entries.iter().position(|e| e.key == *key)?;
        let entry = self.entries.remove(i)?;
        self.entries.push_front(entry);
        self.entries.front_mut().map(|e| &mut e.value)
    }

    /// Puts a value at the front, pushing out the least recently used entries over either bound;
    /// None when the value alone is over the budget (it is not kept, and nothing is pushed out).
    pub(super) fn insert(&mut self, key: K, value: V) -> Option<&mut V> {
        let bytes = Self::measure(&value);
        if bytes > self.budget {
            return None;
        }
        self.held += bytes;
        self.entries.push_front(Entry { key, value, bytes });
        self.trim();
        self.entries.front_mut().map(|e| &mut e.value)
    }

    /// Measures the front entry again (its value grew in place through `get_mut`) and pushes out
    /// the least recently used entries over the budget, the front one last.
    pub(super) fn remeasure_front(&mut self) {
        if let Some(front) = self.entries.front_mut() {
            let bytes = Self::measure(&front.value);
            self.held = self.held - front.bytes + bytes;
            front.bytes = bytes;
        }
        self.trim();
    }

    fn trim(&mut self) {
        while self.entries.len() > self.capacity || self.held > self.budget {
            match self.entries.pop_back() {
                Some(old) => self.held -= old.bytes,
                None => break,
            }
        }
    }
}

impl<K: PartialEq, V: Footprint + Clone> Cache<K, V> {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A value of `n` f64 on the heap.
    #[derive(Clone)]
    struct Big(Vec<f64>);

    impl Footprint for Big {
        fn bytes(&self) -> usize {
            self.0.len() * size_of::<f64>()
        }
    }

    #[test]
    fn the_byte_budget_holds_under_many_inserts_of_big_entries() {
        const BUDGET: usize = 1 << 20;
        let mut cache = Cache::new(1000, BUDGET);
        // entries of 100 kB to 400 kB: between 2 and 10 fit
        for i in 0..500usize {
            let n = 12_500 + (i * 7919) % 37_500;
            cache.insert(i, Big(vec![i as f64; n]));
            let held: usize = cache
                .entries
                .iter()
                .map(|e| size_of::<Entry<usize, Big>>() + e.value.bytes())
                .sum();
            assert_eq!(cache.held(), held);
            assert!(held <= BUDGET, "{held} bytes held after insert {i}");
            // the newest entry is kept, and the oldest go first
            assert_eq!(cache.entries.front().map(|e| e.key), Some(i));
            assert!(cache.len() >= 2.min(i + 1));
        }
        assert!(cache.get(&499).is_some() && cache.get(&0).is_none());
    }

    #[test]
    fn an_entry_bigger_than_the_budget_is_not_kept() {
        let mut cache = Cache::new(8, 1 << 16);
        assert!(cache.insert(1, Big(vec![0.0; 100])).is_some());
        assert!(cache.insert(2, Big(vec![0.0; 1 << 14])).is_none());
        assert!(cache.get(&2).is_none());
        // and it pushed out nothing
        assert!(cache.get(&1).is_some());
        assert_eq!(cache.len(), 1);
    }

    #[test]
    fn an_entry_grown_in_place_pushes_out_the_older_ones() {
        let mut cache = Cache::new(8, 1 << 16);
        cache.insert(1, Big(vec![0.0; 1000]));
        cache.insert(2, Big(vec![0.0; 1000]));
        let grown = cache.get_mut(&2).expect("kept");
        grown.0.resize(7500, 0.0);
        cache.remeasure_front();
        assert!(cache.get(&1).is_none() && cache.get(&2).is_some());
        assert!(cache.held() <= 1 << 16);
    }

    #[test]
    fn the_entry_count_still_bounds_small_entries() {
        let mut cache = Cache::new(3, 1 << 30);
        for i in 0..10 {
            cache.insert(i, Big(vec![0.0; 1]));
        }
        assert_eq!(cache.len(), 3);
        assert!(cache.get(&9).is_some() && cache.get(&6).is_none());
    }
}

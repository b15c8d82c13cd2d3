//! Candidate sets: the profiles of a knowledge base's labels laid out for ranking, and what lets a
//! ranking skip most of them.

use super::profile::{Class, Profile, Traits};
use super::{squash, EmbeddingSimilarity};
use crate::similarity::cones::{dot, Cones};
use crate::similarity::Prepared;
use rustc_hash::FxHashMap as HashMap;
use std::sync::{Arc, OnceLock};

/// Candidate sets whose profiles are kept (a planner index has two: all labels, ingredient labels).
pub(super) const SET_PROFILES_KEPT: usize = 4;

/// The profiles of one candidate set, in its order, remembered between calls.
pub(super) type SetProfiles = Arc<CandidateSet>;

/// The profiles of a candidate set, with what a ranking reads of every candidate laid out in order: a
/// scan of a large knowledge base's labels then reads memory front to back instead of one profile here
/// and one there.
pub(super) struct CandidateSet {
    pub(super) profiles: Vec<Arc<Profile>>,
    dims: usize,
    /// `dims` values per candidate: its unit vector, or zeros when `has_vector` is false.
    vectors: Vec<f32>,
    has_vector: Vec<bool>,
    /// Hashes of each candidate's name, canonical name, word-stem key and canonical key: only one
    /// sharing a hash with the query can be an exact match, either way.
    hashes: Vec<[u64; 4]>,
    pub(super) composite: Vec<bool>,
    pub(super) utensil: Vec<bool>,
    known: Vec<bool>,
    pub(super) class: Vec<Class>,
    /// Every candidate's `stems`, one after another; candidate i's are `stems[stem_at[i]..stem_at[i + 1]]`.
    stems: Vec<u64>,
    stem_at: Vec<u32>,
    /// For the rankings of a remembered set (`rank_in_set`), made on the first: the vectors grouped in
    /// cones, and the candidates by the hashes an exact match is decided on.
    search: OnceLock<SetSearch>,
}

/// What lets a ranking skip most of a large candidate set: cones of its vectors (skipped whole when
/// their bound cannot place), and its candidates by name hash and by stem-key hash (an exact match, which
/// outranks everything, is then found without a scan).
pub(super) struct SetSearch {
    pub(super) cones: Cones,
    by_name: HashMap<u64, Vec<u32>>,
    by_key: HashMap<u64, Vec<u32>>,
}

impl SetSearch {
    /// Every candidate that `may_match` `q` (and maybe a few more), ascending.
    pub(super) fn exact_candidates(&self, q: &Profile) -> Vec<usize> {
        let names = [q.name.hash, q.canonical.hash].map(|h| self.by_name.get(&h));
        let keys = [q.key.hash, q.canonical_key.hash].map(|h| self.by_key.get(&h));
        let mut out: Vec<usize> = names
            .into_iter()
            .chain(keys)
            .flatten()
            .flatten()
            .map(|&i| i as usize)
            .collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

impl CandidateSet {
    pub(super) fn new(profiles: Vec<Arc<Profile>>, dims: usize) -> CandidateSet {
        let mut vectors = vec![0.0; profiles.len() * dims];
        for (p, row) in profiles.iter().zip(vectors.chunks_exact_mut(dims.max(1))) {
            if let Some(v) = &p.vector {
                row.copy_from_slice(&v[..dims]);
            }
        }
        CandidateSet {
            dims,
            vectors,
            has_vector: profiles.iter().map(|p| p.vector.is_some()).collect(),
            hashes: profiles
                .iter()
                .map(|p| {
                    [
                        p.name.hash,
                        p.canonical.hash,
                        p.key.hash,
                        p.canonical_key.hash,
                    ]
                })
                .collect(),
            composite: profiles.iter().map(|p| p.composite).collect(),
            utensil: profiles.iter().map(|p| p.utensil).collect(),
            known: profiles.iter().map(|p| p.is_known()).collect(),
            class: profiles.iter().map(|p| p.class()).collect(),
            stems: profiles
                .iter()
                .flat_map(|p| p.stems.iter().copied())
                .collect(),
            stem_at: std::iter::once(0)
                .chain(profiles.iter().scan(0u32, |at, p| {
                    *at += p.stems.len() as u32;
                    Some(*at)
                }))
                .collect(),
            profiles,
            search: OnceLock::new(),
        }
    }

    pub(super) fn search(&self) -> &SetSearch {
        self.search.get_or_init(|| {
            let mut by_name: HashMap<u64, Vec<u32>> = HashMap::default();
            let mut by_key: HashMap<u64, Vec<u32>> = HashMap::default();
            for (i, h) in self.hashes.iter().enumerate() {
                by_name.entry(h[0]).or_default().push(i as u32);
                by_key.entry(h[2]).or_default().push(i as u32);
            }
            SetSearch {
                cones: Cones::new(&self.vectors, self.dims, &self.has_vector),
                by_name,
                by_key,
            }
        })
    }

    pub(super) fn len(&self) -> usize {
        self.profiles.len()
    }

    /// `may_match` the other way: whether `q` can be an exact match for candidate i.
    pub(super) fn may_be_matched(&self, q: &Profile, i: usize) -> bool {
        self.hashes[i]
            .iter()
            .any(|&x| x == q.name.hash || x == q.key.hash)
    }
}

/// What a ranking reads of candidate i (in range).
impl CandidateSet {
    pub(super) fn traits(&self, i: usize) -> Traits<'_> {
        Traits {
            class: self.class[i],
            stems: &self.stems[self.stem_at[i] as usize..self.stem_at[i + 1] as usize],
        }
    }
    /// Whether candidate i can be an exact match for `q`, from hashes alone: false is certain, true
    /// must be confirmed with `is_exact(q, candidate)`.
    pub(super) fn may_match(&self, sim: &EmbeddingSimilarity, q: &Profile, i: usize) -> bool {
        let h = &self.hashes[i];
        sim.exact_rule(q, |x| x.hash == h[0], |x| x.hash == h[2])
    }
    /// `cosine_of(q, candidate i)`, from the laid-out vectors.
    pub(super) fn cosine(&self, q: &Profile, i: usize) -> f32 {
        match &q.vector {
            Some(a) if self.has_vector[i] => {
                dot(a, &self.vectors[i * self.dims..(i + 1) * self.dims])
            }
            _ => 0.0,
        }
    }
}

impl EmbeddingSimilarity {
    /// The profiles of a candidate set, remembered for the last few set ids asked.
    pub(super) fn set_profiles(&self, set: u64, candidates: &[String]) -> SetProfiles {
        if let Ok(kept) = self.set_profiles.lock() {
            if let Some((_, profiles)) = kept
                .iter()
                .find(|(id, p)| *id == set && p.len() == candidates.len())
            {
                return Arc::clone(profiles);
            }
        }
        let profiles = Arc::new(CandidateSet::new(
            candidates.iter().map(|c| self.profile(c)).collect(),
            self.table.dims(),
        ));
        if let Ok(mut kept) = self.set_profiles.lock() {
            kept.retain(|(id, _)| *id != set);
            if kept.len() >= SET_PROFILES_KEPT {
                kept.remove(0);
            }
            kept.push((set, Arc::clone(&profiles)));
        }
        profiles
    }
}

/// A query's profile with the profiles of a candidate set (`Similarity::prepare`).
pub(super) struct PreparedName<'a> {
    pub(super) sim: &'a EmbeddingSimilarity,
    pub(super) query: Arc<Profile>,
    pub(super) set: SetProfiles,
}

impl Prepared for PreparedName<'_> {
    fn to(&self, i: usize) -> f32 {
        self.set
            .profiles
            .get(i)
            .map_or(0.0, |c| self.sim.profile_similarity(&self.query, c))
    }

    fn from(&self, i: usize) -> f32 {
        self.set
            .profiles
            .get(i)
            .map_or(0.0, |c| self.sim.profile_similarity(c, &self.query))
    }

    fn both(&self, i: usize) -> (f32, f32) {
        let (set, q) = (&self.set, &self.query);
        if i >= set.len() {
            return (0.0, 0.0);
        }
        // the candidate's profile is read only when its hashes allow an exact match: a scan of many
        // labels then reads the set's arrays in order
        if (set.may_match(self.sim, q, i) && self.sim.is_exact(q, &set.profiles[i]))
            || (set.may_be_matched(q, i) && self.sim.is_exact(&set.profiles[i], q))
        {
            return (self.to(i), self.from(i));
        }
        // neither is exact: the graded score is symmetric, so one comparison serves both
        let s = squash(self.sim.graded(q.traits(), set.traits(i), set.cosine(q, i)));
        (
            if q.is_known() { s } else { 0.0 },
            if set.known[i] { s } else { 0.0 },
        )
    }
}

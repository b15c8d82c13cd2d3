//! Candidate sets: the profiles of a knowledge base's labels laid out for ranking.

use super::profile::{dot, Class, Profile, Traits};
use super::{squash, EmbeddingSimilarity};
use crate::similarity::Prepared;
use std::sync::Arc;

/// Candidate sets whose profiles are kept (a planner index has two: all labels, ingredient labels).
pub(super) const SET_PROFILES_KEPT: usize = 4;

/// The profiles of one candidate set, in its order, remembered between calls.
pub(super) type SetProfiles = Arc<CandidateSet>;

/// The profiles of a candidate set, with what a ranking reads of every candidate laid out in order: a
/// scan of a large knowledge base's labels then reads memory front to back instead of one profile here
/// and one there.
pub(super) struct CandidateSet {
    profiles: Vec<Arc<Profile>>,
    dims: usize,
    /// `dims` values per candidate: its unit vector, or zeros when `has_vector` is false.
    vectors: Vec<f32>,
    has_vector: Vec<bool>,
    composite: Vec<bool>,
    utensil: Vec<bool>,
    known: Vec<bool>,
    class: Vec<Class>,
    /// Every candidate's `stems`, one after another; candidate i's are `stems[stem_at[i]..stem_at[i + 1]]`.
    stems: Vec<u64>,
    stem_at: Vec<u32>,
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
        }
    }

    pub(super) fn len(&self) -> usize {
        self.profiles.len()
    }

    // what a ranking reads of candidate i (in range)
    pub(super) fn profile(&self, i: usize) -> &Profile {
        &self.profiles[i]
    }
    pub(super) fn composite(&self, i: usize) -> bool {
        self.composite[i]
    }
    pub(super) fn utensil(&self, i: usize) -> bool {
        self.utensil[i]
    }
    pub(super) fn class(&self, i: usize) -> Class {
        self.class[i]
    }
    pub(super) fn traits(&self, i: usize) -> Traits<'_> {
        Traits {
            class: self.class[i],
            stems: &self.stems[self.stem_at[i] as usize..self.stem_at[i + 1] as usize],
        }
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
        let c = &set.profiles[i];
        if self.sim.is_exact(q, c) || self.sim.is_exact(c, q) {
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

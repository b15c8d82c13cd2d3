//! Unit vectors grouped into cones (a centroid and the widest angle of a member from it), so that a scan
//! for the vectors nearest a query can skip a whole group at once: no member of a cone can be nearer the
//! query than the cone's edge. Exact: a bound never lies, so a scan that skips by it finds what a full
//! scan finds.

/// Cones over a set of unit vectors; vectors that are missing (`has_vector` false) form one more group
/// whose cosine with anything is 0.
#[derive(Default)]
pub struct Cones {
    dims: usize,
    /// Vector indices, grouped by cone, ascending within each; the vectorless group last.
    members: Vec<u32>,
    /// Cone k's members are `members[at[k]..at[k + 1]]`.
    at: Vec<u32>,
    /// Unit centroid of each cone with vectors, `dims` values each.
    centroids: Vec<f32>,
    /// Cosine and sine of each cone's half-angle (the widest angle of a member from the centroid).
    cos_half: Vec<f32>,
    sin_half: Vec<f32>,
}

/// Added to every bound: the scan's own cosines are rounded sums, the bound's trigonometry too.
const MARGIN: f32 = 1e-3;
/// More cones make tighter bounds but cost a centroid comparison each per query.
const MAX_CONES: usize = 256;

impl Cones {
    /// Groups `vectors` (`dims` values per vector, unit length where `has_vector`) by one pass of
    /// nearest-seed assignment from evenly spaced seeds: about √n cones. Deterministic.
    pub fn new(vectors: &[f32], dims: usize, has_vector: &[bool]) -> Cones {
        let dims = dims.max(1);
        let row = |i: usize| &vectors[i * dims..(i + 1) * dims];
        let with: Vec<usize> = (0..has_vector.len()).filter(|&i| has_vector[i]).collect();
        let count = ((with.len() as f64).sqrt().round() as usize).min(MAX_CONES);
        let seeds: Vec<usize> = (0..count).map(|j| with[j * with.len() / count]).collect();
        let mut groups: Vec<Vec<u32>> = vec![Vec::new(); count];
        for &i in &with {
            // the first of the nearest seeds
            let nearest = (seeds.iter().enumerate())
                .map(|(j, &s)| (dot(row(s), row(i)), j))
                .reduce(|best, next| if next.0 > best.0 { next } else { best });
            groups[nearest.map_or(0, |n| n.1)].push(i as u32);
        }
        groups.retain(|g| !g.is_empty());
        let mut cones = Cones {
            dims,
            at: vec![0],
            ..Cones::default()
        };
        for g in &groups {
            let mut centroid = vec![0f32; dims];
            for &i in g {
                centroid
                    .iter_mut()
                    .zip(row(i as usize))
                    .for_each(|(c, x)| *c += x);
            }
            let norm = dot(&centroid, &centroid).sqrt();
            // members summing to nothing: no direction, so a half-angle of 180 degrees
            let cos_half = if norm > 0.0 {
                centroid.iter_mut().for_each(|c| *c /= norm);
                g.iter()
                    .map(|&i| dot(&centroid, row(i as usize)))
                    .fold(1.0f32, f32::min)
                    .clamp(-1.0, 1.0)
            } else {
                -1.0
            };
            cones.centroids.extend(centroid);
            cones.cos_half.push(cos_half);
            cones
                .sin_half
                .push((1.0 - cos_half * cos_half).max(0.0).sqrt());
            cones.members.extend_from_slice(g);
            cones.at.push(cones.members.len() as u32);
        }
        cones.members.extend(
            (0..has_vector.len())
                .filter(|&i| !has_vector[i])
                .map(|i| i as u32),
        );
        if cones.members.len() > *cones.at.last().unwrap_or(&0) as usize {
            cones.at.push(cones.members.len() as u32);
        }
        cones
    }

    /// Number of groups (cones and the vectorless group).
    pub fn len(&self) -> usize {
        self.at.len() - 1
    }

    pub fn members(&self, k: usize) -> &[u32] {
        &self.members[self.at[k] as usize..self.at[k + 1] as usize]
    }

    /// For each group, the most a member's cosine with `query` (a unit vector, or none: cosine 0 with
    /// everything) can be, as (bound, group), highest first.
    pub fn bounds(&self, query: Option<&[f32]>) -> Vec<(f32, usize)> {
        let mut out: Vec<(f32, usize)> = (0..self.len())
            .map(|k| {
                let bound = match query {
                    Some(q) if k < self.cos_half.len() => {
                        let c = &self.centroids[k * self.dims..(k + 1) * self.dims];
                        let cos_q = dot(q, c).clamp(-1.0, 1.0);
                        if cos_q >= self.cos_half[k] {
                            1.0 // the query is inside the cone
                        } else {
                            // cos(angle to centroid - half-angle)
                            let sin_q = (1.0 - cos_q * cos_q).max(0.0).sqrt();
                            cos_q * self.cos_half[k] + sin_q * self.sin_half[k]
                        }
                    }
                    _ => 0.0,
                };
                (bound + MARGIN, k)
            })
            .collect();
        out.sort_by(|a, b| b.0.total_cmp(&a.0).then(a.1.cmp(&b.1)));
        out
    }
}

/// Dot product in eight fixed lanes (every score adds it up the same way, so equal pairs score equal):
/// lanes the compiler can keep in vector registers, where one running sum would be a chain of
/// dependent additions.
pub(crate) fn dot(a: &[f32], b: &[f32]) -> f32 {
    const LANES: usize = 8;
    let mut acc = [0f32; LANES];
    let (ca, cb) = (a.chunks_exact(LANES), b.chunks_exact(LANES));
    let tail: f32 = ca
        .remainder()
        .iter()
        .zip(cb.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in ca.zip(cb) {
        for i in 0..LANES {
            acc[i] += x[i] * y[i];
        }
    }
    acc.iter().sum::<f32>() + tail
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Deterministic unit vectors around 30 random directions, `spread` apart from their direction (a
    /// knowledge base's labels gather so: kinds of cheese, of pepper, relabelled copies).
    fn vectors(n: usize, dims: usize, spread: f32) -> Vec<f32> {
        let mut state = 0x9e37_79b9_u32;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            (state as f32 / u32::MAX as f32) - 0.5
        };
        let centres: Vec<Vec<f32>> = (0..30)
            .map(|_| (0..dims).map(|_| next()).collect())
            .collect();
        let mut out = Vec::with_capacity(n * dims);
        for i in 0..n {
            let mut v: Vec<f32> = centres[i % 30]
                .iter()
                .map(|c| c + next() * spread)
                .collect();
            let norm = dot(&v, &v).sqrt();
            v.iter_mut().for_each(|x| *x /= norm);
            out.extend(v);
        }
        out
    }

    #[test]
    fn no_member_is_nearer_a_query_than_its_cone_allows() {
        let (n, dims) = (500, 12);
        let v = vectors(n, dims, 0.5);
        let has: Vec<bool> = (0..n).map(|i| i % 17 != 0).collect();
        let cones = Cones::new(&v, dims, &has);
        let all: usize = (0..cones.len()).map(|k| cones.members(k).len()).sum();
        assert_eq!(all, n, "every vector in exactly one group");
        assert!(cones.len() > 10);
        for q in (0..n).step_by(7) {
            let query = &v[q * dims..(q + 1) * dims];
            let bounds = cones.bounds(Some(query));
            assert!(bounds.windows(2).all(|w| w[0].0 >= w[1].0), "highest first");
            for (bound, k) in bounds {
                for &i in cones.members(k) {
                    let i = i as usize;
                    let cos = if has[i] {
                        dot(query, &v[i * dims..(i + 1) * dims])
                    } else {
                        0.0
                    };
                    assert!(
                        cos <= bound,
                        "query {q}, member {i}: cosine {cos} over bound {bound}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_bounds_skip_most_cones_far_from_a_query() {
        let (n, dims) = (2000, 12);
        let v = vectors(n, dims, 0.1);
        let cones = Cones::new(&v, dims, &vec![true; n]);
        let bounds = cones.bounds(Some(&v[..dims]));
        // the query's own cone reaches it; the cones of other directions are bounded well below 1
        assert!(bounds[0].0 >= 1.0);
        let far = bounds.iter().filter(|b| b.0 < 0.8).count();
        assert!(
            far > bounds.len() / 4,
            "{far} of {} cones bounded below 0.8",
            bounds.len()
        );
    }

    #[test]
    fn no_vectors_or_no_query_bound_everything_by_zero() {
        let cones = Cones::new(&[0.0; 6], 3, &[false, false]);
        assert_eq!(cones.len(), 1);
        assert_eq!(cones.members(0), &[0, 1]);
        assert!(cones.bounds(None).iter().all(|b| b.0 < 0.01));
        assert_eq!(Cones::new(&[], 3, &[]).len(), 0);
    }
}

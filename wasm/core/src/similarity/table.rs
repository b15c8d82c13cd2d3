//! The compressed food-domain word-vector table (`public/data/food-embeddings.bin`, built by
//! `scripts/build_embeddings.py`) and phrase embedding: normalise, split into words, stem each word with
//! the Snowball English stemmer the table was trained with, and average the word vectors.
//!
//! Loading is pure Rust from bytes (the WASM bindings hand over the fetched file), verifies the magic,
//! version, sizes and CRC-32, and never panics on damaged input.

use crate::error::{ErrorCode, FoonError, Result};
use crate::memo::Memo;
use rust_stemmers::{Algorithm, Stemmer};
use rustc_hash::FxHashMap as HashMap;
use std::sync::Arc;

pub const MAGIC: &[u8; 8] = b"FOONEMB\0";
pub const VERSION: u32 = 2;
/// Upper bounds that keep a damaged header from asking for absurd allocations.
const MAX_DIMS: usize = 1024;
const MAX_WORDS: usize = 1_000_000;
/// Words whose stems `resolve` keeps; it starts again when full.
const RESOLVED_LIMIT: usize = 100_000;

/// Words that carry no food meaning inside an ingredient phrase.
const STOP_WORDS: &[&str] = &[
    "a", "an", "and", "the", "of", "or", "with", "for", "in", "to", "de", "du", "la", "le", "au",
];

/// The word-vector table: one row per stemmed word, its int8 components as stored (a row's direction:
/// phrases are embedded from unit rows, so a row's length carries no meaning).
pub struct EmbeddingTable {
    dims: usize,
    words: Vec<String>,
    index: HashMap<String, u32>,
    /// Row-major, `words.len() * dims`.
    vectors: Vec<f32>,
    stemmer: Stemmer,
    /// `resolve` of each word asked so far: labels and taxonomy names repeat their words.
    resolved: Memo<String, Arc<WordStems>, RESOLVED_LIMIT>,
}

/// A word's stem, and the stems standing for it in the table (`EmbeddingTable::word_stems`).
#[derive(Debug)]
pub struct WordStems {
    pub stem: String,
    pub stems: Vec<String>,
}

impl std::fmt::Debug for EmbeddingTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("EmbeddingTable")
            .field("dims", &self.dims)
            .field("words", &self.words.len())
            .finish()
    }
}

/// How a phrase was embedded: its vector (none when no word of it is known) and what was used.
#[derive(Clone, Debug, PartialEq)]
pub struct PhraseVector {
    pub vector: Option<Vec<f32>>,
    /// Stems whose vectors went into the average (a word with no vector of its own may contribute
    /// the parts it is made of, e.g. "gingerroot" -> "ginger" + "root").
    pub known: Vec<String>,
    /// Words for which no vector was found at all.
    pub unknown: Vec<String>,
}

fn bad(message: impl Into<String>) -> FoonError {
    FoonError::new(ErrorCode::BadEmbeddings, message)
}

/// CRC-32 (IEEE 802.3, reflected, as zlib's `crc32`).
pub fn crc32(bytes: &[u8]) -> u32 {
    static TABLE: std::sync::OnceLock<[u32; 256]> = std::sync::OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t = [0u32; 256];
        for (i, slot) in t.iter_mut().enumerate() {
            let mut c = i as u32;
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
            *slot = c;
        }
        t
    });
    let mut crc = 0xFFFF_FFFFu32;
    for &b in bytes {
        crc = table[((crc ^ b as u32) & 0xFF) as usize] ^ (crc >> 8);
    }
    !crc
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8]> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len())
            .ok_or_else(|| bad(format!("embedding table is truncated in its {what}")))?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn u32(&mut self, what: &str) -> Result<u32> {
        let bytes = self.take(4, what)?.try_into().expect("four bytes taken");
        Ok(u32::from_le_bytes(bytes))
    }
}

/// Lower-cased words of a phrase: letters and digits, everything else separates words.
pub fn words(phrase: &str) -> Vec<String> {
    phrase
        .to_lowercase()
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
        .map(fold_accents)
        .collect()
}

/// Folds the accented Latin letters of food names ("jalapeño", "crème") to ASCII.
fn fold_accents(word: &str) -> String {
    word.chars()
        .map(|c| match c {
            'à' | 'á' | 'â' | 'ã' | 'ä' | 'å' => 'a',
            'ç' => 'c',
            'è' | 'é' | 'ê' | 'ë' => 'e',
            'ì' | 'í' | 'î' | 'ï' => 'i',
            'ñ' => 'n',
            'ò' | 'ó' | 'ô' | 'õ' | 'ö' => 'o',
            'ù' | 'ú' | 'û' | 'ü' => 'u',
            other => other,
        })
        .collect()
}

pub fn is_stop_word(word: &str) -> bool {
    STOP_WORDS.contains(&word)
}

impl EmbeddingTable {
    /// Reads a table written by `scripts/build_embeddings.py`; `BadEmbeddings` on any damage.
    pub fn from_bytes(bytes: &[u8]) -> Result<EmbeddingTable> {
        if bytes.len() < MAGIC.len() + 20 || !bytes.starts_with(MAGIC) {
            return Err(bad("not a foon-planner embedding table (bad magic)"));
        }
        let (body, stored) = bytes.split_last_chunk().expect("longer than its magic");
        let stored = u32::from_le_bytes(*stored);
        let mut r = Reader {
            bytes: body,
            at: MAGIC.len(),
        };
        let version = r.u32("header")?;
        if version != VERSION {
            return Err(bad(format!(
                "embedding table version {version}; this build reads version {VERSION}"
            )));
        }
        if crc32(body) != stored {
            return Err(bad("embedding table checksum mismatch (damaged file)"));
        }
        let dims = r.u32("header")? as usize;
        let count = r.u32("header")? as usize;
        let word_len = r.u32("header")? as usize;
        if dims == 0 || dims > MAX_DIMS || count == 0 || count > MAX_WORDS {
            let why = format!("embedding table header out of range ({count} words x {dims} dims)");
            return Err(bad(why));
        }
        let blob = r.take(word_len, "word list")?;
        let text =
            std::str::from_utf8(blob).map_err(|_| bad("embedding word list is not UTF-8"))?;
        let words: Vec<String> = text.split_terminator('\n').map(str::to_string).collect();
        if words.len() != count || !text.ends_with('\n') {
            return Err(bad(format!(
                "embedding word list has {} words; the header says {count}",
                words.len()
            )));
        }
        let rows = r.take(count * dims, "vectors")?;
        if r.at != body.len() {
            return Err(bad("embedding table has trailing bytes"));
        }
        let vectors = rows.iter().map(|&q| q as i8 as f32).collect();
        let mut index = HashMap::with_capacity_and_hasher(count, Default::default());
        for (i, w) in words.iter().enumerate() {
            if w.is_empty() || index.insert(w.clone(), i as u32).is_some() {
                let why = format!("embedding word list has an empty or repeated word at {i}");
                return Err(bad(why));
            }
        }
        Ok(EmbeddingTable {
            dims,
            words,
            index,
            vectors,
            stemmer: Stemmer::create(Algorithm::English),
            resolved: Memo::default(),
        })
    }

    pub fn dims(&self) -> usize {
        self.dims
    }

    pub fn len(&self) -> usize {
        self.words.len()
    }

    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
    }

    pub fn stem(&self, word: &str) -> String {
        self.stemmer.stem(word).into_owned()
    }

    /// The vector of a stem exactly as stored.
    pub fn row(&self, stem: &str) -> Option<&[f32]> {
        let i = *self.index.get(stem)? as usize;
        Some(&self.vectors[i * self.dims..(i + 1) * self.dims])
    }

    /// Position of a stem in the table (the source lists words by falling frequency).
    pub fn rank_of(&self, stem: &str) -> Option<u32> {
        self.index.get(stem).copied()
    }

    pub fn contains_stem(&self, stem: &str) -> bool {
        self.index.contains_key(stem)
    }

    /// The stems standing for one word: its own stem when the table has it; else the stem of the word
    /// with a lost final "s" put back ("asparagu", "molass", "watercres" come from naive
    /// singularisation); else the word split into two known parts ("gingerroot", "soymilk",
    /// "crabmeat"), longest known first part preferred. Empty when nothing is known.
    pub fn word_stems(&self, word: &str) -> Vec<String> {
        self.resolve(word).stems.clone()
    }

    /// The stem of a word with its `word_stems`, worked out once per word.
    pub fn resolve(&self, word: &str) -> Arc<WordStems> {
        if let Some(r) = self.resolved.get(word) {
            return r;
        }
        let stem = self.stem(word);
        let r = Arc::new(WordStems {
            stems: self.resolve_word(word, &stem),
            stem,
        });
        self.resolved.insert(word.to_string(), Arc::clone(&r));
        r
    }

    /// `word_stems` without the memo, from the word's stem.
    fn resolve_word(&self, word: &str, stem: &str) -> Vec<String> {
        // A word and its plural share a stem; when they do not, the word may be a plural cut short
        // ("watercres", "lemongras"): the table's words are in frequency order, the commoner wins.
        let plural = self.stem(&format!("{word}s"));
        match (self.rank_of(stem), self.rank_of(&plural)) {
            (Some(a), Some(b)) if b < a => return vec![plural],
            (Some(_), _) => return vec![stem.to_string()],
            _ => {}
        }
        if self.contains_stem(word) {
            return vec![word.to_string()];
        }
        if self.contains_stem(&plural) {
            return vec![plural];
        }
        let chars: Vec<(usize, char)> = word.char_indices().collect();
        if chars.len() >= 6 {
            for k in (3..=chars.len() - 3).rev() {
                let at = chars[k].0;
                let (a, b) = (&word[..at], &word[at..]);
                let (sa, sb) = (self.stem(a), self.stem(b));
                if self.contains_stem(&sa) && self.contains_stem(&sb) {
                    return vec![sa, sb];
                }
            }
        }
        Vec::new()
    }

    /// Embeds a phrase: the mean of the unit word vectors of its words (stop words left out), the
    /// last (head) word weighted `head_weight` times. `vector` is None when no word is known.
    pub fn embed_weighted(&self, phrase: &str, head_weight: f32) -> PhraseVector {
        let ws: Vec<String> = words(phrase)
            .into_iter()
            .filter(|w| !is_stop_word(w))
            .collect();
        self.embed_words(&ws, head_weight)
    }

    /// `embed_weighted` of a phrase already split into words (`words`, stop words left out).
    pub fn embed_words(&self, ws: &[String], head_weight: f32) -> PhraseVector {
        let mut sum = vec![0f32; self.dims];
        let mut known = Vec::new();
        let mut unknown = Vec::new();
        let mut total = 0f32;
        for (i, w) in ws.iter().enumerate() {
            let stems = &self.resolve(w).stems;
            if stems.is_empty() {
                unknown.push(w.clone());
                continue;
            }
            let weight = if i + 1 == ws.len() { head_weight } else { 1.0 } / stems.len() as f32;
            for s in stems {
                if let Some(row) = self.row(s) {
                    let n = norm(row);
                    if n > 0.0 {
                        for (acc, x) in sum.iter_mut().zip(row) {
                            *acc += weight * x / n;
                        }
                        total += weight;
                    }
                }
                known.push(s.clone());
            }
        }
        PhraseVector {
            vector: (total > 0.0 && norm(&sum) > 0.0).then_some(sum),
            known,
            unknown,
        }
    }

    /// `embed_weighted` with equal weights.
    pub fn embed(&self, phrase: &str) -> PhraseVector {
        self.embed_weighted(phrase, 1.0)
    }
}

pub fn norm(v: &[f32]) -> f32 {
    v.iter().map(|x| x * x).sum::<f32>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crc32_matches_zlib() {
        assert_eq!(crc32(b""), 0);
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn words_fold_case_punctuation_and_accents() {
        assert_eq!(
            words("Jalapeño  Five-Spice"),
            vec!["jalapeno", "five", "spice"]
        );
    }

    #[test]
    fn garbage_is_an_error_not_a_panic() {
        for bytes in [
            &b""[..],
            b"FOONEMB\0",
            b"FOONEMB\0\x01\0\0\0zzzzzzzzzzzzzzzzzzzz",
        ] {
            let e = EmbeddingTable::from_bytes(bytes).unwrap_err();
            assert_eq!(e.code, ErrorCode::BadEmbeddings);
        }
    }
}

//! A merged knowledge base as bytes, so that a page that has loaded one can keep it (the app caches it
//! in IndexedDB) and load it again without parsing and merging its files. What the merge derives from the
//! units (producers, consumers, the kitchen, the node index) is not stored but derived again on reading.
//!
//! Layout: the magic `FOONKB`, the format version (u16), a checksum of the rest (u64), then every distinct
//! string once and the parts of the knowledge base with strings as numbers into that list. Numbers are
//! LEB128 varints. Reading checks the checksum and every number it uses as an index: damaged bytes, or
//! bytes written by another format version, read as `None`, never as another knowledge base.

use crate::error::{ErrorCode, FoonError};
use crate::foon::kb::{Goal, KnowledgeBase, SubgraphInfo};
use crate::foon::model::{FunctionalUnit, NodeId, ObjectNode, State, StateArg, UnitObject};
use rustc_hash::FxHashMap;
use serde::de::{Deserialize, IntoDeserializer};
use smol_str::SmolStr;
use std::sync::Arc;

const MAGIC: &[u8; 6] = b"FOONKB";
/// Bumped whenever the layout or the meaning of what is stored changes.
const VERSION: u16 = 1;

/// The knowledge base as snapshot bytes (`read` gives it back equal).
pub fn write(kb: &KnowledgeBase) -> Vec<u8> {
    let mut w = Writer::default();
    w.seq(&kb.nodes, Writer::node);
    w.seq(&kb.units, Writer::unit);
    w.seq(&kb.provenance, |w, files| w.seq(files, |w, f| w.str(f)));
    w.seq(&kb.goals, Writer::goal);
    w.seq(&kb.subgraphs, |w, s| {
        w.str(&s.name);
        w.str(&s.title);
        w.num(s.units);
    });
    w.num(kb.units_before_merge);
    w.seq(&kb.warnings, Writer::warning);

    let mut body = Vec::new();
    num(&mut body, w.strings.len());
    for s in &w.strings {
        num(&mut body, s.len());
        body.extend_from_slice(s.as_bytes());
    }
    body.extend_from_slice(&w.out);
    with_header(&body)
}

/// `body` after the magic, the version and the body's checksum.
fn with_header(body: &[u8]) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&checksum(body).to_le_bytes());
    out.extend_from_slice(body);
    out
}

/// The knowledge base the bytes hold; `None` for bytes that are damaged, truncated, of another format
/// version or not a snapshot at all.
pub fn read(bytes: &[u8]) -> Option<KnowledgeBase> {
    let (magic, rest) = bytes.split_first_chunk()?;
    let (version, rest) = rest.split_first_chunk()?;
    let (sum, body) = rest.split_first_chunk()?;
    let version = u16::from_le_bytes(*version);
    if magic != MAGIC || version != VERSION || checksum(body) != u64::from_le_bytes(*sum) {
        return None;
    }
    let mut r = Reader {
        bytes: body,
        ..Reader::default()
    };
    r.strings = r.seq(|r| {
        let len = r.num()?;
        let text = std::str::from_utf8(r.take(len)?).ok()?;
        Some(SmolStr::from(text))
    })?;
    let nodes = r.seq(Reader::node)?;
    r.nodes = nodes.len();
    let units = r.seq(Reader::unit)?;
    let provenance = r.seq(|r| Some(Arc::from(r.seq(Reader::string)?)))?;
    let goals = r.seq(Reader::goal)?;
    let subgraphs = r.seq(|r| {
        Some(SubgraphInfo {
            name: r.string()?,
            title: r.string()?,
            units: r.num()?,
        })
    })?;
    let units_before_merge = r.num()?;
    let warnings = r.seq(Reader::warning)?;
    let complete = r.at == body.len() && provenance.len() == units.len();
    complete.then(|| {
        KnowledgeBase::from_merged(
            nodes,
            units,
            provenance,
            goals,
            subgraphs,
            units_before_merge,
            warnings,
        )
    })
}

/// A 64-bit checksum of the bytes, eight at a time (the same on every platform).
fn checksum(bytes: &[u8]) -> u64 {
    const K: u64 = 0x517c_c1b7_2722_0a95;
    let mut hash = bytes.len() as u64;
    for chunk in bytes.chunks(8) {
        let mut word = [0u8; 8];
        word[..chunk.len()].copy_from_slice(chunk);
        hash = (hash.rotate_left(5) ^ u64::from_le_bytes(word)).wrapping_mul(K);
    }
    hash
}

/// Appends `n` as a LEB128 varint.
fn num(out: &mut Vec<u8>, n: usize) {
    let mut n = n as u64;
    while n >= 0x80 {
        out.push((n as u8) | 0x80);
        n >>= 7;
    }
    out.push(n as u8);
}

#[derive(Default)]
struct Writer<'k> {
    out: Vec<u8>,
    /// Each distinct string once, in first-use order, and its number.
    strings: Vec<&'k str>,
    numbers: FxHashMap<&'k str, usize>,
}

impl<'k> Writer<'k> {
    fn num(&mut self, n: usize) {
        num(&mut self.out, n);
    }

    fn str(&mut self, s: &'k str) {
        let next = self.strings.len();
        let n = *self.numbers.entry(s).or_insert(next);
        if n == next {
            self.strings.push(s);
        }
        self.num(n);
    }

    fn seq<T>(&mut self, items: &'k [T], mut each: impl FnMut(&mut Self, &'k T)) {
        self.num(items.len());
        for item in items {
            each(self, item);
        }
    }

    /// An optional number: 0 for none, else the number plus one.
    fn option(&mut self, n: Option<usize>) {
        self.num(n.map_or(0, |n| n + 1));
    }

    fn node(&mut self, node: &'k ObjectNode) {
        self.str(&node.label);
        self.seq(&node.states, |w, s| {
            w.str(&s.name);
            match &s.arg {
                None => w.num(0),
                Some(StateArg::Container(c)) => {
                    w.num(1);
                    w.str(c);
                }
                Some(StateArg::Ingredients(list)) => {
                    w.num(2);
                    w.seq(list, |w, i| w.str(i));
                }
            }
        });
    }

    fn unit(&mut self, unit: &'k FunctionalUnit) {
        // a node's number and its motion flag in one number
        let object = |w: &mut Self, o: &UnitObject| w.num(o.node.0 * 2 + usize::from(o.moves));
        self.seq(&unit.inputs, object);
        self.str(&unit.motion);
        self.seq(&unit.outputs, object);
    }

    fn goal(&mut self, goal: &'k Goal) {
        self.num(goal.node.0);
        self.option(goal.dish_class.map(|c| c as usize));
        self.str(&goal.subgraph);
        self.seq(&goal.ingredients, |w, i| w.str(i));
    }

    fn warning(&mut self, e: &'k FoonError) {
        self.str(e.code.as_str());
        self.str(&e.message);
        // the file as a list of none or one
        self.seq(e.file.as_slice(), |w, file| w.str(file));
        self.option(e.line);
        self.option(e.column);
    }
}

#[derive(Default)]
struct Reader<'b> {
    bytes: &'b [u8],
    at: usize,
    strings: Vec<SmolStr>,
    /// How many nodes were read: a unit or goal naming another node is damaged.
    nodes: usize,
}

impl Reader<'_> {
    fn take(&mut self, len: usize) -> Option<&[u8]> {
        let end = self.at.checked_add(len)?;
        let bytes = self.bytes.get(self.at..end)?;
        self.at = end;
        Some(bytes)
    }

    fn num(&mut self) -> Option<usize> {
        let mut n: u64 = 0;
        for shift in (0..64).step_by(7) {
            let byte = *self.bytes.get(self.at)?;
            self.at += 1;
            n |= u64::from(byte & 0x7f) << shift;
            if byte < 0x80 {
                return usize::try_from(n).ok();
            }
        }
        None
    }

    /// A count of items, each taking at least a byte: a count beyond the bytes left is damage, and is
    /// not allocated for.
    fn seq<T>(&mut self, mut each: impl FnMut(&mut Self) -> Option<T>) -> Option<Vec<T>> {
        let len = self.num()?;
        if len > self.bytes.len() - self.at {
            return None;
        }
        (0..len).map(|_| each(self)).collect()
    }

    fn option(&mut self) -> Option<Option<usize>> {
        Some(self.num()?.checked_sub(1))
    }

    fn smol(&mut self) -> Option<SmolStr> {
        let n = self.num()?;
        self.strings.get(n).cloned()
    }

    fn string(&mut self) -> Option<String> {
        self.smol().map(String::from)
    }

    fn node_id(&mut self, n: usize) -> Option<NodeId> {
        (n < self.nodes).then_some(NodeId(n))
    }

    fn node(&mut self) -> Option<ObjectNode> {
        let label = self.smol()?;
        let states = self.seq(|r| {
            let name = r.smol()?;
            let arg = match r.num()? {
                0 => None,
                1 => Some(StateArg::Container(r.smol()?)),
                2 => Some(StateArg::Ingredients(r.seq(Reader::smol)?)),
                _ => return None,
            };
            Some(State { name, arg })
        })?;
        // as stored: the states were sorted when the node was made
        Some(ObjectNode { label, states })
    }

    fn unit(&mut self) -> Option<FunctionalUnit> {
        let object = |r: &mut Self| {
            let n = r.num()?;
            Some(UnitObject {
                node: r.node_id(n / 2)?,
                moves: n % 2 == 1,
            })
        };
        Some(FunctionalUnit {
            inputs: self.seq(object)?,
            motion: self.string()?,
            outputs: self.seq(object)?,
        })
    }

    fn goal(&mut self) -> Option<Goal> {
        let n = self.num()?;
        Some(Goal {
            node: self.node_id(n)?,
            dish_class: self.option()?.map(u32::try_from).transpose().ok()?,
            subgraph: self.string()?,
            ingredients: self.seq(Reader::string)?,
        })
    }

    fn warning(&mut self) -> Option<FoonError> {
        let code = self.smol()?;
        let code = ErrorCode::deserialize(code.as_str().into_deserializer())
            .map_err(|_: serde::de::value::Error| ())
            .ok()?;
        let message = self.string()?;
        let file = match self.num()? {
            0 => None,
            1 => Some(self.string()?),
            _ => return None,
        };
        Some(FoonError {
            code,
            message,
            file,
            line: self.option()?,
            column: self.option()?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foon::read::parse_str;

    const A: &str = "# title: tomato salad\n//\nO\ttomato\t1\nS\twhole\nO\tknife\t0\nM\tslice\t<Assumed>\nO\ttomato\t1\nS\tsliced\nS\ton\t[cutting board]\n//\nO\ttomato\t1\nS\tsliced\nS\ton\t[cutting board]\nO\tbowl\t0\nS\tempty\nM\tadd\t<Assumed>\nO\tbowl\t0\nS\tcontains\t{tomato}\nO\tsalad\t1\t15\nS\tin\t[bowl]\n//\nO\tbowl\t0\nM\tstir\n//\n";

    fn kb() -> KnowledgeBase {
        KnowledgeBase::merge(&[parse_str("a.txt", A).unwrap()]).unwrap()
    }

    #[test]
    fn reads_back_the_same_knowledge_base_with_its_warnings() {
        let kb = kb();
        assert_eq!(kb.warnings.len(), 1, "the stir without outputs is skipped");
        assert_eq!(read(&write(&kb)), Some(kb));
    }

    #[test]
    fn damaged_or_truncated_bytes_read_as_none() {
        let bytes = write(&kb());
        for at in 0..bytes.len() {
            let mut damaged = bytes.clone();
            damaged[at] ^= 0x10;
            assert_eq!(read(&damaged), None, "byte {at} changed");
            assert_eq!(read(&bytes[..at]), None, "cut at {at}");
        }
        let mut longer = bytes.clone();
        longer.push(0);
        assert_eq!(read(&longer), None);
    }

    #[test]
    fn another_format_version_reads_as_none() {
        let mut bytes = write(&kb());
        bytes[MAGIC.len()] = bytes[MAGIC.len()].wrapping_add(1);
        assert_eq!(read(&bytes), None);
    }

    #[test]
    fn numbers_out_of_range_read_as_none_even_with_a_right_checksum() {
        // no strings, no nodes, one unit whose input is node 0
        assert_eq!(read(&with_header(&[0, 0, 1, 1, 0])), None);
        // a string number beyond the list
        assert_eq!(read(&with_header(&[0, 1, 5, 0])), None);
        // a count larger than the bytes left
        assert_eq!(read(&with_header(&[0, 0xff, 0xff, 0x03])), None);
        // a varint that never ends
        assert_eq!(read(&with_header(&[0x80; 12])), None);
    }
}

//! The plan as compact JSON for the app, written directly: what `serde_json` writes for the serde
//! derives of `plan.rs`, which stay the definition of the format, except that a node shared by
//! several units is written once and then referred to by number (see `Units`). A test holds the two
//! equal, once the numbers are resolved, on every dev plan and on texts that need escaping. A plan is
//! about 1,200 short texts and 14 kB; through serde, every key and text was scanned byte by byte
//! for escapes, and writing took twice as long.

use crate::plan::{
    Alternative, Caution, CautionKind, DishClassRef, GoalInfo, IngredientOutcome, Match, Origin,
    Plan, PlanNode, PlanUnit, ProgressLine, ProgressState, Query, QueryIngredient, Status,
};
use smol_str::SmolStr;
use std::sync::Arc;

/// Writes `plan` as compact JSON at the end of `out`, shared nodes by number.
pub fn write_plan_json(plan: &Plan, out: &mut Vec<u8>) {
    // the JSON is a little longer than the texts: one reservation for most plans
    out.reserve(16 * 1024);
    plan.write(out);
}

/// A value as JSON.
trait Json {
    fn write(&self, out: &mut Vec<u8>);
}

/// An object's fields, comma-separated. Each key comes quoted, with its colon (`key!`): the plan's
/// field names are plain ASCII and need no escape.
struct Object<'a> {
    out: &'a mut Vec<u8>,
    first: bool,
}

impl<'a> Object<'a> {
    fn begin(out: &'a mut Vec<u8>) -> Object<'a> {
        out.push(b'{');
        Object { out, first: true }
    }

    // inlined: each key is then a copy of known length, without a call to `memcpy`
    #[inline(always)]
    fn field(&mut self, key: &[u8], value: &(impl Json + ?Sized)) -> &mut Self {
        value.write(self.key(key));
        self
    }

    /// Starts a field whose value the caller writes.
    #[inline(always)]
    fn key(&mut self, key: &[u8]) -> &mut Vec<u8> {
        if !self.first {
            self.out.push(b',');
        }
        self.first = false;
        self.out.extend_from_slice(key);
        self.out
    }

    fn end(&mut self) {
        self.out.push(b'}');
    }
}

/// `"name":`, as `Object::field` takes a key.
macro_rules! key {
    ($name:literal) => {
        concat!("\"", $name, "\":").as_bytes()
    };
}

/// Whether JSON needs any of the bytes escaped (a quote, a backslash, a control character), eight at a
/// time: nearly every text needs none, and most are too short for a loop over bytes to be cheap.
fn needs_escape(bytes: &[u8]) -> bool {
    // a byte repeated eight times
    let each = |b: u8| u64::from_le_bytes([b; 8]);
    // in a word, a byte below `n` (at most 0x80) makes the subtraction set a top bit that no byte had
    // (`!w`); with every byte at `n` or above, none is. A quote or a backslash is a zero after the xor.
    let below = |w: u64, n: u8| w.wrapping_sub(each(n));
    let any = |w: u64| {
        let hit = below(w, 0x20) | below(w ^ each(b'"'), 1) | below(w ^ each(b'\\'), 1);
        (hit & !w & each(0x80)) != 0
    };
    let n = bytes.len();
    let half = |at: usize| u64::from(u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()));
    // shorter than a word: overlapping pieces of it, or the first, middle and last byte with letters
    match n {
        0 => false,
        1..=3 => any(u64::from(bytes[0])
            | u64::from(bytes[n / 2]) << 8
            | u64::from(bytes[n - 1]) << 16
            | u64::from_le_bytes([0, 0, 0, b'a', b'a', b'a', b'a', b'a'])),
        4..=7 => any(half(0) | half(n - 4) << 32),
        _ => {
            let (words, rest) = bytes.as_chunks::<8>();
            words.iter().any(|w| any(u64::from_le_bytes(*w)))
                || !rest.is_empty() && any(u64::from_le_bytes(bytes[n - 8..].try_into().unwrap()))
        }
    }
}

impl Json for str {
    fn write(&self, out: &mut Vec<u8>) {
        let bytes = self.as_bytes();
        if needs_escape(bytes) {
            return write_escaped(bytes, out);
        }
        out.push(b'"');
        out.extend_from_slice(bytes);
        out.push(b'"');
    }
}

/// A text that needs escapes, copied in runs between them: a function of its own, so that the
/// common case above saves and restores few registers.
#[cold]
#[inline(never)]
fn write_escaped(bytes: &[u8], out: &mut Vec<u8>) {
    out.push(b'"');
    let mut run = 0;
    for (i, &b) in bytes.iter().enumerate() {
        let escape: &[u8] = match b {
            b'"' => b"\\\"",
            b'\\' => b"\\\\",
            b'\n' => b"\\n",
            b'\r' => b"\\r",
            b'\t' => b"\\t",
            0x08 => b"\\b",
            0x0c => b"\\f",
            0..=0x1f => b"\\u00",
            _ => continue,
        };
        out.extend_from_slice(&bytes[run..i]);
        out.extend_from_slice(escape);
        if escape == b"\\u00" {
            const HEX: &[u8; 16] = b"0123456789abcdef";
            out.extend_from_slice(&[HEX[usize::from(b >> 4)], HEX[usize::from(b & 15)]]);
        }
        run = i + 1;
    }
    out.extend_from_slice(&bytes[run..]);
    out.push(b'"');
}

impl Json for String {
    fn write(&self, out: &mut Vec<u8>) {
        self.as_str().write(out);
    }
}

impl Json for SmolStr {
    fn write(&self, out: &mut Vec<u8>) {
        self.as_str().write(out);
    }
}

impl Json for bool {
    fn write(&self, out: &mut Vec<u8>) {
        out.extend_from_slice(if *self { b"true" } else { b"false" });
    }
}

/// Numbers as serde_json writes them (floats have more than one faithful spelling).
macro_rules! number {
    ($($t:ty),*) => {$(
        impl Json for $t {
            fn write(&self, out: &mut Vec<u8>) {
                // writing a number into a Vec cannot fail
                let _ = serde_json::to_writer(&mut *out, self);
            }
        }
    )*};
}
number!(u8, u32, f32);

impl<T: Json> Json for Option<T> {
    fn write(&self, out: &mut Vec<u8>) {
        match self {
            Some(x) => x.write(out),
            None => out.extend_from_slice(b"null"),
        }
    }
}

impl<T: Json + ?Sized> Json for Arc<T> {
    fn write(&self, out: &mut Vec<u8>) {
        (**self).write(out);
    }
}

impl<T: Json> Json for [T] {
    fn write(&self, out: &mut Vec<u8>) {
        out.push(b'[');
        for (i, x) in self.iter().enumerate() {
            if i > 0 {
                out.push(b',');
            }
            x.write(out);
        }
        out.push(b']');
    }
}

impl<T: Json> Json for Vec<T> {
    fn write(&self, out: &mut Vec<u8>) {
        self.as_slice().write(out);
    }
}

/// Unit enums by their serde name (`snake_case`).
macro_rules! name {
    ($t:ty { $($v:ident => $s:literal),* }) => {
        impl Json for $t {
            fn write(&self, out: &mut Vec<u8>) {
                let name = match self {
                    $(<$t>::$v => concat!("\"", $s, "\""),)*
                };
                out.extend_from_slice(name.as_bytes());
            }
        }
    };
}
name!(Origin {
    Reference => "reference",
    Renamed => "renamed",
    Grafted => "grafted",
    Copied => "copied",
    Attached => "attached"
});
name!(Status { Planned => "planned", Unplannable => "unplannable" });
name!(CautionKind {
    MotionOnForm => "motion_on_form",
    Uncooked => "uncooked",
    ShortOfDish => "short_of_dish",
    LeftWhole => "left_whole"
});

/// Structs field by field, in declaration order and with their serde names. The struct is taken apart
/// without `..`, so a field added to `plan.rs` and not here does not compile.
macro_rules! fields {
    // `field as Writer`: the field is written through a writer of its own (`Units`)
    ($t:ident { $($key:literal => $f:ident $(as $writer:ident)?),* }) => {
        impl Json for $t {
            fn write(&self, out: &mut Vec<u8>) {
                let $t { $($f),* } = self;
                Object::begin(out) $(.field(key!($key), fields!(@value $f $($writer)?)))* .end();
            }
        }
    };
    (@value $f:ident) => { $f };
    (@value $f:ident $writer:ident) => { &$writer($f) };
}
fields!(QueryIngredient { "object" => object, "state" => state });
fields!(DishClassRef { "index" => index, "name" => name });
fields!(GoalInfo {
    "label" => label,
    "states" => states,
    "ingredients" => ingredients,
    "subgraph" => subgraph,
    "score" => score,
    "dish_class" => dish_class
});
fields!(PlanNode {
    "label" => label,
    "states" => states,
    "ingredients" => ingredients,
    "container" => container
});
fields!(Match { "label" => label, "state" => state, "similarity" => similarity });
fields!(Alternative { "label" => label, "similarity" => similarity });
fields!(ProgressState { "physical_state" => physical_state, "location" => location });
fields!(ProgressLine {
    "ingredient" => ingredient,
    "state" => state,
    "motion" => motion,
    "end_product" => end_product
});
fields!(Caution { "kind" => kind, "food" => food, "detail" => detail });

// the three with a field left out when empty (`skip_serializing_if`), taken apart like the others
impl Json for Plan {
    fn write(&self, out: &mut Vec<u8>) {
        let Plan {
            format_version,
            query,
            dish_class,
            notes,
            modified,
            goal,
            units,
            ingredients,
            removed,
            progress_lines,
            steps,
            cautions,
            trace,
            robot,
        } = self;
        let mut o = Object::begin(out);
        o.field(key!("format_version"), format_version)
            .field(key!("query"), query)
            .field(key!("dish_class"), dish_class)
            .field(key!("notes"), notes)
            .field(key!("modified"), modified)
            .field(key!("goal"), goal)
            .field(key!("units"), &Units(units))
            .field(key!("ingredients"), ingredients)
            .field(key!("removed"), removed)
            .field(key!("progress_lines"), progress_lines)
            .field(key!("steps"), steps)
            .field(key!("cautions"), cautions);
        if let Some(trace) = trace {
            // written once per explained plan, through serde: its speed does not matter
            let _ = serde_json::to_writer(o.key(key!("trace")), trace);
        }
        if let Some(robot) = robot {
            let _ = serde_json::to_writer(o.key(key!("robot")), robot);
        }
        o.end();
    }
}

impl Json for Query {
    fn write(&self, out: &mut Vec<u8>) {
        let Query {
            id,
            dish_type,
            ingredients,
        } = self;
        let mut o = Object::begin(out);
        if let Some(id) = id {
            o.field(key!("id"), id);
        }
        o.field(key!("type"), dish_type)
            .field(key!("ingredients"), ingredients)
            .end();
    }
}

impl Json for IngredientOutcome {
    fn write(&self, out: &mut Vec<u8>) {
        let IngredientOutcome {
            object,
            state,
            case,
            matched,
            alternatives,
            low_confidence,
            overridden,
            status,
            reason,
        } = self;
        let mut o = Object::begin(out);
        o.field(key!("object"), object)
            .field(key!("state"), state)
            .field(key!("case"), case)
            .field(key!("match"), matched)
            .field(key!("alternatives"), alternatives)
            .field(key!("low_confidence"), low_confidence)
            .field(key!("overridden"), overridden)
            .field(key!("status"), status);
        if let Some(reason) = reason {
            o.field(key!("reason"), reason);
        }
        o.end();
    }
}

/// How many of the last nodes written `Units` looks through for a node written before.
const SHARED_NODE_WINDOW: usize = 64;

/// The plan's units. A node several units share (what one unit makes and the next uses, a bowl: about
/// 40 % of a plan's nodes) is written in full once; where it comes again, its number stands in its
/// place: the count of nodes written in full before it. JSON.parse then makes a third fewer objects
/// from a sixth less text, and the reader (`src/planner/index.ts`) puts the nodes back.
struct Units<'a>(&'a [PlanUnit]);

impl Json for Units<'_> {
    fn write(&self, out: &mut Vec<u8>) {
        // each node written in full so far, by address (a plan shares equal nodes), in order
        let mut written: Vec<*const PlanNode> = Vec::with_capacity(64);
        let mut nodes = |list: &[Arc<PlanNode>], out: &mut Vec<u8>| {
            out.push(b'[');
            for (i, node) in list.iter().enumerate() {
                if i > 0 {
                    out.push(b',');
                }
                let at = Arc::as_ptr(node);
                // a node is mostly used again soon after it was made: looked for among the last few
                // (a bound, so that a plan of thousands of units is not written in quadratic time; a
                // node seen before the window is written in full again, under a new number)
                let from = written.len().saturating_sub(SHARED_NODE_WINDOW);
                match written[from..].iter().rposition(|&w| w == at) {
                    Some(k) => ((from + k) as u32).write(out),
                    None => {
                        node.write(out);
                        written.push(at);
                    }
                }
            }
            out.push(b']');
        };
        out.push(b'[');
        for (i, unit) in self.0.iter().enumerate() {
            if i > 0 {
                out.push(b',');
            }
            let PlanUnit {
                inputs,
                motion,
                outputs,
                origin,
                sources,
            } = unit;
            let mut o = Object::begin(out);
            nodes(inputs, o.key(key!("inputs")));
            o.field(key!("motion"), motion);
            nodes(outputs, o.key(key!("outputs")));
            o.field(key!("origin"), origin)
                .field(key!("sources"), sources)
                .end();
        }
        out.push(b']');
    }
}

#[cfg(test)]
mod tests {
    /// Byte by byte, the bytes JSON escapes.
    fn escaped(b: u8) -> bool {
        b < 0x20 || b == b'"' || b == b'\\'
    }

    #[test]
    fn needs_escape_finds_any_byte_at_any_place() {
        for len in 0..=24 {
            for fill in [b'a', b' ', b'!', b'#', b']', 0x7f, 0x80, 0xff] {
                for at in 0..len {
                    for b in 0..=u8::MAX {
                        let mut text = vec![fill; len];
                        text[at] = b;
                        assert_eq!(super::needs_escape(&text), escaped(b), "{text:?}");
                    }
                }
                assert!(!super::needs_escape(&vec![fill; len]));
            }
        }
    }
}

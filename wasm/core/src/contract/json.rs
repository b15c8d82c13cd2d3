//! The plan as JSON (`docs/plan-format.md`), on `plan.rs`'s serde derives, the one definition of the
//! format. Serde writes every node in full (the JSON export, the CLI). `write_plan_json`, the app's way
//! through the WASM module, writes a node several units share (what one unit makes and the next uses, a
//! bowl: about 40 % of a plan's nodes) in full once and then by its number, the count of nodes written in
//! full before it, so the app parses a sixth less text; its reader (`src/planner/index.ts`) and
//! `deserialize` here put the nodes back.

use crate::contract::plan::{Origin, Plan, PlanNode, PlanUnit};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use smol_str::SmolStr;
use std::cell::Cell;
use std::sync::Arc;

thread_local! {
    /// Set while `write_plan_json` writes: `Plan::units` then writes shared nodes by number.
    static SHARED_NODES: Cell<bool> = const { Cell::new(false) };
}

/// Writes `plan` as compact JSON at the end of `out`, shared nodes by number.
pub fn write_plan_json(plan: &Plan, out: &mut Vec<u8>) {
    SHARED_NODES.set(true);
    let written = serde_json::to_writer(out, plan);
    SHARED_NODES.set(false);
    written.expect("a plan has only string keys: it always writes");
}

/// How many of the last nodes written in full are looked through for the one at hand: a node is mostly
/// used again soon after it was made, and the bound keeps a plan of thousands of units from taking
/// quadratic time (a node seen before the window is written in full again, under a new number).
const SHARED_NODE_WINDOW: usize = 64;

/// A unit as written: `PlanUnit`'s fields, its nodes each in full or by number.
#[derive(Serialize, Deserialize)]
struct Unit<N, M, S> {
    inputs: Vec<Shared<N>>,
    motion: M,
    outputs: Vec<Shared<N>>,
    origin: Origin,
    sources: S,
}

#[derive(Serialize, Deserialize)]
#[serde(untagged)]
enum Shared<N> {
    Seen(usize),
    Full(N),
}

/// `Plan::units` as JSON: every node in full, or shared nodes by number within `write_plan_json`.
pub(crate) fn serialize<S: Serializer>(
    units: &[PlanUnit],
    serializer: S,
) -> Result<S::Ok, S::Error> {
    if !SHARED_NODES.get() {
        return units.serialize(serializer);
    }
    let mut written = Vec::new();
    let mut shared = |node| shared(&mut written, node);
    let units: Vec<Unit<&PlanNode, &SmolStr, &Arc<[String]>>> = units
        .iter()
        .map(|unit| Unit {
            inputs: unit.inputs.iter().map(&mut shared).collect(),
            motion: &unit.motion,
            outputs: unit.outputs.iter().map(&mut shared).collect(),
            origin: unit.origin,
            sources: &unit.sources,
        })
        .collect();
    units.serialize(serializer)
}

/// `node` in full the first time, by number while it is among the last nodes written in full.
fn shared<'a>(
    written: &mut Vec<&'a Arc<PlanNode>>,
    node: &'a Arc<PlanNode>,
) -> Shared<&'a PlanNode> {
    let from = written.len().saturating_sub(SHARED_NODE_WINDOW);
    match written[from..].iter().rposition(|w| Arc::ptr_eq(w, node)) {
        Some(k) => Shared::Seen(from + k),
        None => {
            written.push(node);
            Shared::Full(node)
        }
    }
}

/// `Plan::units` read back from either form: each number becomes the node it stands for, shared as
/// it was.
pub(crate) fn deserialize<'de, D: Deserializer<'de>>(
    deserializer: D,
) -> Result<Vec<PlanUnit>, D::Error> {
    let units: Vec<Unit<PlanNode, SmolStr, Arc<[String]>>> = Vec::deserialize(deserializer)?;
    let mut written: Vec<Arc<PlanNode>> = Vec::new();
    let mut resolve = |nodes: Vec<Shared<PlanNode>>| -> Result<Vec<Arc<PlanNode>>, D::Error> {
        nodes
            .into_iter()
            .map(|node| match node {
                Shared::Full(node) => {
                    written.push(Arc::new(node));
                    Ok(Arc::clone(written.last().expect("just pushed")))
                }
                Shared::Seen(k) => written.get(k).cloned().ok_or_else(|| {
                    serde::de::Error::custom(format!("node number {k} before that many nodes"))
                }),
            })
            .collect()
    };
    units
        .into_iter()
        .map(|unit| {
            Ok(PlanUnit {
                inputs: resolve(unit.inputs)?,
                motion: unit.motion,
                outputs: resolve(unit.outputs)?,
                origin: unit.origin,
                sources: unit.sources,
            })
        })
        .collect()
}

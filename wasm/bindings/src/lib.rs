//! foon-wasm: the thin JavaScript face of foon-core. One coarse handle, `Planner`, built once from
//! knowledge-base files; requests and results cross the boundary as JSON text, errors as JS `Error`s
//! carrying a stable `code` and, for file errors, `file`, `line` and `column`.

use foon_core::foon::read::{parse_bytes, Subgraph};
use foon_core::foon::{bundle, snapshot};
use foon_core::similarity::{ExactMatch, Similarity};
use foon_core::{
    EmbeddingSimilarity, ErrorCode, FoonError, KnowledgeBase, Plan, PlanRequest, PlannerIndex,
};
use js_sys::JsString;
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

// Talc instead of Rust's default dlmalloc: a plan makes and frees a thousand or more small allocations, and
// interleaved runs of the two builds put Talc's plans 3-5 % faster.
#[cfg(all(not(target_feature = "atomics"), target_family = "wasm"))]
#[global_allocator]
static ALLOCATOR: talc::wasm::WasmDynamicTalc = talc::wasm::new_wasm_dynamic_allocator();

/// Converts a core error into a JS `Error` with `code`, `file`, `line`, `column` properties.
fn js_error(e: &FoonError) -> JsValue {
    let error = js_sys::Error::new(&e.to_string());
    let set = |key: &str, value: JsValue| {
        // Reflect::set only fails on frozen objects; a fresh Error is not frozen.
        let _ = js_sys::Reflect::set(&error, &JsValue::from_str(key), &value);
    };
    set("code", JsValue::from_str(e.code.as_str()));
    set("reason", JsValue::from_str(&e.message));
    if let Some(file) = &e.file {
        set("file", JsValue::from_str(file));
    }
    if let Some(line) = e.line {
        set("line", JsValue::from_f64(line as f64));
    }
    if let Some(column) = e.column {
        set("column", JsValue::from_f64(column as f64));
    }
    error.into()
}

/// A failure that is not the caller's (a result that cannot be serialised): still a JS `Error` with a
/// stable code, `internal`, so that the app can tell it from a bad file or a bad request.
fn internal_error(message: String) -> JsValue {
    let error = js_sys::Error::new(&format!("{message} (internal)"));
    let _ = js_sys::Reflect::set(
        &error,
        &JsValue::from_str("code"),
        &JsValue::from_str("internal"),
    );
    let _ = js_sys::Reflect::set(
        &error,
        &JsValue::from_str("reason"),
        &JsValue::from_str(&message),
    );
    error.into()
}

fn cannot_serialise(e: &dyn std::fmt::Display) -> JsValue {
    internal_error(format!("cannot serialise result: {e}"))
}

fn to_json<T: serde::Serialize>(value: &T) -> Result<String, JsValue> {
    serde_json::to_string(value).map_err(|e| cannot_serialise(&e))
}

fn to_json_pretty<T: serde::Serialize>(value: &T) -> Result<String, JsValue> {
    serde_json::to_string_pretty(value).map_err(|e| cannot_serialise(&e))
}

/// Collects knowledge-base files one by one (each parsed at once, so an error names its file), then
/// merges them into a `Planner`.
#[wasm_bindgen]
#[derive(Default)]
pub struct KnowledgeBaseLoader {
    graphs: Vec<Subgraph>,
}

#[wasm_bindgen]
impl KnowledgeBaseLoader {
    #[wasm_bindgen(constructor)]
    pub fn new() -> KnowledgeBaseLoader {
        KnowledgeBaseLoader::default()
    }

    /// Adds one FOON file, or a bundle of files (`#@file <name>` sections).
    #[wasm_bindgen(js_name = addFile)]
    pub fn add_file(&mut self, name: &str, bytes: &[u8]) -> Result<(), JsValue> {
        let parts = bundle::split_bundle_bytes(bytes);
        if parts.is_empty() {
            self.graphs
                .push(parse_bytes(name, bytes).map_err(|e| js_error(&e))?);
        }
        for (part, body) in parts {
            self.graphs
                .push(parse_bytes(&part, body).map_err(|e| js_error(&e))?);
        }
        Ok(())
    }

    /// Merges the files into a universal FOON and returns the planner handle. With `embeddings` (the
    /// food embedding table) ingredients are matched by meaning, otherwise by exact name only.
    pub fn finish(self, embeddings: Option<Vec<u8>>) -> Result<Planner, JsValue> {
        let kb = KnowledgeBase::merge(&self.graphs).map_err(|e| js_error(&e))?;
        Planner::new(kb, embeddings)
    }
}
/// A loaded knowledge base and everything the planner needs with it.
#[wasm_bindgen]
pub struct Planner {
    kb: KnowledgeBase,
    index: PlannerIndex,
    similarity: Box<dyn Similarity>,
    /// The plan JSON is written here and copied into a JS string: one buffer for every plan, rather than
    /// a new one grown, shrunk to size and freed per plan.
    text: RefCell<Vec<u8>>,
}

impl Planner {
    fn new(kb: KnowledgeBase, embeddings: Option<Vec<u8>>) -> Result<Planner, JsValue> {
        let similarity: Box<dyn Similarity> = match embeddings {
            Some(bytes) => {
                Box::new(EmbeddingSimilarity::from_bytes(&bytes).map_err(|e| js_error(&e))?)
            }
            None => Box::new(ExactMatch),
        };
        let index = PlannerIndex::new(&kb);
        Ok(Planner {
            kb,
            index,
            similarity,
            text: RefCell::default(),
        })
    }
}

#[wasm_bindgen]
impl Planner {
    /// The planner of a knowledge base saved with `snapshot()`, without parsing and merging its files;
    /// `undefined` when the bytes are damaged or were written by another format version (load the files).
    #[wasm_bindgen(js_name = fromSnapshot)]
    pub fn from_snapshot(
        bytes: &[u8],
        embeddings: Option<Vec<u8>>,
    ) -> Result<Option<Planner>, JsValue> {
        snapshot::read(bytes)
            .map(|kb| Planner::new(kb, embeddings))
            .transpose()
    }

    /// The loaded knowledge base as bytes for `fromSnapshot` (`foon_core::foon::snapshot`).
    pub fn snapshot(&self) -> Vec<u8> {
        snapshot::write(&self.kb)
    }

    /// Statistics of the knowledge base, as JSON (`foon_core::Stats`).
    pub fn stats(&self) -> Result<String, JsValue> {
        to_json(&foon_core::stats(&self.kb))
    }

    /// Dish classes with their recipe titles, labels and plain states, as JSON
    /// (`foon_core::Vocabulary`).
    pub fn vocabulary(&self) -> Result<String, JsValue> {
        to_json(&foon_core::vocabulary(&self.kb))
    }

    fn run(&self, request_json: &str) -> Result<Plan, JsValue> {
        let request: PlanRequest =
            foon_core::contract::decode::plan_request(request_json).map_err(|e| js_error(&e))?;
        foon_core::plan(&self.kb, &self.index, self.similarity.as_ref(), &request)
            .map_err(|e| js_error(&e))
    }

    /// Plans a request (`{query, modify?, overrides?}` as JSON) and returns the plan as JSON.
    pub fn plan(&self, request_json: &str) -> Result<JsString, JsValue> {
        let plan = self.run(request_json)?;
        // a call is never re-entered (JS is single-threaded and nothing here calls back into JS)
        let mut text = self.text.borrow_mut();
        text.clear();
        foon_core::write_plan_json(&plan, &mut text);
        let json = std::str::from_utf8(&text).map_err(|e| cannot_serialise(&e))?;
        Ok(JsString::from(json))
    }

    /// Plans a request and renders it: `json`, `foon` (plain FOON text), `pddl` (domain and problem),
    /// `pddl-domain`, `pddl-problem`, or `progress` (the published progress-line JSON).
    pub fn export(&self, request_json: &str, format: &str) -> Result<String, JsValue> {
        let plan = self.run(request_json)?;
        match format {
            "json" => to_json_pretty(&plan),
            "foon" => Ok(foon_core::foon_text(&plan)),
            "pddl" => {
                let p = foon_core::pddl(&plan);
                Ok(format!("{}\n{}", p.domain, p.problem))
            }
            "pddl-domain" => Ok(foon_core::pddl(&plan).domain),
            "pddl-problem" => Ok(foon_core::pddl(&plan).problem),
            "progress" => to_json_pretty(&foon_core::progress_json(&plan)),
            other => Err(js_error(&FoonError::new(
                ErrorCode::BadQuery,
                format!("unknown export format '{other}' (json, foon, pddl, pddl-domain, pddl-problem, progress)"),
            ))),
        }
    }

    /// The knowledge-base ingredients most similar to each name (`names_json`: a JSON array of
    /// strings), best first, as JSON `[{query, candidates: [{label, similarity}]}]`.
    pub fn similar(&self, names_json: &str, top: usize) -> Result<String, JsValue> {
        let names = foon_core::contract::decode::names(names_json).map_err(|e| js_error(&e))?;
        to_json(&foon_core::similar(
            &self.kb,
            self.similarity.as_ref(),
            &names,
            top,
        ))
    }

    /// Reader warnings (units skipped, empty arguments), as JSON error objects.
    pub fn warnings(&self) -> Result<String, JsValue> {
        to_json(&self.kb.warnings)
    }
}

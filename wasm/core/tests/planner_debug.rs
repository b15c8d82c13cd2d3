//! Tools for looking at plans (they do nothing unless asked):
//! `PLAN_QUERY=path/to/query.json cargo test --test planner_debug -- --nocapture` prints one plan;
//! `PLAN_DUMP=out.jsonl cargo test --release --test planner_debug` writes every dev plan, both variants, as
//! JSON lines (`{"variant","plan"}`). `PLAN_SIM=exact` uses exact matching instead of the embedding table.

mod common;
use common::{dev_plans, dev_queries, embeddings, foon111, load};
use foon_core::planner::violations;
use foon_core::similarity::{ExactMatch, Similarity};
use foon_core::{plan, PlanRequest, PlannerIndex, Query};

fn similarity() -> Box<dyn Similarity> {
    if std::env::var("PLAN_SIM").is_ok_and(|v| v == "exact") {
        return Box::new(ExactMatch);
    }
    Box::new(embeddings())
}

#[test]
fn dump_dev_plans() {
    let Some(out) = std::env::var_os("PLAN_DUMP") else {
        return;
    };
    let mut lines = String::new();
    for (modify, p) in dev_plans(similarity().as_ref()) {
        let variant = if modify { "modified" } else { "unmodified" };
        lines.push_str(&format!(
            "{{\"variant\":\"{variant}\",\"plan\":{}}}\n",
            serde_json::to_string(&p).unwrap()
        ));
    }
    std::fs::write(out, lines).unwrap();
}

#[test]
fn print_one_plan() {
    let Some(path) = std::env::var_os("PLAN_QUERY") else {
        return;
    };
    let kb = load(&foon111("plain"));
    let index = PlannerIndex::new(&kb);
    let sim = similarity();
    let q: Query = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let mut request = PlanRequest::new(q);
    request.modify = std::env::var("PLAN_MODIFY").map_or(true, |v| v != "0");
    let p = plan(&kb, &index, sim.as_ref(), &request).unwrap();
    for (i, (u, s)) in p.units.iter().zip(&p.steps).enumerate() {
        let show = |ns: &[std::sync::Arc<foon_core::plan::PlanNode>]| {
            ns.iter()
                .map(|n| format!("{}({})", n.label, n.states.join("; ")))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        eprintln!(
            "{:2} [{:?}] {} --{}--> {}\n     {s} {:?}",
            i,
            u.origin,
            show(&u.inputs),
            u.motion,
            show(&u.outputs),
            u.sources
        );
    }
    for o in &p.ingredients {
        eprintln!(
            "{} ({}) case {:?} {:?} {:?} {:?}",
            o.object,
            o.state,
            o.case,
            o.matched.as_ref().map(|m| (&m.label, &m.state)),
            o.status,
            o.reason
        );
    }
    for l in &p.progress_lines {
        eprintln!("line {l:?}");
    }
    eprintln!(
        "goal {:?}\nremoved {:?}\nnotes {:?}",
        p.goal, p.removed, p.notes
    );
    for v in violations(&p) {
        eprintln!("VIOLATION {v}");
    }
}

/// `PLAN_TIME=1 cargo test --release --test planner_debug time_dev_plans -- --nocapture`: native plan
/// times over the dev queries (figures only, never asserted).
#[test]
fn time_dev_plans() {
    if std::env::var_os("PLAN_TIME").is_none() {
        return;
    }
    let kb = load(&foon111("plain"));
    let index = PlannerIndex::new(&kb);
    let sim = similarity();
    let queries: Vec<Query> = dev_queries().into_iter().map(|(_, q)| q).collect();
    let mut times = Vec::new();
    for round in 0..4 {
        for q in &queries {
            let started = std::time::Instant::now();
            let _ = plan(&kb, &index, sim.as_ref(), &PlanRequest::new(q.clone()));
            if round > 0 {
                times.push(started.elapsed().as_secs_f64() * 1000.0);
            }
        }
    }
    times.sort_by(f64::total_cmp);
    let at = |p: f64| times[((times.len() as f64 * p) as usize).min(times.len() - 1)];
    eprintln!(
        "native plan: median {:.3} ms, p95 {:.3} ms, max {:.3} ms",
        at(0.5),
        at(0.95),
        times[times.len() - 1]
    );
}

//! `PLAN_QUERY=path/to/query.json cargo test --test planner_debug -- --nocapture` prints one plan.

mod common;
use common::{foon111, load};
use foon_core::planner::violations;
use foon_core::similarity::ExactMatch;
use foon_core::{plan, PlanRequest, PlannerIndex, Query};

#[test]
fn print_one_plan() {
    let Some(path) = std::env::var_os("PLAN_QUERY") else {
        return;
    };
    let kb = load(&foon111("plain"));
    let index = PlannerIndex::new(&kb);
    let q: Query = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let mut request = PlanRequest::new(q);
    request.modify = std::env::var("PLAN_MODIFY").map_or(true, |v| v != "0");
    let p = plan(&kb, &index, &ExactMatch, &request).unwrap();
    for (i, (u, s)) in p.units.iter().zip(&p.steps).enumerate() {
        let show = |ns: &[foon_core::plan::PlanNode]| {
            ns.iter()
                .map(|n| format!("{}({})", n.label, n.states.join("; ")))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        eprintln!(
            "{:2} [{:?}] {} --{}--> {}\n     {s} {:?}",
            i + 1,
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
    eprintln!(
        "goal {:?}\nremoved {:?}\nnotes {:?}",
        p.goal, p.removed, p.notes
    );
    for v in violations(&p) {
        eprintln!("VIOLATION {v}");
    }
}

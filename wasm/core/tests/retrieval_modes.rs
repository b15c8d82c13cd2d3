//! The retrieval modes (`docs/robot.md`) on a hand-made knowledge base where each picks a different tree,
//! the robot view's figures, trees whose units share a made node (hand-made, and random ones against a
//! brute force), the search budget, and on FOON-111's dev queries: each mode's tree is at least as good,
//! by its own measure, as the heuristic's.

mod common;
use common::hand::{plan_of, try_plan};
use common::{dev_queries, foon111, load};
use foon_core::contract::plan::{Performer, RetrievalMode, RobotOptions};
use foon_core::error::ErrorCode;
use foon_core::similarity::ExactMatch;
use foon_core::{plan, Plan, PlanRequest, PlannerIndex};

/// Three ways to a cucumber salad: one slice; two pours; a stir and a mix.
const SLICED: &str = "//
O\tcucumber\t1
S\twhole
M\tslice\t<Assumed>
O\tcucumber salad\t1\t15
S\tmixed
//
";
const POURED: &str = "//
O\tcucumber\t1
S\twhole
M\tpour\t<Assumed>
O\tcucumber\t1
S\tin\t[bowl]
//
O\tcucumber\t1
S\tin\t[bowl]
M\tpour\t<Assumed>
O\tcucumber salad\t1\t15
S\tmixed
//
";
const STIRRED: &str = "//
O\tcucumber\t1
S\twhole
M\tstir\t<Assumed>
O\tcucumber\t1
S\tstirred
//
O\tcucumber\t1
S\tstirred
M\tmix\t<Assumed>
O\tcucumber salad\t1\t15
S\tmixed
//
";
const FILES: &[(&str, &str)] = &[("a.txt", SLICED), ("b.txt", POURED), ("c.txt", STIRRED)];

/// The figures of the request: slicing dear and unreliable, pouring cheapest, stirring and mixing surest.
const FIGURES: &str = r#""motion_costs": {"slice": 5, "pour": 1, "stir": 1, "mix": 3},
    "success_rates": {"slice": 0.6, "pour": 0.9, "stir": 0.99, "mix": 0.99}"#;

fn request(mode: &str, extra: &str) -> String {
    format!(
        r#"{{"query": {{"type": "salad", "ingredients": [{{"object": "cucumber", "state": "whole"}}]}},
        "modify": false, "robot": {{"mode": "{mode}", {FIGURES}{extra}}}}}"#
    )
}

fn motions(p: &Plan) -> Vec<&str> {
    p.units.iter().map(|u| u.motion.as_str()).collect()
}

#[test]
fn each_mode_picks_its_own_tree() {
    let fewest = plan_of(FILES, &ExactMatch, &request("fewest_units", ""));
    assert_eq!(motions(&fewest), ["slice"]);
    let cheapest = plan_of(FILES, &ExactMatch, &request("lowest_cost", ""));
    assert_eq!(motions(&cheapest), ["pour", "pour"]);
    let surest = plan_of(FILES, &ExactMatch, &request("most_reliable", ""));
    assert_eq!(motions(&surest), ["stir", "mix"]);
    // each is the best by its own measure
    let robot = |p: &Plan| p.robot.clone().expect("a robot view");
    assert_eq!(robot(&fewest).cost, 5.0);
    assert_eq!(robot(&cheapest).cost, 2.0);
    assert_eq!(robot(&surest).cost, 4.0);
    assert!((robot(&surest).success_rate - 0.9801).abs() < 1e-9);
    assert!((robot(&cheapest).success_rate - 0.81).abs() < 1e-9);
    assert_eq!(robot(&surest).mode, RetrievalMode::MostReliable);
}

#[test]
fn the_least_reliable_units_go_to_a_person() {
    let p = plan_of(
        FILES,
        &ExactMatch,
        &request("lowest_cost", r#", "human_steps": 1"#),
    );
    let view = p.robot.expect("a robot view");
    // equally reliable pours: the first goes to the person
    assert_eq!(view.human_units, [0]);
    assert_eq!(view.units[0].by, Performer::Human);
    assert_eq!(view.units[1].by, Performer::Robot);
    assert_eq!((view.cost, view.success_rate), (1.0, 0.9));
}

#[test]
fn without_robot_options_the_plan_has_no_robot_view_and_bad_figures_are_refused() {
    let plain = r#"{"query": {"type": "salad", "ingredients": [{"object": "cucumber", "state": "whole"}]}}"#;
    assert_eq!(plan_of(FILES, &ExactMatch, plain).robot, None);
    let bad = request("lowest_cost", "").replace("0.6", "1.6");
    let e = try_plan(FILES, &ExactMatch, &bad).expect_err("a rate above 1");
    assert_eq!(e.code, ErrorCode::BadQuery);
    assert!(e.message.contains("'slice'"), "{e}");
    // an unknown mode or option is a bad request with its place in the JSON
    for wrong in [r#""mode": "fastest""#, r#""human_step": 1"#] {
        let text = format!(r#"{{"query": {{"type": "salad"}}, "robot": {{{wrong}}}}}"#);
        let e = foon_core::contract::decode::plan_request(&text).expect_err(wrong);
        assert_eq!((e.code, e.line), (ErrorCode::BadQuery, Some(1)), "{e}");
    }
}

#[test]
fn modified_plans_in_every_mode_are_sound() {
    for mode in ["heuristic", "fewest_units", "lowest_cost", "most_reliable"] {
        let r = request(mode, "").replace(r#""modify": false"#, r#""modify": true"#);
        let p = plan_of(FILES, &ExactMatch, &r);
        assert!(!p.units.is_empty(), "{mode}");
    }
}

/// Two ways to a cucumber salad with salt: blend the cucumber with the salt (cost 10), or slice it (5),
/// pour one part and stir the other (1 each) and mix the two (1). The lightest derivation counts the
/// slicing once for each unit taking the slices (13); the tree's own cost is 8.
const SHARED_SLICES: &str = "//
O\tcucumber\t1
S\twhole
M\tslice\t<Assumed>
O\tcucumber\t1
S\tsliced
//
O\tcucumber\t1
S\tsliced
M\tpour\t<Assumed>
O\tcucumber\t1
S\tin\t[bowl]
//
O\tcucumber\t1
S\tsliced
M\tstir\t<Assumed>
O\tcucumber\t1
S\tstirred
//
O\tcucumber\t1
S\tin\t[bowl]
O\tcucumber\t1
S\tstirred
M\tmix\t<Assumed>
O\tcucumber salad\t1\t15
S\tmixed
//
";
const BLENDED: &str = "//
O\tcucumber\t1
S\twhole
O\tsalt\t1
S\tground
M\tblend\t<Assumed>
O\tcucumber salad\t1\t15
S\tmixed
//
";

#[test]
fn a_made_node_two_units_share_counts_once() {
    let files = [("a.txt", SHARED_SLICES), ("b.txt", BLENDED)];
    let request = r#"{"query": {"type": "salad", "ingredients": [{"object": "cucumber", "state": "whole"},
        {"object": "salt", "state": "ground"}]}, "modify": false, "robot": {"mode": "lowest_cost",
        "motion_costs": {"slice": 5, "pour": 1, "stir": 1, "mix": 1, "blend": 10}}}"#;
    // the paper's heuristic blends (it keeps the salt)
    let heuristic = request.replace("lowest_cost", "heuristic");
    assert_eq!(
        motions(&plan_of(&files, &ExactMatch, &heuristic)),
        ["blend"]
    );
    let cheapest = plan_of(&files, &ExactMatch, request);
    let mut chosen = motions(&cheapest);
    chosen.sort_unstable();
    assert_eq!(chosen, ["mix", "pour", "slice", "stir"]);
    assert_eq!(cheapest.robot.expect("a robot view").cost, 8.0);
    assert!(
        cheapest.notes.iter().all(|n| !n.contains("lowest_cost")),
        "{:?}",
        cheapest.notes
    );
}

/// A salad of 18 cucumber parts, each poured from shared slices (cost 1) or stirred (free) from a part
/// shaken (free) from a part peeled (10): the search's bound sees only the free units below a stirred part
/// until every part is decided, so it meets all 2^18 ways of deciding them, more than its budget.
fn many_parts() -> [(&'static str, String); 2] {
    let unit = |input: &str, motion: &str, output: &str| {
        format!(
            "//\nO\tcucumber\t1\nS\t{input}\nM\t{motion}\t<Assumed>\nO\tcucumber\t1\nS\t{output}\n"
        )
    };
    let parts = 0..18;
    let mix: String = parts
        .clone()
        .map(|i| format!("O\tcucumber\t1\nS\tin\t[bowl {i}]\n"))
        .collect();
    let mix = format!("//\n{mix}M\tmix\t<Assumed>\nO\tcucumber salad\t1\t15\nS\tmixed\n//\n");
    let mut poured = unit("whole", "slice", "sliced");
    let mut stirred = String::new();
    for i in parts {
        poured += &unit("sliced", "pour", &format!("in\t[bowl {i}]"));
        stirred += &unit("whole", "peel", &format!("in\t[jar {i}]"));
        stirred += &unit(
            &format!("in\t[jar {i}]"),
            "shake",
            &format!("in\t[cup {i}]"),
        );
        stirred += &unit(
            &format!("in\t[cup {i}]"),
            "stir",
            &format!("in\t[bowl {i}]"),
        );
    }
    [("a.txt", poured + &mix), ("b.txt", stirred + &mix)]
}

#[test]
fn when_the_search_budget_runs_out_the_best_tree_found_is_kept_and_said() {
    let files = many_parts();
    let files: Vec<(&str, &str)> = files.iter().map(|(n, t)| (*n, t.as_str())).collect();
    let request = r#"{"query": {"type": "salad", "ingredients": [{"object": "cucumber", "state": "whole"}]},
        "modify": false, "robot": {"mode": "lowest_cost", "motion_costs": {"slice": 1, "pour": 1,
        "mix": 1, "stir": 0, "shake": 0, "peel": 10}}, "explain": true}"#;
    let p = plan_of(&files, &ExactMatch, request);
    // the lightest derivation's tree: slice, 18 pours, mix
    assert_eq!(p.units.len(), 20);
    assert_eq!(p.robot.expect("a robot view").cost, 20.0);
    let note = "lowest_cost: the search for the best tree stopped";
    assert!(p.notes.iter().any(|n| n.contains(note)), "{:?}", p.notes);
    let trace = p.trace.expect("explain asks for a trace");
    let why = trace.retrieval[0].why.as_deref().expect("the mode's name");
    assert_eq!(
        why,
        "lowest_cost (the best tree found: the search budget ran out)"
    );
}

/// On FOON-111, each mode's reference task tree is no worse by its measure than the heuristic's.
#[test]
fn on_dev_queries_each_mode_is_at_least_as_good_as_the_heuristic() {
    let kb = load(&foon111("plain"));
    let index = PlannerIndex::new(&kb);
    let run = |q: &foon_core::Query, mode: RetrievalMode| {
        let mut r = PlanRequest::new(q.clone());
        r.modify = false;
        r.robot = Some(RobotOptions {
            mode,
            ..RobotOptions::default()
        });
        plan(&kb, &index, &ExactMatch, &r).unwrap_or_else(|e| panic!("{e}"))
    };
    let mut better = [0; 3];
    for (path, q) in dev_queries().iter().step_by(4) {
        let base = run(q, RetrievalMode::Heuristic);
        let view = |p: &Plan| p.robot.clone().unwrap();
        let fewest = run(q, RetrievalMode::FewestUnits);
        let cheapest = run(q, RetrievalMode::LowestCost);
        let surest = run(q, RetrievalMode::MostReliable);
        assert!(fewest.units.len() <= base.units.len(), "{path}");
        assert!(view(&cheapest).cost <= view(&base).cost + 1e-9, "{path}");
        assert!(
            view(&surest).success_rate >= view(&base).success_rate - 1e-9,
            "{path}"
        );
        better[0] += usize::from(fewest.units.len() < base.units.len());
        better[1] += usize::from(view(&cheapest).cost < view(&base).cost);
        better[2] += usize::from(view(&surest).success_rate > view(&base).success_rate);
    }
    eprintln!("trees better than the heuristic's (fewest, cheapest, surest): {better:?}");
    assert!(better.iter().all(|&b| b > 0), "{better:?}");
}

/// A small random graph in one recipe: the cucumber's states s1..s5 and the salad, each made by one or two
/// units from one or two earlier states (s0 is the whole cucumber, from the kitchen); unit i has motion
/// `m{i}`, and a cost of 0 to 5. Returns the recipe, each unit's inputs (state numbers), output and cost.
#[allow(clippy::type_complexity)]
fn random_graph(seed: &mut u64) -> (String, Vec<(Vec<usize>, usize, u32)>) {
    let mut next = |n: u64| {
        *seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((*seed >> 33) % n) as usize
    };
    let mut units = Vec::new();
    for output in 1..=6 {
        for _ in 0..=next(2) {
            let mut inputs: Vec<usize> = (0..=next(2)).map(|_| next(output as u64)).collect();
            inputs.sort_unstable();
            inputs.dedup();
            units.push((inputs, output, next(6) as u32));
        }
    }
    let node = |s: usize| match s {
        0 => "O\tcucumber\t1\nS\twhole\n".to_string(),
        6 => "O\tcucumber salad\t1\t15\nS\tmixed\n".to_string(),
        s => format!("O\tcucumber\t1\nS\ts{s}\n"),
    };
    let mut text = String::new();
    for (i, (inputs, output, _)) in units.iter().enumerate() {
        text += "//\n";
        text += &inputs.iter().map(|&s| node(s)).collect::<String>();
        text += &format!("M\tm{i}\t<Assumed>\n{}", node(*output));
    }
    (text + "//\n", units)
}

/// The least (cost, units) of any set of the units that makes the salad from the whole cucumber.
fn cheapest_by_brute_force(units: &[(Vec<usize>, usize, u32)]) -> (u32, usize) {
    let mut best = (u32::MAX, usize::MAX);
    for set in 0u32..1 << units.len() {
        let chosen: Vec<_> = (0..units.len()).filter(|i| set >> i & 1 == 1).collect();
        let mut made = [true, false, false, false, false, false, false];
        while let Some(&i) = chosen
            .iter()
            .find(|&&i| !made[units[i].1] && units[i].0.iter().all(|&s| made[s]))
        {
            made[units[i].1] = true;
        }
        if made[6] {
            let cost = chosen.iter().map(|&i| units[i].2).sum();
            best = best.min((cost, chosen.len()));
        }
    }
    best
}

#[test]
fn on_random_graphs_with_shared_states_the_cheapest_tree_is_found() {
    let mut seed = 33;
    for round in 0..200 {
        let (text, units) = random_graph(&mut seed);
        let costs: Vec<String> = (0..units.len())
            .map(|i| format!(r#""m{i}": {}"#, units[i].2))
            .collect();
        let request = format!(
            r#"{{"query": {{"type": "salad", "ingredients": [{{"object": "cucumber", "state": "whole"}}]}},
            "modify": false, "robot": {{"mode": "lowest_cost", "motion_costs": {{{}}}}}}}"#,
            costs.join(", ")
        );
        let p = plan_of(&[("a.txt", &text)], &ExactMatch, &request);
        let found = (p.robot.expect("a robot view").cost as u32, p.units.len());
        assert_eq!(
            found,
            cheapest_by_brute_force(&units),
            "round {round}:\n{text}"
        );
    }
}

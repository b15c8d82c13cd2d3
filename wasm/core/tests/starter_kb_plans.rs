//! The starter knowledge base on its own (no FOON-111) plans every dev query of the paper's five evaluation
//! classes (salad, cake, soup, omelette, drinks) with the shipped embedding table, into sound task trees.

mod common;
use common::{dev_queries, embeddings, load, starter_kb_files};
use foon_core::planner::violations;
use foon_core::{plan, PlanRequest, PlannerIndex};
use std::collections::BTreeMap;

#[test]
fn every_dev_query_of_the_evaluation_classes_gets_a_sound_plan() {
    let kb = load(&starter_kb_files());
    let index = PlannerIndex::new(&kb);
    let sim = embeddings();
    let mut cases: BTreeMap<String, usize> = BTreeMap::new();
    let mut planned = 0;
    for (path, query) in dev_queries() {
        if !["salad", "cake", "soup", "omelette", "drinks"].contains(&query.dish_type.as_str()) {
            continue;
        }
        let plan = plan(&kb, &index, &sim, &PlanRequest::new(query))
            .unwrap_or_else(|e| panic!("{path}: {e}"));
        let broken = violations(&plan);
        assert!(broken.is_empty(), "{path}: {broken:?}");
        assert!(!plan.units.is_empty(), "{path}: an empty task tree");
        assert_eq!(
            plan.dish_class.as_ref().map(|c| c.name.as_str()),
            Some(plan.query.dish_type.as_str()),
            "{path}"
        );
        for i in &plan.ingredients {
            let case = i.case.map_or("none".to_string(), |c| c.to_string());
            *cases.entry(case).or_insert(0) += 1;
        }
        planned += 1;
    }
    assert_eq!(planned, 200, "40 dev queries for each of the five classes");
    eprintln!("starter KB, 200 dev queries of the evaluation classes: cases {cases:?}");
}

//! The state-transition model mined from FOON-111's functional units: which motion brings a food of
//! each form into which state, and the plans that follow it.

mod common;
use common::{embeddings, foon111, load};
use foon_core::planner::{Transitions, Verdict};
use foon_core::vocab::foods;
use foon_core::{plan, PlanRequest, PlannerIndex, Query};

#[test]
fn foon_handles_each_form_of_food_only_in_ways_a_cook_would() {
    let kb = load(&foon111("plain"));
    let t = Transitions::mine(&kb);
    // what recipes do
    assert_eq!(t.makes("onion", "chop", "chopped"), Verdict::Seen);
    assert_eq!(t.makes("flour", "pour", ""), Verdict::Seen);
    assert_eq!(t.makes("milk", "pour", ""), Verdict::Seen);
    assert_eq!(t.makes("butter", "melt", "melted"), Verdict::Seen);
    // what none does: a powder squeezed, butter blended soft, milk chopped
    assert_eq!(t.makes("sugar", "squeeze", ""), Verdict::Unseen);
    assert_eq!(t.makes("butter", "blend", "softened"), Verdict::Unseen);
    assert_eq!(t.makes("milk", "chop", "chopped"), Verdict::Unseen);
    // a food of unknown form is not judged
    assert_eq!(t.makes("unheard-of food", "squeeze", ""), Verdict::Unknown);
    // cheese is grated in FOON: asked shredded, it is grated
    assert_eq!(t.motion_for("cheddar", "shredded"), Some("grate"));
    assert_ne!(t.motion_for("butter", "softened"), Some("blend"));
}

#[test]
fn butter_asked_soft_is_never_blended_and_cheese_asked_shredded_is_grated() {
    let kb = load(&foon111("plain"));
    let index = PlannerIndex::new(&kb);
    let sim = embeddings();
    let q: Query = serde_json::from_str(
        r#"{"dish_type":"cake","ingredients":[
            {"object":"butter","state":"softened"},{"object":"flour","state":"ground"},
            {"object":"sugar","state":"ground"},{"object":"egg","state":"whole raw"},
            {"object":"cheddar","state":"shredded"}]}"#,
    )
    .unwrap();
    let p = plan(&kb, &index, &sim, &PlanRequest::new(q)).unwrap();
    let line = |food: &str| {
        p.progress_lines
            .iter()
            .find(|l| l.ingredient == food)
            .unwrap_or_else(|| panic!("no line for {food}"))
    };
    assert!(
        line("butter").motion.iter().all(|m| m != "blend"),
        "{:?}",
        line("butter")
    );
    // grated by the cook, or bought grated: never cut another way
    let cheddar = line("cheddar");
    let grated =
        cheddar.motion.iter().any(|m| m == "grate") || cheddar.state[0].physical_state == "grated";
    assert!(grated, "{cheddar:?}");
    assert!(
        cheddar
            .motion
            .iter()
            .all(|m| !foods::cuts(m) || m == "grate"),
        "{cheddar:?}"
    );
}

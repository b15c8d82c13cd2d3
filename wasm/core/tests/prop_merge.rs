//! Properties of the universal FOON on random graphs: the merge gives the same knowledge base for any file
//! order (and for one bundle holding the same files); its indexes agree with its units; exported as a
//! bundle and read back, or as a snapshot, it is the same knowledge base.

mod gen;
use foon_core::foon::{snapshot, write};
use foon_core::{load, KnowledgeBase};
use proptest::prelude::*;

fn as_files(files: &[(String, String)]) -> Vec<(String, Vec<u8>)> {
    files
        .iter()
        .map(|(n, t)| (n.clone(), t.clone().into_bytes()))
        .collect()
}

fn assert_indexes_agree(kb: &KnowledgeBase) {
    for (n, node) in kb.each_node() {
        for &u in &kb.producers[n] {
            assert!(kb.units[u].output_nodes().any(|m| m == n));
        }
        for &u in &kb.consumers[n] {
            assert!(kb.units[u].input_nodes().any(|m| m == n));
        }
        assert_eq!(kb.node_id(node), Some(n));
        if kb.producers[n].is_empty() {
            assert!(kb.kitchen[n], "a node nothing makes must be in the kitchen");
        }
    }
    for (u, unit) in kb.each_unit() {
        assert!(unit.input_nodes().all(|n| kb.consumers[n].contains(&u)));
        assert!(unit.output_nodes().all(|n| kb.producers[n].contains(&u)));
        assert!(!kb.provenance[u].is_empty());
    }
    // no two units are the same (inputs, motion, outputs)
    let mut keys: Vec<_> = kb
        .units
        .iter()
        .map(|u| {
            (
                u.input_nodes().collect::<Vec<_>>(),
                &u.motion,
                u.output_nodes().collect::<Vec<_>>(),
            )
        })
        .collect();
    let all = keys.len();
    keys.sort();
    keys.dedup();
    assert_eq!(keys.len(), all, "duplicate units after merging");
    // goals: one per (subgraph, node)
    let mut goals: Vec<_> = kb.goals.iter().map(|g| (&g.subgraph, g.node)).collect();
    let all = goals.len();
    goals.dedup();
    assert_eq!(goals.len(), all, "a node is a goal twice in one subgraph");
}

proptest! {
    #![proptest_config(gen::config(128))]

    #[test]
    fn the_universal_foon_does_not_depend_on_file_order(
        files in gen::files(5, 6),
        seed in any::<u64>(),
    ) {
        let kb = load(&as_files(&files)).unwrap();
        assert_indexes_agree(&kb);
        prop_assert_eq!(snapshot::read(&snapshot::write(&kb)), Some(kb.clone()));
        // a permutation drawn from the seed, and the reverse order
        let mut shuffled = files.clone();
        let mut state = seed | 1;
        for i in (1..shuffled.len()).rev() {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            shuffled.swap(i, (state % (i as u64 + 1)) as usize);
        }
        prop_assert_eq!(&load(&as_files(&shuffled)).unwrap(), &kb);
        let reversed: Vec<_> = files.iter().rev().cloned().collect();
        prop_assert_eq!(&load(&as_files(&reversed)).unwrap(), &kb);
        // the same files as one bundle
        let bundle = foon_core::foon::bundle::join_bundle(files.iter().map(|(n, t)| (n.as_str(), t.as_str())));
        prop_assert_eq!(&load(&[("kb.foon".to_string(), bundle.into_bytes())]).unwrap(), &kb);
    }

    #[test]
    fn a_knowledge_base_exported_as_a_bundle_reads_back_the_same(files in gen::files(4, 6)) {
        let kb = load(&as_files(&files)).unwrap();
        let text = write::kb_bundle(&kb);
        let again = load(&[("export.foon".to_string(), text.clone().into_bytes())])
            .unwrap_or_else(|e| panic!("{e}\n{text}"));
        prop_assert_eq!(&again.nodes, &kb.nodes);
        prop_assert_eq!(&again.units, &kb.units);
        prop_assert_eq!(&again.provenance, &kb.provenance);
        prop_assert_eq!(&again.producers, &kb.producers);
        prop_assert_eq!(&again.kitchen, &kb.kitchen);
        prop_assert_eq!(&again.goals, &kb.goals);
        prop_assert!(again.warnings.is_empty());
        // and exporting again gives the same text
        prop_assert_eq!(write::kb_bundle(&again), text);
    }

    #[test]
    fn a_file_given_twice_adds_no_units(files in gen::files(3, 6)) {
        let kb = load(&as_files(&files)).unwrap();
        let mut twice = as_files(&files);
        twice.extend(files.iter().map(|(n, t)| (format!("copy-{n}"), t.clone().into_bytes())));
        let doubled = load(&twice).unwrap();
        prop_assert_eq!(&doubled.nodes, &kb.nodes);
        prop_assert_eq!(doubled.units.len(), kb.units.len());
        prop_assert_eq!(doubled.units_before_merge, 2 * kb.units_before_merge);
    }
}

//! The knowledge base's snapshot (`foon::snapshot`) on the real knowledge bases: FOON-111 in both dialects
//! and the starter knowledge base read back equal, and so plan the same; damage anywhere reads as `None`.

mod common;
use common::{foon111, load, starter_kb_files};
use foon_core::foon::snapshot;
use foon_core::KnowledgeBase;

fn assert_reads_back(kb: &KnowledgeBase) -> Vec<u8> {
    let bytes = snapshot::write(kb);
    let again = snapshot::read(&bytes).expect("a fresh snapshot reads");
    assert_eq!(&again, kb);
    bytes
}

#[test]
fn foon111_reads_back_equal() {
    assert_reads_back(&load(&foon111("plain")));
    let indexed = load(&foon111("indexed"));
    assert!(!indexed.warnings.is_empty(), "FOON-111 has skipped units");
    assert_reads_back(&indexed);
}

#[test]
fn the_starter_knowledge_base_reads_back_equal_and_damage_is_seen() {
    let bytes = assert_reads_back(&load(&starter_kb_files()));
    // a byte changed anywhere (every 97th, from the header on) or the end cut off
    for at in (0..bytes.len()).step_by(97) {
        let mut damaged = bytes.clone();
        damaged[at] = damaged[at].wrapping_add(1);
        assert_eq!(snapshot::read(&damaged), None, "byte {at} changed");
    }
    assert_eq!(snapshot::read(&bytes[..bytes.len() - 1]), None);
}

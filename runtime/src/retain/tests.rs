use program_image::Region;

use super::*;
use crate::engine::{Engine, ResetKind};
use crate::test_images::{TestTask, count, dint, image};

/// An engine whose task 0's cycle count (at 8) is RETAIN.
fn retaining_engine() -> Engine {
    Engine::new(image(&[TestTask::cyclic(1_000_000, 0)], &[(count(0), 4)])).unwrap()
}

fn set_dint(engine: &mut Engine, offset: u32, value: i32) {
    let at = offset as usize;
    engine.region_mut(Region::Data)[at..at + 4].copy_from_slice(&value.to_le_bytes());
}

#[test]
fn retained_values_survive_into_a_new_engine_of_the_same_image() {
    let dir = tempfile::tempdir().unwrap();
    let mut engine = retaining_engine();
    set_dint(&mut engine, count(0), 41);
    // The sequence counter is not retained.
    set_dint(&mut engine, 0, 7);
    assert!(RetainStore::new(dir.path()).save(&engine).unwrap());
    assert!(!dir.path().join("retain.bin.tmp").exists());

    let mut restarted = retaining_engine();
    let mut store = RetainStore::new(dir.path());
    let outcome = store.restore(&mut restarted);
    assert_eq!(
        outcome,
        RetainRestore::Restored {
            path: dir.path().join(RETAIN_FILE)
        }
    );
    assert_eq!(dint(restarted.region(Region::Data), count(0)), 41);
    assert_eq!(dint(restarted.region(Region::Data), 0), 0);
    // What was just restored is not written again.
    assert!(!store.save(&restarted).unwrap());
    set_dint(&mut restarted, count(0), 42);
    assert!(store.save(&restarted).unwrap());
}

#[test]
fn data_saved_by_another_layout_is_not_restored_and_the_message_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let mut engine = retaining_engine();
    set_dint(&mut engine, count(0), 41);
    RetainStore::new(dir.path()).save(&engine).unwrap();

    let two_tasks = [
        TestTask::cyclic(1_000_000, 0),
        TestTask::cyclic(1_000_000, 1),
    ];
    let mut other = Engine::new(image(&two_tasks, &[(count(0), 4)])).unwrap();
    let outcome = RetainStore::new(dir.path()).restore(&mut other);
    assert!(matches!(outcome, RetainRestore::LayoutChanged { .. }));
    assert!(
        outcome
            .to_string()
            .contains("start from their initial values"),
        "{outcome}"
    );
    assert_eq!(dint(other.region(Region::Data), count(0)), 0);
}

#[test]
fn a_damaged_file_is_not_restored_and_is_named_with_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    let mut engine = retaining_engine();
    set_dint(&mut engine, count(0), 41);
    RetainStore::new(dir.path()).save(&engine).unwrap();
    let path = dir.path().join(RETAIN_FILE);
    let mut bytes = fs::read(&path).unwrap();
    let middle = bytes.len() / 2;
    bytes[middle] ^= 0xff;
    fs::write(&path, &bytes).unwrap();

    let mut restarted = retaining_engine();
    let outcome = RetainStore::new(dir.path()).restore(&mut restarted);
    let message = outcome.to_string();
    assert!(matches!(outcome, RetainRestore::Unreadable { .. }));
    assert!(
        message.contains("SHA-256") && message.contains("retain.bin"),
        "{message}"
    );
    assert_eq!(dint(restarted.region(Region::Data), count(0)), 0);

    fs::write(&path, &bytes[..20]).unwrap();
    let outcome = RetainStore::new(dir.path()).restore(&mut restarted);
    assert!(outcome.to_string().contains("truncated"), "{outcome}");
}

#[test]
fn an_origin_reset_deletes_the_saved_data() {
    let dir = tempfile::tempdir().unwrap();
    let mut engine = retaining_engine();
    let mut store = RetainStore::new(dir.path());
    assert!(matches!(
        store.restore(&mut engine),
        RetainRestore::NothingSaved { .. }
    ));
    set_dint(&mut engine, count(0), 5);
    store.save(&engine).unwrap();
    engine.reset(ResetKind::Origin);
    store.delete().unwrap();
    assert!(!store.path().exists());
    // Deleting twice is fine, and the next save writes even identical bytes.
    store.delete().unwrap();
    set_dint(&mut engine, count(0), 5);
    assert!(store.save(&engine).unwrap());
}

#[test]
fn an_image_without_retained_variables_leaves_saved_data_alone() {
    let dir = tempfile::tempdir().unwrap();
    let mut engine = retaining_engine();
    set_dint(&mut engine, count(0), 41);
    RetainStore::new(dir.path()).save(&engine).unwrap();

    let mut plain = Engine::new(image(&[TestTask::cyclic(1_000_000, 0)], &[])).unwrap();
    let mut store = RetainStore::new(dir.path());
    assert_eq!(
        store.restore(&mut plain),
        RetainRestore::NoRetainedVariables
    );
    assert!(!store.save(&plain).unwrap());
    assert!(
        RetainStore::new(dir.path())
            .restore(&mut retaining_engine())
            .to_string()
            .starts_with("restored")
    );
}

#[test]
fn the_layout_hash_changes_with_the_retained_ranges_only() {
    let task = [TestTask::cyclic(1_000_000, 0)];
    let base = image(&task, &[(count(0), 4)]);
    let mut renamed = base.clone();
    renamed.pous[0].name = "Renamed".to_owned();
    assert_eq!(layout_hash(&base), layout_hash(&renamed));
    assert_ne!(layout_hash(&base), layout_hash(&image(&task, &[(0, 4)])));
}

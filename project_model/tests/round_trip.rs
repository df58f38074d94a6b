//! Property tests of the project files: saving and loading gives back the same project, and
//! saving an unchanged project rewrites nothing.

#![allow(clippy::unwrap_used, clippy::expect_used)] // Test helpers may panic: a panic is a failed test.

use std::collections::BTreeSet;

use proptest::prelude::*;

use project_model::{arb, load_project, save_project};

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, ..ProptestConfig::default() })]

    #[test]
    fn a_saved_project_loads_back_equal_and_saves_again_unchanged(project in arb::project()) {
        let dir = tempfile::tempdir().unwrap();
        let first = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
        prop_assert_eq!(first.written.len(), first.files.len());

        let loaded = load_project(dir.path()).unwrap();
        prop_assert_eq!(&loaded.project, &project);
        prop_assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        prop_assert_eq!(&loaded.files, &first.files);

        let second = save_project(&loaded.project, dir.path(), &loaded.files).unwrap();
        prop_assert!(second.written.is_empty(), "rewrote {:?}", second.written);
        prop_assert!(second.removed.is_empty());
    }
}

//! Data other tools wrote into an imported PLCopen XML file that Rivet does not model, kept in
//! the project so an export writes it back where it came from (`docs/plcopen-xml.md` §2.6, §5.5).

use serde::{Deserialize, Serialize};

use crate::ObjectKind;
use crate::network::NetworkOutput;
use crate::network_walk::ElementRef;

/// The vendor data of an imported PLCopen file. Saved in `plcopen.toml` beside the manifest
/// when not empty (`docs/project-format.md` §3.1); lives as long as the project.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VendorData {
    /// The imported file's `fileHeader@creationDateTime`, which the export writes back instead
    /// of its fixed date, so a file taken in and given back keeps its date.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub creation_date_time: Option<String>,
    /// The `addData/data` entries, ordered by place and, within a place, as the file had them.
    #[serde(default, rename = "entry", skip_serializing_if = "Vec::is_empty")]
    pub entries: Vec<VendorEntry>,
}

/// One `addData/data` entry of another tool.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VendorEntry {
    /// Where it stood, named by object and path: `project`, `contentHeader`, `pou:Main`,
    /// `pou:Main/body`, `pou:Main/body/element:7` (element 7 of its LD or FBD body),
    /// `pou:Main/interface`, `pou:Main/action:A`, `pou:Main/transition:T`,
    /// `pou:Main/variable:x`, `type:T`, `gvl:G`, `gvl:G/variable:x`, `task:T`,
    /// `configuration`, `resource` (`docs/plcopen-xml.md` §2.6).
    pub place: String,
    /// The whole `data` element as the file had it, from `<data` to `</data>`.
    pub xml: String,
    /// For an element's entry (`…/element:ID`), the [`element_signature`] of the element the
    /// object became: the export writes the entry into element ID only while its signature is
    /// the same, since an edit may give the id to another element or change the element
    /// (`docs/plcopen-xml.md` §5.5). An element's entry without one is never written into an
    /// element.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub signature: Option<String>,
}

impl VendorEntry {
    /// True when this entry belongs to `element`: its recorded signature is the element's
    /// (identifiers compare without regard to case, as in IEC 61131-3).
    pub fn fits(&self, element: ElementRef<'_>) -> bool {
        self.signature
            .as_deref()
            .is_some_and(|signature| signature.eq_ignore_ascii_case(&element_signature(element)))
    }
}

/// What an LD or FBD element is, in a few words: its kind and what tells one of that kind from
/// another (`block ADD`, `block TON EN` for a box with EN/ENO, `operand x`, `coil y`,
/// `jump L`, `return`, `parallel`, `branch`). Another tool's data of an object is only written
/// back into an element with the signature the object's element had.
pub fn element_signature(element: ElementRef<'_>) -> String {
    match element {
        ElementRef::Operand(operand) => format!("operand {}", operand.text.trim()),
        ElementRef::Parallel(_) => "parallel".to_owned(),
        ElementRef::Block(block) if block.has_en_eno() => format!("block {} EN", block.type_name),
        ElementRef::Block(block) => format!("block {}", block.type_name),
        ElementRef::Output(NetworkOutput::Coil(coil)) => format!("coil {}", coil.variable.trim()),
        ElementRef::Output(NetworkOutput::Jump { label, .. }) => format!("jump {label}"),
        ElementRef::Output(NetworkOutput::Return { .. }) => "return".to_owned(),
        ElementRef::Output(NetworkOutput::Branch { .. }) => "branch".to_owned(),
    }
}

impl VendorData {
    /// True when there is nothing to keep.
    pub fn is_empty(&self) -> bool {
        self.creation_date_time.is_none() && self.entries.is_empty()
    }

    /// Moves the entries of the object `old` of `kind` (its own and its parts') to its new name
    /// `new`, as a rename of the object does: their places name it. Entries already at `new`
    /// are a deleted object's (names are unique): they move to `detached:PLACE`, a place no
    /// object has, so they are kept as leftovers and not written into the renamed object.
    pub fn rename_object(&mut self, kind: ObjectKind, old: &str, new: &str) {
        let (Some(old), Some(new)) = (vendor_prefix(kind, old), vendor_prefix(kind, new)) else {
            return;
        };
        self.move_place(&old, &new);
    }

    /// Moves the entries of the task `old` (place `task:OLD`) to its new name `new`, as a
    /// rename of the task does, with the same care for a deleted task's entries at `new` as
    /// [`VendorData::rename_object`].
    pub fn rename_task(&mut self, old: &str, new: &str) {
        self.move_place(&format!("task:{old}"), &format!("task:{new}"));
    }

    /// Moves the entries at the place `old` and below it to `new`, detaching those already at
    /// `new`, and keeps the entries ordered by place.
    fn move_place(&mut self, old: &str, new: &str) {
        // A rename that changes only the case keeps the entries where they are.
        let same_name = old.eq_ignore_ascii_case(new);
        for entry in &mut self.entries {
            if !same_name && is_place_of(&entry.place, new) {
                entry.place = format!("detached:{}", entry.place);
            }
        }
        for entry in &mut self.entries {
            if is_place_of(&entry.place, old) {
                entry.place = format!("{new}{}", &entry.place[old.len()..]);
            }
        }
        self.entries
            .sort_by(|left, right| left.place.cmp(&right.place));
    }

    /// The entries of `place`, in order.
    pub fn at<'a>(&'a self, place: &'a str) -> impl Iterator<Item = &'a VendorEntry> + 'a {
        self.entries
            .iter()
            .filter(move |entry| entry.place == place)
    }
}

/// The vendor data place of an object (`pou:NAME`, `gvl:NAME`, `type:NAME`), below which the
/// places of its parts are; `None` for kinds vendor data never names.
pub(crate) fn vendor_prefix(kind: ObjectKind, name: &str) -> Option<String> {
    let prefix = match kind {
        ObjectKind::Pou => "pou",
        ObjectKind::Gvl => "gvl",
        ObjectKind::DataType => "type",
        ObjectKind::CamTable | ObjectKind::Trace | ObjectKind::WatchList => return None,
    };
    Some(format!("{prefix}:{name}"))
}

/// True when the vendor data place `place` is `object` (a [`vendor_prefix`]) or one of its
/// parts; names compare without regard to case, as identifiers do.
pub(crate) fn is_place_of(place: &str, object: &str) -> bool {
    let Some(head) = place.get(..object.len()) else {
        return false;
    };
    head.eq_ignore_ascii_case(object)
        && (place.len() == object.len() || place[object.len()..].starts_with('/'))
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeSet;

    use super::*;
    use crate::{Project, VENDOR_DATA_FILE_NAME, load_project, save_project};

    fn with_vendor_data() -> Project {
        Project {
            name: "Imported".into(),
            vendor_data: VendorData {
                creation_date_time: Some("2016-10-24T18:09:22".into()),
                entries: vec![VendorEntry {
                    place: "pou:Main".into(),
                    xml: "<data name=\"http://www.3s-software.com/plcopenxml/objectid\" handleUnknown=\"discard\">\n  <ObjectId>832e</ObjectId>\n</data>".into(),
                    signature: None,
                }],
            },
            ..Project::default()
        }
    }

    #[test]
    fn vendor_data_is_saved_beside_the_manifest_and_loads_back() {
        let dir = tempfile::tempdir().unwrap();
        let project = with_vendor_data();
        let saved = save_project(&project, dir.path(), &BTreeSet::new()).unwrap();
        assert!(
            saved
                .files
                .contains(std::path::Path::new(VENDOR_DATA_FILE_NAME))
        );
        let loaded = load_project(dir.path()).unwrap();
        assert_eq!(loaded.project, project);
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    }

    #[test]
    fn a_project_without_vendor_data_has_no_file_and_loses_an_old_one() {
        let dir = tempfile::tempdir().unwrap();
        let saved = save_project(&with_vendor_data(), dir.path(), &BTreeSet::new()).unwrap();
        let emptied = Project {
            name: "Imported".into(),
            ..Project::default()
        };
        let second = save_project(&emptied, dir.path(), &saved.files).unwrap();
        assert_eq!(
            second.removed,
            vec![std::path::PathBuf::from(VENDOR_DATA_FILE_NAME)]
        );
        assert!(!dir.path().join(VENDOR_DATA_FILE_NAME).exists());
        assert_eq!(load_project(dir.path()).unwrap().project, emptied);
    }

    #[test]
    fn a_renamed_object_takes_its_entries_along_and_no_other() {
        let entry = |place: &str| VendorEntry {
            place: place.into(),
            xml: "<data/>".into(),
            signature: None,
        };
        let mut data = VendorData {
            creation_date_time: None,
            entries: vec![
                entry("pou:Main"),
                entry("pou:Main/body/element:3"),
                entry("pou:MainTwo"),
                entry("gvl:Main"),
            ],
        };
        data.rename_object(ObjectKind::Pou, "main", "Cycle");
        let places: Vec<&str> = data
            .entries
            .iter()
            .map(|entry| entry.place.as_str())
            .collect();
        assert_eq!(
            places,
            [
                "gvl:Main",
                "pou:Cycle",
                "pou:Cycle/body/element:3",
                "pou:MainTwo"
            ]
        );
    }

    #[test]
    fn renaming_onto_a_deleted_objects_name_detaches_its_entries() {
        let entry = |place: &str| VendorEntry {
            place: place.into(),
            xml: "<data/>".into(),
            signature: None,
        };
        // `pou:Old` is what a deleted POU left; `Cycle` is renamed to its name.
        let mut data = VendorData {
            creation_date_time: None,
            entries: vec![entry("pou:Cycle/interface"), entry("pou:Old/interface")],
        };
        data.rename_object(ObjectKind::Pou, "Cycle", "Old");
        let places: Vec<&str> = data
            .entries
            .iter()
            .map(|entry| entry.place.as_str())
            .collect();
        assert_eq!(places, ["detached:pou:Old/interface", "pou:Old/interface"]);
        // Back again: the renamed object's entries follow it; the detached ones stay.
        data.rename_object(ObjectKind::Pou, "Old", "Cycle");
        let places: Vec<&str> = data
            .entries
            .iter()
            .map(|entry| entry.place.as_str())
            .collect();
        assert_eq!(
            places,
            ["detached:pou:Old/interface", "pou:Cycle/interface"]
        );
    }

    #[test]
    fn renaming_a_list_by_an_edit_moves_its_entries_and_undo_moves_them_back() {
        let mut project = with_vendor_data();
        project
            .application
            .children
            .push(crate::Node::Object(crate::Object::Gvl(
                crate::GlobalVarList {
                    name: "Main".into(),
                    ..crate::GlobalVarList::default()
                },
            )));
        project.vendor_data.entries[0].place = "gvl:Main/variable:x".into();
        let before = project.vendor_data.clone();
        let inverse = crate::Edit::Tree(crate::TreeEdit::Rename {
            folder: Vec::new(),
            index: 0,
            name: "Cycle".into(),
        })
        .apply(&mut project)
        .unwrap();
        assert_eq!(project.vendor_data.entries[0].place, "gvl:Cycle/variable:x");
        inverse.apply(&mut project).unwrap();
        assert_eq!(project.vendor_data, before);
    }

    #[test]
    fn a_broken_vendor_data_file_is_an_error_naming_it() {
        let dir = tempfile::tempdir().unwrap();
        save_project(&with_vendor_data(), dir.path(), &BTreeSet::new()).unwrap();
        std::fs::write(dir.path().join(VENDOR_DATA_FILE_NAME), "entry = 3\n").unwrap();
        let error = load_project(dir.path()).unwrap_err();
        let text = error.to_string();
        assert!(text.contains(VENDOR_DATA_FILE_NAME), "{text}");
    }
}

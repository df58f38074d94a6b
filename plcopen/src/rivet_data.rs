//! Rivet's own data in `addData` (`docs/plcopen-xml.md` §5.4): what PLCopen cannot express, so a
//! project exported and imported again is the same project.
//!
//! Every entry is `<data name="https://rivet-plc.dev/plcopen/1/WHAT" handleUnknown="preserve">`
//! with one element of the namespace `https://rivet-plc.dev/plcopen/1` inside. The export writes
//! them and the import reads them; the texts inside are the TOML of the project's own files
//! (`docs/project-format.md`), so the two formats cannot drift apart.

use project_model::{Axis, Controller, Dialect, IoArea, ModbusDevice, SerialPort, Task};
use serde::{Deserialize, Serialize};

/// Rivet's namespace for its `addData` entries and their elements.
pub const RIVET_NAMESPACE: &str = "https://rivet-plc.dev/plcopen/1";

/// The entry of the project's `addData` holding [`ProjectEntry`].
pub(crate) const PROJECT_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/project";

/// The entry of an object (POU, data type, list; cams, traces and watch lists in the project's
/// `addData`) holding the object's file.
pub(crate) const OBJECT_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/object";

/// The entry of an LD or FBD body's `addData` delimiting its networks and holding their
/// titles, comments and labels: `<networks><network first="LOCALID" title comment label/>`.
pub(crate) const NETWORKS_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/networks";

/// The entry of an FBD body's `addData` saying it is a CFC chart: `<language name="CFC"/>`.
pub(crate) const LANGUAGE_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/language";

/// The entry of an FBD `AND` or `OR` box that the export writes for what the model has no box
/// for: `<gate of="series"/>` on the AND of a chain's operand with the chain before it (its
/// `IN1`) and `<gate of="parallel"/>` on the OR of a parallel group's branches, so the import
/// gives the chain and the group back rather than boxes (§5.2).
pub(crate) const GATE_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/gate";

/// The entry of a box first in a rung or an input's source whose first input has a source of
/// its own: `<source pin="IN"/>`, so the import gives that source back to the pin rather than as
/// the chain before the box, which the lowering treats as power (§5.2).
pub(crate) const SOURCE_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/source";

/// The entry of an SFC step's `addData` with what PLCopen has no attribute for:
/// `<step minTime maxTime entryAction mainAction exitAction comment/>`, empty ones left out.
pub(crate) const STEP_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/step";

/// The entry of the project's `addData` holding another tool's entry whose place the export does
/// not write (a POU Rivet did not convert, for one): `<vendor place="…">` with the entry's XML
/// as text.
pub(crate) const VENDOR_ENTRY: &str = "https://rivet-plc.dev/plcopen/1/vendor";

/// What the project entry holds: the device tree, the dialect and the application tree, which
/// PLCopen has no place for (its tasks are also written as PLCopen tasks, but Rivet's carry a
/// watchdog and events PLCopen cannot say).
#[derive(Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct ProjectEntry {
    /// The project's name (also the content header's `name`).
    pub name: String,
    /// The project's description (also the content header's `Comment`).
    #[serde(default)]
    pub description: String,
    /// The dialect.
    #[serde(default)]
    pub dialect: Dialect,
    /// The controller.
    pub controller: Controller,
    /// The tasks, in order.
    #[serde(default, rename = "task")]
    pub tasks: Vec<Task>,
    /// The I/O areas.
    #[serde(default, rename = "io_area")]
    pub io_areas: Vec<IoArea>,
    /// The serial ports.
    #[serde(default, rename = "serial_port", skip_serializing_if = "Vec::is_empty")]
    pub serial_ports: Vec<SerialPort>,
    /// The Modbus devices.
    #[serde(default, rename = "modbus_device")]
    pub modbus_devices: Vec<ModbusDevice>,
    /// The axes.
    #[serde(default, rename = "axis")]
    pub axes: Vec<Axis>,
    /// The application tree in display order, depth first: folders and objects by name.
    #[serde(default, rename = "node")]
    pub nodes: Vec<TreeNode>,
}

/// One entry of the application tree.
#[derive(Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct TreeNode {
    /// The folder path the entry stands in (for a folder: its own path, its name last).
    #[serde(default)]
    pub folder: Vec<String>,
    /// The object's name; `None` for a folder.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub object: Option<String>,
}

/// The kind of an object entry, as its `kind` attribute says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ObjectEntryKind {
    /// `pou`.
    Pou,
    /// `type`.
    DataType,
    /// `gvl`.
    Gvl,
    /// `cam`.
    Cam,
    /// `trace`.
    Trace,
    /// `watch`.
    Watch,
}

impl ObjectEntryKind {
    /// The `kind` attribute.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Pou => "pou",
            Self::DataType => "type",
            Self::Gvl => "gvl",
            Self::Cam => "cam",
            Self::Trace => "trace",
            Self::Watch => "watch",
        }
    }

    /// The kind named by a `kind` attribute.
    pub fn parse(text: &str) -> Option<Self> {
        [
            Self::Pou,
            Self::DataType,
            Self::Gvl,
            Self::Cam,
            Self::Trace,
            Self::Watch,
        ]
        .into_iter()
        .find(|kind| kind.as_str() == text)
    }
}

/// An object entry as read back: its kind, name, TOML and the ST texts PLCopen has no place for
/// (property accessors), by the key `PROPERTY.get` or `PROPERTY.set`.
#[derive(Debug, PartialEq)]
pub(crate) struct ObjectEntry {
    /// The object's kind.
    pub kind: ObjectEntryKind,
    /// The object's name.
    pub name: String,
    /// The object's file, as TOML.
    pub toml: String,
    /// ST texts by key.
    pub st: Vec<(String, String)>,
}

/// Why one of Rivet's own entries cannot be read back (`docs/plcopen-xml.md` §5.4); the
/// import wraps it in [`crate::ImportErrorKind::RivetData`] at the entry's element.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RivetDataError {
    /// The entry's text is not well-formed XML on its own.
    #[error("{0}")]
    NotXml(#[from] roxmltree::Error),
    /// The `data` element holds no element.
    #[error("the entry holds no element")]
    NoElement,
    /// The `data` element holds another element than the one its name announces.
    #[error("expected a `{expected}` element of {RIVET_NAMESPACE}")]
    WrongElement {
        /// The local name the entry's kind needs (`object`, `project`, `vendor`).
        expected: &'static str,
    },
    /// A required attribute of the entry's element is missing.
    #[error("`{0}` is missing")]
    MissingAttribute(&'static str),
    /// An object entry's `kind` names no kind of object.
    #[error("`{0}` is not a kind of object")]
    UnknownKind(String),
    /// An `st` child without the `body` attribute that says which accessor it holds.
    #[error("an `st` without `body`")]
    StWithoutBody,
    /// A child of an object entry other than `toml` and `st`.
    #[error("unexpected element `{0}`")]
    UnexpectedElement(String),
    /// An object entry without its `toml` child.
    #[error("the `toml` element is missing")]
    MissingToml,
    /// The project entry's TOML does not describe a project's device tree and application tree.
    #[error("{0}")]
    ProjectToml(Box<toml::de::Error>),
    /// An object entry of another kind than the element it stands in.
    #[error("the entry is of a {found}, not of a {expected}")]
    WrongKind {
        /// The entry's `kind` attribute.
        found: &'static str,
        /// The kind the element it stands in needs.
        expected: &'static str,
    },
    /// An object entry whose TOML is not the file of an object of its kind.
    #[error("the {kind} '{name}': {source}")]
    ObjectToml {
        /// The entry's `kind` attribute.
        kind: &'static str,
        /// The object's name.
        name: String,
        /// What the TOML reader found (boxed: the TOML reader's error is large).
        source: Box<toml::de::Error>,
    },
    /// An entry of a POU, data type or variable list in the project's `addData`, where only
    /// cams, traces and watch lists stand.
    #[error("a {0} entry stands in the project's addData")]
    MisplacedObject(&'static str),
}

/// Reads the element of a Rivet entry from the entry's raw XML (`<data …>…</data>`): the
/// element's attributes, its text and its children's (name, key attribute, text).
pub(crate) fn parse_object_entry(xml: &str) -> Result<ObjectEntry, RivetDataError> {
    let document = roxmltree::Document::parse(xml)?;
    let element = rivet_element(&document, "object")?;
    let kind_text = element
        .attribute("kind")
        .ok_or(RivetDataError::MissingAttribute("kind"))?;
    let kind = ObjectEntryKind::parse(kind_text)
        .ok_or_else(|| RivetDataError::UnknownKind(kind_text.to_owned()))?;
    let name = element
        .attribute("name")
        .ok_or(RivetDataError::MissingAttribute("name"))?
        .to_owned();
    let mut toml = None;
    let mut st = Vec::new();
    for child in element.children().filter(|node| node.is_element()) {
        let text = child_text(child);
        match child.tag_name().name() {
            "toml" => toml = Some(text),
            "st" => {
                let key = child
                    .attribute("body")
                    .ok_or(RivetDataError::StWithoutBody)?;
                st.push((key.to_owned(), text));
            }
            other => return Err(RivetDataError::UnexpectedElement(other.to_owned())),
        }
    }
    Ok(ObjectEntry {
        kind,
        name,
        toml: toml.ok_or(RivetDataError::MissingToml)?,
        st,
    })
}

/// Reads the TOML of the project entry from its raw XML.
pub(crate) fn parse_project_entry(xml: &str) -> Result<ProjectEntry, RivetDataError> {
    let document = roxmltree::Document::parse(xml)?;
    let element = rivet_element(&document, "project")?;
    toml::from_str(&child_text(element))
        .map_err(|error| RivetDataError::ProjectToml(Box::new(error)))
}

/// Reads a vendor entry kept in a `…/vendor` entry: its place and XML.
pub(crate) fn parse_vendor_entry(xml: &str) -> Result<project_model::VendorEntry, RivetDataError> {
    let document = roxmltree::Document::parse(xml)?;
    let element = rivet_element(&document, "vendor")?;
    Ok(project_model::VendorEntry {
        place: element
            .attribute("place")
            .ok_or(RivetDataError::MissingAttribute("place"))?
            .to_owned(),
        xml: child_text(element),
        signature: element.attribute("signature").map(str::to_owned),
    })
}

/// The one element of Rivet's namespace named `name` inside an entry's `data` element.
fn rivet_element<'a, 'input>(
    document: &'a roxmltree::Document<'input>,
    name: &'static str,
) -> Result<roxmltree::Node<'a, 'input>, RivetDataError> {
    let element = document
        .root_element()
        .children()
        .find(|node| node.is_element())
        .ok_or(RivetDataError::NoElement)?;
    if element.tag_name().namespace() != Some(RIVET_NAMESPACE) || element.tag_name().name() != name
    {
        return Err(RivetDataError::WrongElement { expected: name });
    }
    Ok(element)
}

/// The text of an element: its text and CDATA nodes joined.
fn child_text(node: roxmltree::Node<'_, '_>) -> String {
    node.children()
        .filter(|child| child.is_text())
        .filter_map(|child| child.text())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{RivetDataError, parse_object_entry, parse_project_entry, parse_vendor_entry};

    /// An entry `<data>` holding `inner`, with Rivet's namespace bound to `r`.
    fn entry(inner: &str) -> String {
        format!(
            r#"<data name="n" handleUnknown="preserve" xmlns:r="https://rivet-plc.dev/plcopen/1">{inner}</data>"#
        )
    }

    #[track_caller]
    fn object_error(inner: &str) -> RivetDataError {
        match parse_object_entry(&entry(inner)) {
            Ok(parsed) => panic!("read: {parsed:?}"),
            Err(error) => error,
        }
    }

    #[test]
    fn an_object_entry_reads_its_kind_name_toml_and_accessors() {
        let parsed = parse_object_entry(&entry(
            r#"<r:object kind="pou" name="P"><r:toml>x = 1</r:toml><r:st body="V.get">V := 1;</r:st></r:object>"#,
        ));
        let parsed = parsed.unwrap_or_else(|error| panic!("{error}"));
        assert_eq!((parsed.name.as_str(), parsed.toml.as_str()), ("P", "x = 1"));
        assert_eq!(parsed.st, [("V.get".to_owned(), "V := 1;".to_owned())]);
    }

    #[test]
    fn each_fault_of_an_object_entry_has_its_kind_and_message() {
        let cases = [
            ("", RivetDataError::NoElement, "the entry holds no element"),
            (
                "<object/>",
                RivetDataError::WrongElement { expected: "object" },
                "expected a `object` element of https://rivet-plc.dev/plcopen/1",
            ),
            (
                r#"<r:object name="P"/>"#,
                RivetDataError::MissingAttribute("kind"),
                "`kind` is missing",
            ),
            (
                r#"<r:object kind="pou"/>"#,
                RivetDataError::MissingAttribute("name"),
                "`name` is missing",
            ),
            (
                r#"<r:object kind="macro" name="P"/>"#,
                RivetDataError::UnknownKind("macro".to_owned()),
                "`macro` is not a kind of object",
            ),
            (
                r#"<r:object kind="pou" name="P"><r:st/></r:object>"#,
                RivetDataError::StWithoutBody,
                "an `st` without `body`",
            ),
            (
                r#"<r:object kind="pou" name="P"><r:json/></r:object>"#,
                RivetDataError::UnexpectedElement("json".to_owned()),
                "unexpected element `json`",
            ),
            (
                r#"<r:object kind="pou" name="P"/>"#,
                RivetDataError::MissingToml,
                "the `toml` element is missing",
            ),
        ];
        for (inner, kind, message) in cases {
            let error = object_error(inner);
            assert_eq!(
                (&error, error.to_string().as_str()),
                (&kind, message),
                "{inner}"
            );
        }
    }

    #[test]
    fn xml_that_does_not_parse_and_toml_that_does_not_read_keep_their_readers_messages() {
        let error = object_error("<r:object>");
        assert!(matches!(error, RivetDataError::NotXml(_)), "{error:?}");
        let Err(error) = parse_project_entry(&entry("<r:project>name = </r:project>")) else {
            panic!("read")
        };
        assert!(matches!(error, RivetDataError::ProjectToml(_)), "{error:?}");
        assert!(error.to_string().contains("line 1"), "{error}");
        let Err(error) = parse_vendor_entry(&entry("<r:vendor/>")) else {
            panic!("read")
        };
        assert_eq!(error, RivetDataError::MissingAttribute("place"));
    }
}

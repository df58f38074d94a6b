//! The application part of the device tree: folders and the objects in them.

#[cfg(feature = "proptest")]
use proptest::prelude::any;

use crate::{CamTable, DataType, GlobalVarList, Pou, TraceConfig, WatchList};

/// A folder of the application tree. The application itself is the root folder, whose name is
/// not used.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
pub struct Folder {
    /// The folder's name; also its directory name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The folders and objects in it, in the order the device tree shows them.
    #[cfg_attr(
        feature = "proptest",
        proptest(strategy = "proptest::collection::vec(any::<Node>(), 0..4)")
    )]
    pub children: Vec<Node>,
}

/// An entry of a folder.
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)] // Nodes live in a tree, built once per load; no hot arrays.
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
pub enum Node {
    /// A sub-folder.
    Folder(
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::leaf_folder()"))] Folder,
    ),
    /// An object.
    Object(Object),
}

/// An object of the application, each stored in a file of its own.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[allow(clippy::large_enum_variant)] // Objects live in a tree, not in hot arrays.
pub enum Object {
    /// A program, function block, function or interface.
    Pou(Pou),
    /// A global variable list.
    Gvl(GlobalVarList),
    /// A user-defined data type.
    DataType(DataType),
    /// A cam table.
    CamTable(CamTable),
    /// A trace configuration.
    Trace(TraceConfig),
    /// A watch list.
    WatchList(WatchList),
}

/// The kinds of application objects, which decide file extensions and icons.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ObjectKind {
    /// POU, `*.pou.toml`.
    Pou,
    /// Global variable list, `*.gvl.toml`.
    Gvl,
    /// Data type, `*.type.toml`.
    DataType,
    /// Cam table, `*.cam.toml`.
    CamTable,
    /// Trace, `*.trace.toml`.
    Trace,
    /// Watch list, `*.watch.toml`.
    WatchList,
}

impl ObjectKind {
    /// Every kind, in the order the loader tries their file suffixes.
    pub const ALL: [Self; 6] = [
        Self::Pou,
        Self::Gvl,
        Self::DataType,
        Self::CamTable,
        Self::Trace,
        Self::WatchList,
    ];

    /// The file name suffix of objects of this kind, such as `.pou.toml`.
    pub fn file_suffix(self) -> &'static str {
        match self {
            Self::Pou => ".pou.toml",
            Self::Gvl => ".gvl.toml",
            Self::DataType => ".type.toml",
            Self::CamTable => ".cam.toml",
            Self::Trace => ".trace.toml",
            Self::WatchList => ".watch.toml",
        }
    }
}

impl Object {
    /// The object's name, unique across the application.
    pub fn name(&self) -> &str {
        match self {
            Self::Pou(pou) => &pou.name,
            Self::Gvl(gvl) => &gvl.name,
            Self::DataType(data_type) => &data_type.name,
            Self::CamTable(cam) => &cam.name,
            Self::Trace(trace) => &trace.name,
            Self::WatchList(watch) => &watch.name,
        }
    }

    /// Changes the object's name.
    pub fn set_name(&mut self, name: String) {
        match self {
            Self::Pou(pou) => pou.name = name,
            Self::Gvl(gvl) => gvl.name = name,
            Self::DataType(data_type) => data_type.name = name,
            Self::CamTable(cam) => cam.name = name,
            Self::Trace(trace) => trace.name = name,
            Self::WatchList(watch) => watch.name = name,
        }
    }

    /// The object's kind.
    pub fn kind(&self) -> ObjectKind {
        match self {
            Self::Pou(_) => ObjectKind::Pou,
            Self::Gvl(_) => ObjectKind::Gvl,
            Self::DataType(_) => ObjectKind::DataType,
            Self::CamTable(_) => ObjectKind::CamTable,
            Self::Trace(_) => ObjectKind::Trace,
            Self::WatchList(_) => ObjectKind::WatchList,
        }
    }
}

impl Node {
    /// The folder's or object's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Folder(folder) => &folder.name,
            Self::Object(object) => object.name(),
        }
    }
}

impl Folder {
    /// The sub-folder at `path` (folder names from this one down), if it exists.
    pub fn folder(&self, path: &[String]) -> Option<&Self> {
        let Some((first, rest)) = path.split_first() else {
            return Some(self);
        };
        self.children.iter().find_map(|node| match node {
            Node::Folder(child) if child.name == *first => child.folder(rest),
            _ => None,
        })
    }

    /// The sub-folder at `path`, mutably.
    pub fn folder_mut(&mut self, path: &[String]) -> Option<&mut Self> {
        let Some((first, rest)) = path.split_first() else {
            return Some(self);
        };
        self.children.iter_mut().find_map(|node| match node {
            Node::Folder(child) if child.name == *first => child.folder_mut(rest),
            _ => None,
        })
    }

    /// Every object in this folder and its sub-folders, depth first in tree order.
    pub fn objects(&self) -> Vec<&Object> {
        let mut found = Vec::new();
        self.collect_objects(&mut found);
        found
    }

    fn collect_objects<'a>(&'a self, found: &mut Vec<&'a Object>) {
        for node in &self.children {
            match node {
                Node::Folder(child) => child.collect_objects(found),
                Node::Object(object) => found.push(object),
            }
        }
    }

    /// The object named `name` (compared as IEC identifiers are), anywhere below this folder.
    pub fn object(&self, name: &str) -> Option<&Object> {
        self.objects()
            .into_iter()
            .find(|object| crate::same_identifier(object.name(), name))
    }

    /// The object named `name`, mutably.
    pub fn object_mut(&mut self, name: &str) -> Option<&mut Object> {
        self.children.iter_mut().find_map(|node| match node {
            Node::Folder(child) => child.object_mut(name),
            Node::Object(object) if crate::same_identifier(object.name(), name) => Some(object),
            Node::Object(_) => None,
        })
    }

    /// The folder path and index of the object named `name`.
    pub fn locate(&self, name: &str) -> Option<(Vec<String>, usize)> {
        for (index, node) in self.children.iter().enumerate() {
            match node {
                Node::Object(object) if crate::same_identifier(object.name(), name) => {
                    return Some((Vec::new(), index));
                }
                Node::Folder(child) => {
                    if let Some((mut path, found)) = child.locate(name) {
                        path.insert(0, child.name.clone());
                        return Some((path, found));
                    }
                }
                Node::Object(_) => {}
            }
        }
        None
    }
}

//! POUs, their actions, transitions and methods.

use crate::add_data::AddData;
use crate::body::Body;
use crate::interface::Interface;
use crate::text::FormattedText;

/// A program organisation unit (`pou`).
#[derive(Clone, Debug, PartialEq)]
pub struct Pou {
    /// `name`.
    pub name: String,
    /// `pouType`.
    pub pou_type: PouType,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `interface`, when present.
    pub interface: Option<Interface>,
    /// `actions/action` in order.
    pub actions: Vec<Action>,
    /// `transitions/transition` in order.
    pub transitions: Vec<Transition>,
    /// The `body` elements in order (the schema allows several; files hold one or none).
    pub bodies: Vec<Body>,
    /// CODESYS methods, read from `addData/data[…/method]/Method` (the entries also stay in
    /// `add_data`).
    pub methods: Vec<Method>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Where the POU was found.
    pub location: PouLocation,
    /// Line of the `pou` element (1-based).
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// `pouType`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PouType {
    /// `function`.
    Function,
    /// `functionBlock`.
    FunctionBlock,
    /// `program`.
    Program,
}

/// Where a POU stands in the document.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PouLocation {
    /// `types/pous`.
    Types,
    /// CODESYS: `configuration/resource/addData/data[…/pou]/pou`.
    Resource {
        /// The configuration's name.
        configuration: String,
        /// The resource's name.
        resource: String,
    },
}

/// `actions/action`.
#[derive(Clone, Debug, PartialEq)]
pub struct Action {
    /// `name`.
    pub name: String,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `body`.
    pub body: Body,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// `transitions/transition`: a named transition condition of an SFC.
#[derive(Clone, Debug, PartialEq)]
pub struct Transition {
    /// `name`.
    pub name: String,
    /// `globalId`.
    pub global_id: Option<String>,
    /// `body`.
    pub body: Body,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

/// A CODESYS method (`Method` inside a POU's `addData`).
#[derive(Clone, Debug, PartialEq)]
pub struct Method {
    /// `name`.
    pub name: String,
    /// `ObjectId`, CODESYS's identity of the object.
    pub object_id: Option<String>,
    /// `interface`.
    pub interface: Option<Interface>,
    /// The `body` elements.
    pub bodies: Vec<Body>,
    /// Vendor data of the method (access modifiers and the like).
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
}

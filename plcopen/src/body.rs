//! Bodies.

use crate::add_data::AddData;
use crate::body_object::BodyObject;
use crate::text::FormattedText;

/// `body`: the code of a POU, action, transition or inline SFC element.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// `WorksheetName`.
    pub worksheet_name: Option<String>,
    /// `globalId`.
    pub global_id: Option<String>,
    /// The language and its content.
    pub content: BodyContent,
    /// CODESYS CFC: the objects of `addData/data[…/cfc]/CFC`, in document order (the entry also
    /// stays in `add_data`, and `content` holds the empty ST CODESYS writes beside it).
    pub cfc: Option<Vec<BodyObject>>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the `body` element (1-based; for inline bodies, of the element that holds them).
    pub line: u32,
}

/// The language of a body and what it holds.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyContent {
    /// Structured Text.
    St(FormattedText),
    /// Instruction List.
    Il(FormattedText),
    /// FBD objects in document order.
    Fbd(Vec<BodyObject>),
    /// LD objects in document order (CODESYS's network order is this order).
    Ld(Vec<BodyObject>),
    /// SFC objects in document order.
    Sfc(Vec<BodyObject>),
}

impl BodyContent {
    /// The objects of a graphical body; empty for ST and IL.
    pub fn objects(&self) -> &[BodyObject] {
        match self {
            BodyContent::St(_) | BodyContent::Il(_) => &[],
            BodyContent::Fbd(objects) | BodyContent::Ld(objects) | BodyContent::Sfc(objects) => {
                objects
            }
        }
    }

    /// The element name of the language (`ST`, `IL`, `FBD`, `LD`, `SFC`).
    pub fn language(&self) -> &'static str {
        match self {
            BodyContent::St(_) => "ST",
            BodyContent::Il(_) => "IL",
            BodyContent::Fbd(_) => "FBD",
            BodyContent::Ld(_) => "LD",
            BodyContent::Sfc(_) => "SFC",
        }
    }
}

//! The file and content headers of a document.

use crate::add_data::AddData;
use crate::text::FormattedText;

/// A point or an offset in the document's coordinates (`position`, `relPosition`, `pageSize`,
/// `scaling`); the schema's `xsd:decimal`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Point {
    /// Horizontal coordinate.
    pub x: f64,
    /// Vertical coordinate.
    pub y: f64,
}

/// `fileHeader`: who wrote the file and when. Every value is kept as written (OpenPLC writes
/// `creationDateTime` without the `T` of `xsd:dateTime`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FileHeader {
    /// `companyName`.
    pub company_name: String,
    /// `companyURL`.
    pub company_url: Option<String>,
    /// `productName`.
    pub product_name: String,
    /// `productVersion`.
    pub product_version: String,
    /// `productRelease`.
    pub product_release: Option<String>,
    /// `creationDateTime`, as written.
    pub creation_date_time: String,
    /// `contentDescription`.
    pub content_description: Option<String>,
}

/// `contentHeader`: the project's name, version, authors and drawing grid.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ContentHeader {
    /// `name`.
    pub name: String,
    /// `version`.
    pub version: Option<String>,
    /// `modificationDateTime`, as written.
    pub modification_date_time: Option<String>,
    /// `organization`.
    pub organization: Option<String>,
    /// `author`.
    pub author: Option<String>,
    /// `language`.
    pub language: Option<String>,
    /// The `Comment` child.
    pub comment: Option<String>,
    /// The drawing grid.
    pub coordinate_info: CoordinateInfo,
    /// `addDataInfo` (which vendor extensions the file uses), as its raw XML text.
    pub add_data_info: Option<String>,
    /// Vendor data of the header.
    pub add_data: AddData,
    /// Documentation, where a vendor wrote one.
    pub documentation: Option<FormattedText>,
}

/// `coordinateInfo`: the page size and the scaling of each graphical language.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CoordinateInfo {
    /// `pageSize`, when given.
    pub page_size: Option<Point>,
    /// `fbd/scaling`.
    pub fbd_scaling: Point,
    /// `ld/scaling`.
    pub ld_scaling: Point,
    /// `sfc/scaling`.
    pub sfc_scaling: Point,
}

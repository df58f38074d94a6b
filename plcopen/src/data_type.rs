//! Data types and values.

use crate::add_data::AddData;
use crate::interface::Variable;
use crate::text::FormattedText;

/// A named type of `types/dataTypes`.
#[derive(Clone, Debug, PartialEq)]
pub struct DataTypeDecl {
    /// `name`.
    pub name: String,
    /// `baseType`: what the type is.
    pub base_type: DataType,
    /// `initialValue`.
    pub initial_value: Option<Value>,
    /// Vendor data.
    pub add_data: AddData,
    /// Documentation.
    pub documentation: Option<FormattedText>,
    /// Line of the `dataType` element (1-based), for the conversion's messages.
    pub line: u32,
    /// Column of the element's `<` (1-based, in characters), for the conversion's messages.
    pub column: u32,
}

/// The type grammar of the schema (`dataType`).
#[derive(Clone, Debug, PartialEq)]
pub enum DataType {
    /// An elementary or generic type written as an empty element, by its element name (`BOOL`,
    /// `LREAL`, `TOD`, `ANY_NUM`, and CODESYS's `LTIME`, …).
    Elementary(String),
    /// `string` (`wide` false) or `wstring` (`wide` true) with its optional `length`.
    String {
        /// True for `wstring`.
        wide: bool,
        /// `length`, as written (a number or a constant's name).
        length: Option<String>,
    },
    /// `array` with its dimensions and element type.
    Array {
        /// `dimension` elements in order.
        dimensions: Vec<Dimension>,
        /// `baseType`.
        base: Box<DataType>,
    },
    /// `derived@name`: a user type or a function block type.
    Derived {
        /// `name`.
        name: String,
    },
    /// `enum` with its values and optional base type.
    Enum {
        /// `values/value` in order.
        values: Vec<EnumValue>,
        /// `baseType`, when given.
        base: Option<Box<DataType>>,
    },
    /// `struct`: its members, read as variables.
    Struct {
        /// The members in order.
        members: Vec<Variable>,
    },
    /// `subrangeSigned` or `subrangeUnsigned`.
    Subrange {
        /// True for `subrangeSigned`.
        signed: bool,
        /// `range@lower`.
        lower: String,
        /// `range@upper`.
        upper: String,
        /// `baseType`.
        base: Box<DataType>,
    },
    /// `pointer` (an extension of the schema) to its base type.
    Pointer {
        /// `baseType`.
        base: Box<DataType>,
    },
}

/// One `dimension` of an array. The bounds are kept as written: the schema says integers, but
/// exporters also write constants' names, which only the conversion can resolve.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dimension {
    /// `lower`.
    pub lower: String,
    /// `upper`.
    pub upper: String,
}

/// One value of an enumeration.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EnumValue {
    /// `name`.
    pub name: String,
    /// `value`, when the enumeration gives numbers.
    pub value: Option<String>,
}

/// An initial value (`value` of the schema).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Value {
    /// `simpleValue@value`, an IEC literal as written.
    Simple(String),
    /// `arrayValue/value*`, each with its optional `repetitionValue`.
    Array(Vec<ValueItem>),
    /// `structValue/value*`, each with its `member`.
    Struct(Vec<ValueItem>),
}

/// One element of an array or structure value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ValueItem {
    /// `repetitionValue` (arrays) or `member` (structures).
    pub key: Option<String>,
    /// The value.
    pub value: Value,
}

//! User-defined data types (DUTs).

use serde::{Deserialize, Serialize};

/// One user-defined data type, stored in a file of its own as CODESYS stores a DUT.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct DataType {
    /// The type's name; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// What the type is for.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The definition.
    pub definition: TypeDefinition,
}

/// What a data type is.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum TypeDefinition {
    /// `STRUCT … END_STRUCT`, optionally extending another structure.
    Struct {
        /// The structure it extends, if any.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        #[cfg_attr(
            feature = "proptest",
            proptest(strategy = "proptest::option::of(crate::arb::ident())")
        )]
        extends: Option<String>,
        /// The members in declaration order.
        #[serde(default, rename = "member", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
        members: Vec<StructMember>,
    },
    /// `UNION … END_UNION`: members share their memory.
    Union {
        /// The members in declaration order.
        #[serde(default, rename = "member", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
        members: Vec<StructMember>,
    },
    /// An enumeration `(Red := 1, Green, Blue) DINT`.
    Enum {
        /// The base type as written, if not the default `INT`.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        #[cfg_attr(
            feature = "proptest",
            proptest(strategy = "proptest::option::of(crate::arb::ident())")
        )]
        base: Option<String>,
        /// The values in declaration order.
        #[serde(default, rename = "value", skip_serializing_if = "Vec::is_empty")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
        values: Vec<EnumValue>,
    },
    /// An alias, subrange or array type written as a type expression, such as
    /// `INT(0..100)` or `ARRAY[1..8] OF BOOL`.
    Alias {
        /// The type expression as written.
        #[serde(rename = "type")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
        ty: String,
        /// The initial value as written, if any.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
        initial: Option<String>,
    },
}

/// A member of a structure or union.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct StructMember {
    /// The member's name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The type as written.
    #[serde(rename = "type")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub ty: String,
    /// The initial value as written, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub initial: Option<String>,
    /// The comment beside the member.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

/// One value of an enumeration.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct EnumValue {
    /// The value's name.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The explicit value as written (`1`, `16#FF`), if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub value: Option<String>,
    /// The comment beside the value.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

//! Global variable lists.

use serde::{Deserialize, Serialize};

use crate::Variable;

/// A global variable list (GVL): variables visible to every POU of the application.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct GlobalVarList {
    /// The list's name; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// What the list is for.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
    /// The variables, in declaration order; their section is `VAR_GLOBAL` or `VAR_CONFIG`.
    #[serde(default, rename = "variable", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub variables: Vec<Variable>,
}

//! Watch lists: variables a user wants to see together while online.

use serde::{Deserialize, Serialize};

/// A watch list object of the application.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct WatchList {
    /// The list's name; it is the file name, not stored in the file.
    #[serde(skip)]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub name: String,
    /// The watched expressions in display order.
    #[serde(default, rename = "entry", skip_serializing_if = "Vec::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::small_vec()"))]
    pub entries: Vec<WatchEntry>,
}

/// One line of a watch list.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "proptest", derive(proptest_derive::Arbitrary))]
#[serde(deny_unknown_fields)]
pub struct WatchEntry {
    /// The variable's path, such as `Main.aValues[3]` or `Main.fbConveyor.xRunning`.
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::ident()"))]
    pub path: String,
    /// A prepared value kept with the list, as written.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::opt_text()"))]
    pub prepared_value: Option<String>,
    /// A note shown beside the value.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    #[cfg_attr(feature = "proptest", proptest(strategy = "crate::arb::text()"))]
    pub comment: String,
}

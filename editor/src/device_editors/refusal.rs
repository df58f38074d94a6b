//! Why a device editor refused a value, kept typed until it is drawn, so the app can say it in
//! the user's language.

use std::fmt;
use std::sync::Arc;

use compiler::ide::{AddressError, ChannelBindingError, ChannelVariableError};
use project_model::DeviceProblem;
use thiserror::Error;

/// Why a value given to a device editor's field was refused; its `Display` is the English
/// reason, and [`RefusalWords`] turns it into the user's language.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum Refusal {
    /// The changed node would have a problem the current one does not have.
    #[error(transparent)]
    Problem(#[from] DeviceProblem),
    /// The text is not a direct address.
    #[error(transparent)]
    Address(#[from] AddressError),
    /// The variable cannot be bound to the channel.
    #[error(transparent)]
    ChannelVariable(#[from] ChannelVariableError),
    /// The variable cannot be a channel's of the runtime master: it has no place the runtime
    /// copies, or does not fit the data type and count (the build's E0140 and E0141).
    #[error(transparent)]
    ChannelBinding(#[from] ChannelBindingError),
    /// A coil or discrete input range that does not start at bit 0 of a byte.
    #[error(
        "a coil or discrete input range starts at bit 0 of a byte, such as %QX4.0, not {address}"
    )]
    BitTableAddress {
        /// The address given.
        address: String,
    },
    /// A register range that does not start at a W, D or L address.
    #[error("a register range starts at a W, D or L address, such as %MW0, not {address}")]
    RegisterTableAddress {
        /// The address given.
        address: String,
    },
    /// A device switched to Modbus RTU in a project with no serial port to put it on.
    #[error("add a serial port under the controller first")]
    NoSerialPorts,
    /// A text that is not a finite number.
    #[error("'{text}' is not a number")]
    NotANumber {
        /// The text given.
        text: String,
    },
    /// A text that is not a whole number in the field's range.
    #[error("'{text}' is not a whole number from {min} to {max}")]
    NotAWholeNumber {
        /// The text given.
        text: String,
        /// The smallest value the field takes, written out.
        min: String,
        /// The largest value the field takes, written out.
        max: String,
    },
}

/// Turns a [`Refusal`] into words in the user's language; the app fills it, and `Default` says
/// the English reason. Lives as long as the [`DeviceTexts`](super::DeviceTexts) holding it.
#[derive(Clone)]
pub struct RefusalWords(Arc<dyn Fn(&Refusal) -> String + Send + Sync>);

impl RefusalWords {
    /// Words made by `describe`.
    pub fn new(describe: impl Fn(&Refusal) -> String + Send + Sync + 'static) -> Self {
        Self(Arc::new(describe))
    }

    /// The reason `refusal` gives, in the user's language.
    pub fn describe(&self, refusal: &Refusal) -> String {
        (self.0)(refusal)
    }
}

impl Default for RefusalWords {
    fn default() -> Self {
        Self::new(Refusal::to_string)
    }
}

impl fmt::Debug for RefusalWords {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("RefusalWords")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_words_are_the_english_reason_and_an_app_may_give_its_own() {
        let refusal = Refusal::NotANumber {
            text: "fast".into(),
        };
        assert_eq!(
            RefusalWords::default().describe(&refusal),
            "'fast' is not a number"
        );
        let words = RefusalWords::new(|refusal| format!("<{refusal}>"));
        assert_eq!(words.describe(&refusal), "<'fast' is not a number>");
    }
}

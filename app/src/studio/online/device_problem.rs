//! Why the studio could not use one of the project's Modbus devices it polls itself: nothing
//! polls it, its queue is full, or it cannot be reached. Shown in the interface language.

use thiserror::Error;

use crate::studio::i18n::{Language, Text};

/// Why a device polled by the studio cannot be read, written or traced now.
#[derive(Debug, Error)]
pub enum DeviceProblem {
    /// Nothing polls the device, so it cannot be written or traced.
    #[error("{}", Text::DeviceNotPolled.fill(*language, &[("device", device)]))]
    NotPolled {
        /// The device's name.
        device: String,
        /// The language the text is shown in.
        language: Language,
    },
    /// The device's queue of commands is full.
    #[error("{}", Text::DeviceBusy.fill(*language, &[("device", device)]))]
    Busy {
        /// The device's name.
        device: String,
        /// The language the text is shown in.
        language: Language,
    },
    /// The device cannot be reached or refused something; its task tries again.
    #[error("{device}: {problem}")]
    Unreachable {
        /// The device's name.
        device: String,
        /// What its task last reported, already in the interface language.
        problem: String,
    },
}

//! Why the device tree refuses an action, kept typed until it is shown in the interface
//! language.

use project_model::EditError;

use crate::studio::error_texts::edit_error_text;
use crate::studio::i18n::{Language, RefusalText};

/// Why a device tree action or a dialog entry cannot be carried out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refusal {
    /// The project model refuses it: a missing object, an invalid or taken name, ….
    Edit(EditError),
    /// The name field is empty.
    EmptyName,
    /// The name is a keyword of IEC 61131-3.
    Keyword(String),
    /// A new function has no return type.
    NoReturnType,
    /// A new property has no type.
    NoPropertyType,
    /// The POU (named here) is neither a program nor a function block, so it takes no
    /// methods, actions, transitions or properties.
    NoMembers(String),
    /// An SFC chart was chosen for a function or a member: only the body of a program or
    /// function block itself can be one.
    SfcNotHere,
    /// The serial port (named first) cannot be deleted while the Modbus devices named next
    /// are on it: deleting it would leave them naming a port the project lacks.
    SerialPortInUse(String, Vec<String>),
}

impl Refusal {
    /// The refusal as the user reads it, in `language`.
    pub fn text(&self, language: Language) -> String {
        match self {
            Self::Edit(error) => edit_error_text(error, language),
            Self::EmptyName => RefusalText::RefuseEmptyName.get(language).to_owned(),
            Self::Keyword(name) => RefusalText::RefuseKeyword.fill(language, &[("name", name)]),
            Self::NoReturnType => RefusalText::RefuseNoReturnType.get(language).to_owned(),
            Self::NoPropertyType => RefusalText::RefuseNoPropertyType.get(language).to_owned(),
            Self::NoMembers(pou) => RefusalText::RefuseNoMembers.fill(language, &[("pou", pou)]),
            Self::SfcNotHere => RefusalText::RefuseSfcNotHere.get(language).to_owned(),
            Self::SerialPortInUse(port, devices) => {
                // Chinese lists its items with the enumeration comma, English with commas.
                let separator = match language {
                    Language::English => ", ",
                    Language::SimplifiedChinese => "、",
                };
                RefusalText::RefuseSerialPortInUse.fill(
                    language,
                    &[("port", port), ("devices", &devices.join(separator))],
                )
            }
        }
    }
}

impl From<EditError> for Refusal {
    fn from(error: EditError) -> Self {
        Self::Edit(error)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refusals_read_in_english_and_chinese() {
        let keyword = Refusal::Keyword("if".to_owned());
        assert_eq!(
            keyword.text(Language::English),
            "'if' is a keyword of IEC 61131-3 and cannot name anything"
        );
        assert!(keyword.text(Language::SimplifiedChinese).contains("关键字"));
        let taken = Refusal::from(EditError::DuplicateName("Main".to_owned()));
        assert_eq!(
            taken.text(Language::English),
            "the name 'Main' is already used"
        );
        assert_eq!(
            taken.text(Language::SimplifiedChinese),
            "名称“Main”已被使用"
        );
        let in_use = Refusal::SerialPortInUse(
            "RS485".to_owned(),
            vec!["Drive".to_owned(), "Meter".to_owned()],
        );
        assert_eq!(
            in_use.text(Language::English),
            "the serial port 'RS485' is used by Drive, Meter: move them to another port or delete them first"
        );
        assert_eq!(
            in_use.text(Language::SimplifiedChinese),
            "串口“RS485”正被 Drive、Meter 使用：请先将这些设备移到其他串口或删除"
        );
    }
}

//! The words of File ▸ Export PLCopen XML… (its menu item, its file dialog and what the status
//! bar says), in English and Simplified Chinese: an enum of its own beside [`super::Text`], so
//! each stays one exhaustive `match` of a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the PLCopen export. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum ExportText {
    MenuItem,
    PickFile,
    Exported,
    ExportedUnsaved,
    Failed,
    ObjectsMissing,
}

impl ExportText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::MenuItem => ("Export PLCopen XML…", "导出 PLCopen XML…"),
            Self::PickFile => (
                "Export the project as a PLCopen XML file",
                "将项目导出为 PLCopen XML 文件",
            ),
            Self::Exported => (
                "Exported {file}: {objects} objects",
                "已导出 {file}：{objects} 个对象",
            ),
            Self::ExportedUnsaved => (
                "Exported {file}: {objects} objects, unsaved changes included",
                "已导出 {file}：{objects} 个对象，包括未保存的更改",
            ),
            Self::Failed => ("PLCopen export failed", "PLCopen 导出失败"),
            Self::ObjectsMissing => (
                "{count} objects could not be loaded and would be missing from the export; fix their files first",
                "有 {count} 个对象无法加载，导出中将缺少它们；请先修复其文件",
            ),
        };
        match language {
            Language::English => english,
            Language::SimplifiedChinese => chinese,
        }
    }

    /// The text in `language` with its `{key}` placeholders filled from `values`.
    pub fn fill(self, language: Language, values: &[(&str, &str)]) -> String {
        fill_template(self.get(language), values)
    }
}

//! The words of File ▸ Import PLCopen XML… (its menu item, file dialogs and the preview
//! dialog), in English and Simplified Chinese: an enum of its own beside [`super::Text`], so
//! each stays one exhaustive `match` of a readable length.

use super::language::Language;
use super::template::fill_template;

/// Every word of the PLCopen import. Adding a variant forces a translation for each language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)] // Each variant's English text says what it is.
pub enum ImportText {
    // The menu and the file dialogs.
    MenuItem,
    PickFile,
    FileFilter,
    PickFolder,
    // The dialog's summary of the file.
    Title,
    Source,
    UnnamedTool,
    Counts,
    // The report.
    ReportHeading,
    ReportCounts,
    Converted,
    Kept,
    NotConverted,
    // The plan against the open project.
    PlanHeading,
    NoProject,
    Added,
    NothingAdded,
    Clashes,
    ClashesWith,
    Skip,
    Replace,
    KeptFromProject,
    // What the plan names.
    KindPou,
    KindGvl,
    KindDataType,
    KindCam,
    KindTrace,
    KindWatchList,
    ItemTask,
    ItemCall,
    PartProjectInfo,
    PartController,
    PartDialect,
    PartIoAreas,
    PartSerialPorts,
    PartModbusDevices,
    PartAxes,
    // The buttons and what they lead to.
    IntoProject,
    AsNewProject,
    Failed,
    UndoLabel,
    ImportedInto,
    NewProjectFailed,
    FolderNotEmpty,
}

impl ImportText {
    /// The text in `language`.
    pub fn get(self, language: Language) -> &'static str {
        let (english, chinese) = match self {
            Self::MenuItem => ("Import PLCopen XML…", "导入 PLCopen XML…"),
            Self::PickFile => ("Choose a PLCopen XML file", "选择 PLCopen XML 文件"),
            Self::FileFilter => ("PLCopen XML", "PLCopen XML 文件"),
            Self::PickFolder => (
                "Choose an empty folder for the new project",
                "为新项目选择一个空文件夹",
            ),
            Self::Title => ("Import PLCopen XML", "导入 PLCopen XML"),
            Self::Source => (
                "{format}, written by {product}",
                "{format}，由 {product} 生成",
            ),
            Self::UnnamedTool => ("an unnamed tool", "未具名的工具"),
            Self::Counts => (
                "{types} data types, {pous} POUs, {configurations} configurations, {tasks} tasks",
                "{types} 个数据类型，{pous} 个 POU，{configurations} 个配置，{tasks} 个任务",
            ),
            Self::ReportHeading => ("Import report", "导入报告"),
            Self::ReportCounts => (
                "{converted} converted, {kept} kept for the export, {not} not converted",
                "{converted} 项已转换，{kept} 项保留以供导出，{not} 项未转换",
            ),
            Self::Converted => ("converted", "已转换"),
            Self::Kept => ("kept", "已保留"),
            Self::NotConverted => ("not converted", "未转换"),
            Self::PlanHeading => ("Into this project", "导入到当前项目"),
            Self::NoProject => (
                "No project is open: import as a new project",
                "未打开项目：请作为新项目导入",
            ),
            Self::Added => ("Will be added ({count})", "将添加（{count}）"),
            Self::NothingAdded => ("Nothing new will be added", "没有新内容需要添加"),
            Self::Clashes => ("Clashes ({count})", "冲突（{count}）"),
            Self::ClashesWith => ("clashes with {existing}", "与 {existing} 冲突"),
            Self::Skip => ("Skip", "跳过"),
            Self::Replace => ("Replace", "替换"),
            Self::KeptFromProject => (
                "This project keeps its own: {parts}",
                "当前项目保留自身的：{parts}",
            ),
            Self::KindPou => ("POU", "POU"),
            Self::KindGvl => ("global variable list", "全局变量表"),
            Self::KindDataType => ("data type", "数据类型"),
            Self::KindCam => ("cam table", "凸轮表"),
            Self::KindTrace => ("trace", "跟踪"),
            Self::KindWatchList => ("watch list", "监视列表"),
            Self::ItemTask => ("task {name}", "任务 {name}"),
            Self::ItemCall => (
                "call of {program} by task {task}",
                "任务 {task} 对 {program} 的调用",
            ),
            Self::PartProjectInfo => ("name and description", "名称和描述"),
            Self::PartController => ("controller", "控制器"),
            Self::PartDialect => ("language dialect", "语言方言"),
            Self::PartIoAreas => ("I/O areas", "输入/输出区"),
            Self::PartSerialPorts => ("serial ports", "串口"),
            Self::PartModbusDevices => ("Modbus devices", "Modbus 设备"),
            Self::PartAxes => ("axes", "轴"),
            Self::IntoProject => ("Import into this project", "导入到当前项目"),
            Self::AsNewProject => ("Import as new project…", "作为新项目导入…"),
            Self::Failed => (
                "The file cannot be imported; nothing was changed:",
                "无法导入该文件；未做任何更改：",
            ),
            Self::UndoLabel => ("Import {file}", "导入 {file}"),
            Self::ImportedInto => (
                "Imported {file}: {added} added, {replaced} replaced, {skipped} skipped",
                "已导入 {file}：添加 {added} 项，替换 {replaced} 项，跳过 {skipped} 项",
            ),
            Self::NewProjectFailed => ("The new project was not written", "新项目未写入"),
            Self::FolderNotEmpty => (
                "{folder}: the folder is not empty; nothing was written",
                "{folder}：文件夹不是空的；未写入任何内容",
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

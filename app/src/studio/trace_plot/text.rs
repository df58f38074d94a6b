//! The plot views' interface text in English and Simplified Chinese.
//!
//! It lives beside the views rather than in `studio::Text` so the views stay self-contained;
//! the two can be merged when the views are wired into the studio.

use crate::studio::i18n::Language;

/// Every piece of text the trace and cycle-time views show.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PlotText {
    OneAxis,
    OnePlotPerSignal,
    ResetView,
    ClearCursors,
    ExportCsv,
    ExportPng,
    NoSamples,
    NoSamplesHint,
    CursorHint,
    Samples,
    CycleTime,
    TracePlot,
    TimeMs,
    Trigger,
    CursorA,
    CursorB,
    Variable,
    AtA,
    AtB,
    Difference,
    DeltaT,
    Task,
    LastUs,
    MinUs,
    AverageUs,
    MaxUs,
    JitterUs,
    Cycles,
    TimeS,
    CycleTimeUs,
    CyclePlot,
    NoStatistics,
}

impl PlotText {
    /// The text in `language`.
    pub(crate) fn get(self, language: Language) -> &'static str {
        let chinese = language == Language::SimplifiedChinese;
        let (english, simplified) = match self {
            Self::OneAxis => ("One y-axis", "单一 Y 轴"),
            Self::OnePlotPerSignal => ("One plot per signal", "每个信号一个图"),
            Self::ResetView => ("Reset view", "重置视图"),
            Self::ClearCursors => ("Clear cursors", "清除光标"),
            Self::ExportCsv => ("Export CSV…", "导出 CSV…"),
            Self::ExportPng => ("Export PNG…", "导出 PNG…"),
            Self::NoSamples => ("No samples yet", "尚无采样"),
            Self::NoSamplesHint => (
                "Configure a trace (variables, task, trigger), log in and start it; the samples appear here when they are uploaded",
                "配置跟踪（变量、任务、触发），登录并启动；上传后采样将显示在这里",
            ),
            Self::CursorHint => (
                "Click places cursor A, Shift+click places cursor B",
                "单击放置光标 A，Shift+单击放置光标 B",
            ),
            Self::Samples => ("samples", "个采样"),
            Self::CycleTime => ("cycle", "周期"),
            Self::TracePlot => ("Trace plot", "跟踪曲线"),
            Self::TimeMs => ("Time (ms)", "时间 (ms)"),
            Self::Trigger => ("Trigger", "触发"),
            Self::CursorA => ("Cursor A", "光标 A"),
            Self::CursorB => ("Cursor B", "光标 B"),
            Self::Variable => ("Variable", "变量"),
            Self::AtA => ("At A", "A 处"),
            Self::AtB => ("At B", "B 处"),
            Self::Difference => ("B − A", "B − A"),
            Self::DeltaT => ("Δt (ms)", "Δt (ms)"),
            Self::Task => ("Task", "任务"),
            Self::LastUs => ("Last (µs)", "最近 (µs)"),
            Self::MinUs => ("Min (µs)", "最小 (µs)"),
            Self::AverageUs => ("Average (µs)", "平均 (µs)"),
            Self::MaxUs => ("Max (µs)", "最大 (µs)"),
            Self::JitterUs => ("Jitter (µs)", "抖动 (µs)"),
            Self::Cycles => ("Cycles", "周期数"),
            Self::TimeS => ("Time (s)", "时间 (s)"),
            Self::CycleTimeUs => ("Cycle time (µs)", "周期时间 (µs)"),
            Self::CyclePlot => ("Task cycle times", "任务周期时间"),
            Self::NoStatistics => (
                "No task statistics yet: log in to a running controller",
                "尚无任务统计：请登录到正在运行的控制器",
            ),
        };
        if chinese { simplified } else { english }
    }
}

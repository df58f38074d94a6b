//! The task cycle-time statistics: a plot of each task's last cycle time over the last minutes
//! and a table of the current figures.

use std::collections::{BTreeMap, VecDeque};

use egui::{Role, Ui, WidgetInfo};
use egui_plot::{Legend, Line, Plot};

use crate::studio::i18n::Language;
use crate::studio::trace_plot::text::PlotText;

/// How many points each task keeps: ten minutes at the studio's polling rate of one per second.
pub const CYCLE_HISTORY_POINTS: usize = 600;

/// The recent cycle-time statistics of every task of the connected runtime. It lives as long as
/// the online session and is not saved.
#[derive(Clone, Debug, Default)]
pub struct CycleHistory {
    /// Per task name, in name order so the legend and table do not reorder between polls.
    tasks: BTreeMap<String, TaskHistory>,
}

/// One poll of one task's statistics, in microseconds for the plot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CyclePoint {
    /// When the statistics were read, in seconds since the session started.
    pub time_s: f64,
    /// The last cycle's duration.
    pub last_us: f64,
    /// The average cycle duration since the statistics were reset.
    pub average_us: f64,
    /// The longest cycle since the statistics were reset.
    pub max_us: f64,
}

/// The figures of the latest poll of one task, as the table shows them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CycleFigures {
    /// The last cycle's duration in nanoseconds.
    pub last_ns: u64,
    /// The average cycle duration in nanoseconds.
    pub average_ns: u64,
    /// The longest cycle in nanoseconds.
    pub max_ns: u64,
    /// The shortest cycle in nanoseconds.
    pub min_ns: u64,
    /// The start jitter in nanoseconds.
    pub jitter_ns: u64,
    /// Cycles run.
    pub cycles: u64,
}

/// One task's bounded history and latest figures.
#[derive(Clone, Debug, Default)]
struct TaskHistory {
    /// The last [`CYCLE_HISTORY_POINTS`] polls, oldest first.
    points: VecDeque<CyclePoint>,
    /// The latest poll.
    latest: CycleFigures,
}

impl CycleHistory {
    /// Records one poll of task `task` taken at `at_s` seconds; the oldest point goes when the
    /// task already holds [`CYCLE_HISTORY_POINTS`].
    #[expect(
        clippy::too_many_arguments,
        reason = "the figures arrive one by one from the runtime's statistics"
    )]
    pub fn push(
        &mut self,
        task: &str,
        at_s: f64,
        last_ns: u64,
        average_ns: u64,
        max_ns: u64,
        min_ns: u64,
        jitter_ns: u64,
        cycles: u64,
    ) {
        let history = self.tasks.entry(task.to_owned()).or_default();
        if history.points.len() == CYCLE_HISTORY_POINTS {
            history.points.pop_front();
        }
        let us = |ns: u64| ns as f64 / 1000.0;
        history.points.push_back(CyclePoint {
            time_s: at_s,
            last_us: us(last_ns),
            average_us: us(average_ns),
            max_us: us(max_ns),
        });
        history.latest = CycleFigures {
            last_ns,
            average_ns,
            max_ns,
            min_ns,
            jitter_ns,
            cycles,
        };
    }

    /// Forgets every task, as when the studio logs out or connects to another runtime.
    pub fn clear(&mut self) {
        self.tasks.clear();
    }

    /// Whether no poll has been recorded.
    pub fn is_empty(&self) -> bool {
        self.tasks.is_empty()
    }

    /// The task names, in the order the plot and table list them.
    pub fn task_names(&self) -> impl Iterator<Item = &str> {
        self.tasks.keys().map(String::as_str)
    }

    /// The recorded points of `task`, oldest first.
    pub fn points(&self, task: &str) -> impl Iterator<Item = &CyclePoint> {
        self.tasks
            .get(task)
            .into_iter()
            .flat_map(|history| &history.points)
    }

    /// The latest figures of `task`.
    pub fn latest(&self, task: &str) -> Option<CycleFigures> {
        self.tasks.get(task).map(|history| history.latest)
    }
}

/// Draws one line per task (its last cycle time over time) and a table of each task's current
/// figures under it.
pub fn cycle_plot_ui(ui: &mut Ui, history: &CycleHistory, language: Language) {
    if history.is_empty() {
        ui.vertical_centered(|ui| {
            ui.add_space(ui.available_height() * 0.3);
            ui.label(PlotText::NoStatistics.get(language));
        });
        return;
    }
    let row_height = ui.spacing().interact_size.y;
    let table_height = (history.tasks.len() + 1) as f32 * row_height;
    let plot_height = (ui.available_height() - table_height - row_height).max(120.0);
    let response = Plot::new("cycle_time_plot")
        .height(plot_height)
        .legend(Legend::default().follow_insertion_order(true))
        .x_axis_label(PlotText::TimeS.get(language))
        .y_axis_label(PlotText::CycleTimeUs.get(language))
        .include_y(0.0)
        .show(ui, |plot_ui| {
            for (name, task) in &history.tasks {
                let points: Vec<[f64; 2]> = task
                    .points
                    .iter()
                    .map(|point| [point.time_s, point.last_us])
                    .collect();
                plot_ui.line(Line::new(name.clone(), points).id(("cycle_task", name)));
            }
        });
    response
        .response
        .widget_info(|| WidgetInfo::labeled(Role::Canvas, true, PlotText::CyclePlot.get(language)));
    egui::Grid::new("cycle_time_grid")
        .striped(true)
        .num_columns(7)
        .show(ui, |ui| {
            for header in [
                PlotText::Task,
                PlotText::LastUs,
                PlotText::MinUs,
                PlotText::AverageUs,
                PlotText::MaxUs,
                PlotText::JitterUs,
                PlotText::Cycles,
            ] {
                ui.strong(header.get(language));
            }
            ui.end_row();
            for (name, task) in &history.tasks {
                let figures = task.latest;
                ui.label(name);
                for ns in [
                    figures.last_ns,
                    figures.min_ns,
                    figures.average_ns,
                    figures.max_ns,
                    figures.jitter_ns,
                ] {
                    ui.label(format_us(ns));
                }
                ui.label(figures.cycles.to_string());
                ui.end_row();
            }
        });
}

/// Nanoseconds as microseconds with one decimal, the resolution a cycle-time table needs.
fn format_us(ns: u64) -> String {
    format!("{:.1}", ns as f64 / 1000.0)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;

    use super::*;

    #[test]
    fn each_task_keeps_only_the_latest_points() {
        let mut history = CycleHistory::default();
        for second in 0..(CYCLE_HISTORY_POINTS + 5) {
            let at_s = second as f64;
            history.push("Fast", at_s, 1_500, 1_200, 3_000, 900, 40, second as u64);
        }
        history.push("Slow", 0.5, 10_000, 10_000, 10_000, 10_000, 0, 1);
        let fast: Vec<&CyclePoint> = history.points("Fast").collect();
        assert_eq!(fast.len(), CYCLE_HISTORY_POINTS);
        assert_eq!(fast[0].time_s, 5.0);
        assert_eq!(fast[0].last_us, 1.5);
        assert_eq!(history.task_names().collect::<Vec<_>>(), ["Fast", "Slow"]);
        let latest = history.latest("Fast").unwrap();
        assert_eq!(latest.cycles, CYCLE_HISTORY_POINTS as u64 + 4);
        assert_eq!(latest.min_ns, 900);
    }

    #[test]
    fn the_table_shows_each_task_s_current_figures() {
        let mut history = CycleHistory::default();
        history.push(
            "MainTask", 1.0, 1_234_567, 1_000_000, 2_000_000, 900_000, 12_300, 42,
        );
        let harness = Harness::new_ui(|ui| cycle_plot_ui(ui, &history, Language::English));
        // The task's name is in the legend and in the table.
        assert!(harness.query_all_by_label("MainTask").count() >= 1);
        harness.get_by_label("1234.6");
        harness.get_by_label("12.3");
        harness.get_by_label("42");
        harness.get_by_label("Task cycle times");
    }

    #[test]
    fn an_empty_history_says_how_to_get_statistics() {
        let history = CycleHistory::default();
        let harness = Harness::new_ui(|ui| cycle_plot_ui(ui, &history, Language::English));
        harness.get_by_label("No task statistics yet: log in to a running controller");
    }
}

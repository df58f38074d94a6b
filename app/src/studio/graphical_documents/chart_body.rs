//! A CFC or SFC body in its chart editor: the model's chart in, one `Edit::ReplaceChart` undo
//! step per change out, with the live check's markers, the target's faults and, while logged
//! in, the values (CFC) or the active steps, times and actions (SFC).

use std::collections::BTreeMap;

use compiler::sema::ProjectDiagnostic;
use editor::{
    CfcDiagnostic, CfcOutput, ElementDiagnostic, SfcDiagnostic, SfcOnlineCommand, SfcOutput,
};
use egui::Ui;
use online::TargetState;
use project_model::{Body, CfcChart, Edit, ElementId, Pou, SfcChart, TextTarget};

use crate::studio::command::{Command, Commands};
use crate::studio::error_texts::{cfc_refusal_text, sfc_edit_error_text};
use crate::studio::i18n::Text;
use crate::studio::view::StudioView;

use super::body::{change_command, prepare_value};
use super::chart_online::{SfcReadings, cfc_online};
use super::diagnostics::{element_diagnostics, fault_diagnostics};
use super::documents::GraphicalDocuments;
use super::online_values::{BodyProbes, ReadValue};
use super::services::DiagramBodyServices;

/// The CFC or SFC body a document shows this frame.
pub(crate) struct ChartShown<'a> {
    /// The POU the body belongs to.
    pub pou: &'a Pou,
    /// Which body.
    pub target: &'a TextTarget,
    /// The body's name for labels (`TempControl`, `FB_Motor.Start`).
    pub label: &'a str,
    /// The live check's findings in the POU, when it was checked.
    pub findings: Option<&'a [ProjectDiagnostic]>,
    /// The instance whose values are shown while online; `None` for a function's body.
    pub instance: Option<String>,
    /// The element to select and scroll to, once.
    pub reveal: Option<ElementId>,
}

/// The markers of the live check and of the target's faults in the body `shown`, as the diagram
/// editor's (a chart has one network, 0).
fn markers(
    view: &StudioView<'_>,
    documents: &mut GraphicalDocuments,
    shown: &ChartShown<'_>,
    project: &project_model::Project,
    revision: u64,
) -> Vec<ElementDiagnostic> {
    let mut markers = shown
        .findings
        .map(|findings| element_diagnostics(findings, shown.target))
        .unwrap_or_default();
    if view.online.target_state() == Some(TargetState::Faulted)
        && let Some(instance) = shown.instance.as_deref()
        && let Some((lowered, _)) =
            documents
                .lowering
                .body(project, shown.pou, revision, shown.target, instance)
    {
        let faults = fault_diagnostics(view.online.faults(), lowered, view.language);
        // The network marker stands for the whole chart; it is kept only when the fault's
        // element is unknown.
        let located = faults.iter().any(|marker| marker.element.is_some());
        markers.extend(
            faults
                .into_iter()
                .filter(|marker| !located || marker.element.is_some()),
        );
    }
    markers
}

/// Draws the CFC body in its editor and queues what the user did: a change as one
/// `Edit::ReplaceChart` (with the declaration of a box's new instance in the same step), a
/// refusal in the status line, a prepared value in `prepared`. Returns the variable paths the
/// editor shows while online, which the studio reads from the target.
pub(crate) fn cfc_body_ui(
    view: StudioView<'_>,
    documents: &mut GraphicalDocuments,
    prepared: &mut BTreeMap<String, String>,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: ChartShown<'_>,
    chart: &CfcChart,
) -> Vec<String> {
    let Some(session) = view.session else {
        return Vec::new();
    };
    let project = &session.project;
    let revision = session.history.revision();
    let target = shown.target;
    let diagnostics = markers(&view, documents, &shown, project, revision)
        .into_iter()
        .map(|marker| CfcDiagnostic {
            element: marker.element,
            pin: marker.pin,
            severity: marker.severity,
            code: marker.code,
            message: marker.message,
        })
        .collect();
    let (file, marks) = super::body_marks(
        &view,
        &mut documents.lowering,
        project,
        revision,
        &shown.pou.name,
        target,
    );

    let mut paths = Vec::new();
    let mut online = None;
    let mut operand_paths = None;
    if view.online.is_online()
        && let Some(instance) = shown.instance.as_deref()
        && let Some((lowered, probe_paths)) = documents
            .lowering
            .body(project, shown.pou, revision, target, instance)
    {
        let read = |path: &str| {
            view.online.program_value(path).map(|value| ReadValue {
                text: value.text.clone(),
                forced: value.forced,
            })
        };
        online = Some(cfc_online(chart, probe_paths, read, prepared));
        paths = probe_paths.iter().map(|probe| probe.path.clone()).collect();
        operand_paths = Some(BodyProbes {
            project,
            pou: shown.pou,
            instance,
            lowered,
        });
    }

    let document = documents.charts.cfc(target, chart, revision);
    document.editor.set_debug_marks(marks);
    document.set_language(view.language);
    document.sync(chart, revision);
    document.set_read_only(view.online.is_logged_in());
    document.set_diagnostics(diagnostics);
    if let Some(show) = documents.show_execution_order {
        document.editor.set_show_execution_order(show);
    }
    document.editor.set_online(online);
    if let Some(element) = shown.reveal {
        document.editor.reveal(element);
        document.editor.request_focus();
    }
    let services = DiagramBodyServices {
        project,
        target: target.clone(),
    };
    let label = Text::ImplementationOf.fill(view.language, &[("name", shown.label)]);
    let output = document.editor.show(ui, &label, &services);
    if let Some(place) = super::focused_place(
        output.response.has_focus(),
        document.editor.breakpoint_place(),
        target,
        &file,
    ) {
        documents.focused_place = Some(place);
    }
    // The editor's own toggle (its context menu) is the studio's setting for every chart.
    if documents.show_execution_order.is_some() {
        documents.show_execution_order = Some(document.editor.shows_execution_order());
    }
    if output.change.is_some() {
        // The model answers the change next frame, whether it takes it or refuses it.
        document.synced = None;
    }
    let language = view.language;
    let CfcOutput {
        change,
        declare_instance,
        prepared: prepared_operand,
        refusal,
        toggle_breakpoint,
        ..
    } = output;
    if let Some(refusal) = refusal {
        commands.error(cfc_refusal_text(&refusal, language));
    }
    if let Some(operand) = prepared_operand
        && let Some(path) = operand_paths
            .as_ref()
            .and_then(|probes| probes.operand_path(&operand.operand))
    {
        prepare_value(prepared, path, &operand.value);
    }
    if let Some(place) = toggle_breakpoint {
        super::toggle_breakpoint(
            commands,
            target,
            &file,
            place,
            &mut documents.lowering,
            (project, revision),
            language,
        );
    }
    if let Some(change) = change {
        let edit = Edit::ReplaceChart {
            target: target.clone(),
            body: Box::new(Body::Cfc {
                chart: change.chart,
            }),
        };
        commands.push(change_command(
            shown.pou,
            target,
            shown.label,
            declare_instance.as_ref(),
            edit,
            language,
        ));
    }
    paths
}

/// Draws the SFC body in its editor and queues what the user did: a change as one
/// `Edit::ReplaceChart`, a refusal in the status line, an online command as a write of the
/// steps' `_x` (never undoable). Returns the variable paths the editor shows while online.
pub(crate) fn sfc_body_ui(
    view: StudioView<'_>,
    documents: &mut GraphicalDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: ChartShown<'_>,
    chart: &SfcChart,
) -> Vec<String> {
    let Some(session) = view.session else {
        return Vec::new();
    };
    let project = &session.project;
    let revision = session.history.revision();
    let target = shown.target;
    let diagnostics = markers(&view, documents, &shown, project, revision)
        .into_iter()
        .map(|marker| SfcDiagnostic {
            element: marker.element,
            severity: marker.severity,
            code: marker.code,
            message: marker.message,
        })
        .collect();

    let mut paths = Vec::new();
    let mut online = None;
    let mut instance_path = None;
    if view.online.is_online()
        && let Some(instance) = shown.instance.as_deref()
        && let Some((_, probe_paths)) = documents
            .lowering
            .body(project, shown.pou, revision, target, instance)
    {
        let readings = SfcReadings::new(shown.pou, chart, instance, probe_paths);
        online =
            Some(readings.online(|path| view.online.program_value(path).map(|v| v.text.clone())));
        paths = readings.paths();
        instance_path = Some(readings.instance);
    }

    let (file, marks) = super::body_marks(
        &view,
        &mut documents.lowering,
        project,
        revision,
        &shown.pou.name,
        target,
    );
    let document = documents.charts.sfc(target, chart, revision);
    document.editor.set_debug_marks(marks);
    document.set_language(view.language);
    let pou = shown.pou;
    document.sync(
        chart,
        revision,
        || {
            pou.actions
                .iter()
                .map(|action| action.name.clone())
                .collect()
        },
        || {
            pou.transitions
                .iter()
                .map(|transition| transition.name.clone())
                .collect()
        },
    );
    document.set_read_only(view.online.is_logged_in());
    document.set_diagnostics(diagnostics);
    document.editor.set_online(online);
    if let Some(element) = shown.reveal {
        document.editor.reveal(element);
        document.editor.request_focus();
    }
    let services = DiagramBodyServices {
        project,
        target: target.clone(),
    };
    let label = Text::ImplementationOf.fill(view.language, &[("name", shown.label)]);
    let output = document.editor.show(ui, &label, &services);
    if let Some(place) = super::focused_place(
        output.response.has_focus(),
        document.editor.breakpoint_place(),
        target,
        &file,
    ) {
        documents.focused_place = Some(place);
    }
    if output.change.is_some() {
        document.synced = None;
    }
    let language = view.language;
    let SfcOutput {
        change,
        online: online_command,
        refusal,
        toggle_breakpoint,
        ..
    } = output;
    if let Some(place) = toggle_breakpoint {
        super::toggle_breakpoint(
            commands,
            target,
            &file,
            place,
            &mut documents.lowering,
            (project, revision),
            language,
        );
    }
    if let Some(refusal) = refusal {
        commands.error(sfc_edit_error_text(&refusal, language));
    }
    if let (Some(command), Some(instance)) = (online_command, instance_path) {
        let writes = step_writes(chart, &instance, command);
        if !writes.is_empty() {
            commands.push(Command::WriteValues(writes));
        }
    }
    if let Some(change) = change {
        commands.push(Command::Edit(
            Text::UndoEdit.fill(language, &[("name", shown.label)]),
            vec![Edit::ReplaceChart {
                target: target.clone(),
                body: Box::new(Body::Sfc {
                    chart: change.chart,
                }),
            }],
        ));
    }
    paths
}

/// The writes that execute an online command of the chart shown for `instance`: a step's
/// `_x`, or, to fire a transition, `_x` FALSE for the steps before it and TRUE for the steps
/// after it.
fn step_writes(
    chart: &SfcChart,
    instance: &str,
    command: SfcOnlineCommand,
) -> Vec<(String, String)> {
    let write = |step: &str, active: bool| {
        (
            format!("{instance}.{step}._x"),
            if active { "TRUE" } else { "FALSE" }.to_owned(),
        )
    };
    match command {
        SfcOnlineCommand::SetStepActive { step, active } => vec![write(&step, active)],
        SfcOnlineCommand::FireTransition { transition } => {
            match project_model::transition_steps(chart, transition) {
                Some(steps) => steps
                    .before
                    .iter()
                    .map(|step| write(step, false))
                    .chain(steps.after.iter().map(|step| write(step, true)))
                    .collect(),
                None => Vec::new(),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::Object;

    #[test]
    fn firing_a_transition_writes_the_steps_around_it() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let Some(Object::Pou(pou)) = project.application.object("PackCycle") else {
            panic!("no PackCycle");
        };
        let Body::Sfc { chart } = &pou.body else {
            panic!("PackCycle is not SFC");
        };
        let fire = SfcOnlineCommand::FireTransition {
            transition: ElementId(2),
        };
        let pair = |path: &str, value: &str| (path.to_owned(), value.to_owned());
        assert_eq!(
            step_writes(chart, "PackCycle", fire),
            [
                pair("PackCycle.Wait._x", "FALSE"),
                pair("PackCycle.Glue._x", "TRUE"),
                pair("PackCycle.Position._x", "TRUE"),
            ]
        );
        let activate = SfcOnlineCommand::SetStepActive {
            step: "Cut".to_owned(),
            active: true,
        };
        assert_eq!(
            step_writes(chart, "PackCycle", activate),
            [pair("PackCycle.Cut._x", "TRUE")]
        );
    }
}

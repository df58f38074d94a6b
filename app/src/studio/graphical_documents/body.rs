//! An LD or FBD body in its diagram editor: the model's networks in, one undo step per change
//! out, with the live check's markers, the target's faults and, while logged in, the power flow
//! and values.

use std::collections::BTreeMap;

use compiler::sema::ProjectDiagnostic;
use editor::{DiagramOutput, InstanceDeclaration};
use egui::Ui;
use online::TargetState;
use project_model::{
    Edit, ElementId, ListEdit, Network, Pou, TextTarget, VarOwner, VarSection, Variable,
};

use crate::studio::command::{Command, Commands};
use crate::studio::error_texts::diagram_refusal_text;
use crate::studio::i18n::{DiagramText, Language, Text};
use crate::studio::view::StudioView;

use super::diagnostics::{element_diagnostics, fault_diagnostics};
use super::documents::{GraphicalDocuments, document};
use super::online_values::{BodyProbes, ReadValue, diagram_online};
use super::services::DiagramBodyServices;

/// The LD/FBD body a document shows this frame.
pub(crate) struct GraphicalShown<'a> {
    /// The POU the body belongs to.
    pub pou: &'a Pou,
    /// Which body.
    pub target: &'a TextTarget,
    /// Its networks, as the model holds them.
    pub networks: &'a [Network],
    /// LD or FBD: the view the editor opens in.
    pub language: project_model::Language,
    /// The body's name for labels (`Interlock`, `FB_Motor.Start`).
    pub label: &'a str,
    /// The live check's findings in the POU, when it was checked.
    pub findings: Option<&'a [ProjectDiagnostic]>,
    /// The instance whose values are shown while online (`Interlock`, `Main.fbConveyor`);
    /// `None` for a function's body.
    pub instance: Option<String>,
    /// The network and element to select and scroll to, once.
    pub reveal: Option<(usize, Option<ElementId>)>,
}

/// Draws the LD/FBD body in its diagram editor and queues what the user did: a change as one
/// `Edit::SpliceNetworks` (with the declaration of a box's new instance in the same step), a
/// refusal in the status line, a prepared value in `prepared`. Returns the variable paths the
/// editor shows while online, which the studio reads from the target.
pub(crate) fn graphical_body_ui(
    view: StudioView<'_>,
    documents: &mut GraphicalDocuments,
    prepared: &mut BTreeMap<String, String>,
    commands: &mut Commands,
    ui: &mut Ui,
    shown: GraphicalShown<'_>,
) -> Vec<String> {
    let Some(session) = view.session else {
        return Vec::new();
    };
    let project = &session.project;
    let revision = session.history.revision();
    let target = shown.target;
    let mut markers = shown
        .findings
        .map(|findings| element_diagnostics(findings, target))
        .unwrap_or_default();

    let (file, marks) = super::body_marks(
        &view,
        &mut documents.lowering,
        project,
        revision,
        &shown.pou.name,
        target,
    );
    // While online the lowering says where each element's value is read and which element a
    // fault's line belongs to.
    let mut paths = Vec::new();
    let mut online = None;
    let mut operand_paths = None;
    if view.online.is_online()
        && let Some(instance) = shown.instance.as_deref()
        && let Some((lowered, probe_paths)) = documents
            .lowering
            .body(project, shown.pou, revision, target, instance)
    {
        if view.online.target_state() == Some(TargetState::Faulted) {
            markers.extend(fault_diagnostics(
                view.online.faults(),
                lowered,
                view.language,
            ));
        }
        // The program's own values, also of a variable bound to a Modbus device, so each
        // operand shows what the network computed with.
        let read = |path: &str| {
            view.online.program_value(path).map(|value| ReadValue {
                text: value.text.clone(),
                forced: value.forced,
            })
        };
        online = Some(diagram_online(shown.networks, probe_paths, read, prepared));
        paths = probe_paths.iter().map(|probe| probe.path.clone()).collect();
        operand_paths = Some(BodyProbes {
            project,
            pou: shown.pou,
            instance,
            lowered,
        });
    }
    let operand_path = |operand: &str| {
        operand_paths
            .as_ref()
            .and_then(|probes| probes.operand_path(operand))
    };

    let document = document(
        &mut documents.documents,
        target,
        shown.networks,
        shown.language,
        revision,
    );
    document.set_language(view.language);
    document.sync(shown.networks, revision);
    document.set_read_only(view.online.is_logged_in());
    document.set_diagnostics(markers);
    document.editor.set_online(online);
    document.editor.set_debug_marks(marks);
    if let Some((network, element)) = shown.reveal {
        match element {
            Some(id) => document.editor.reveal(id),
            None => document.editor.select(Some(network), Vec::new()),
        }
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
        // The model answers the change next frame, whether it takes it or refuses it.
        document.synced = None;
    }
    let language = view.language;
    let DiagramOutput {
        change,
        declare_instance,
        prepared: prepared_operand,
        refusal,
        toggle_breakpoint,
        ..
    } = output;
    if let Some(refusal) = refusal {
        commands.error(diagram_refusal_text(&refusal, language));
    }
    if let Some(operand) = prepared_operand
        && let Some(path) = operand_path(&operand.operand)
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
        let edit = Edit::SpliceNetworks {
            target: target.clone(),
            at: change.at,
            remove: change.remove,
            insert: change.insert,
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

/// Keeps `value`, prepared on an operand read at `path`, for F7 and Ctrl+F7; an empty value
/// takes the preparation back.
pub(super) fn prepare_value(prepared: &mut BTreeMap<String, String>, path: String, value: &str) {
    if value.trim().is_empty() {
        prepared.remove(&path);
    } else {
        prepared.insert(path, value.trim().to_owned());
    }
}

/// The undo step of one diagram gesture on the body `target` (named `label`): `edit`, after
/// the declaration of a box's new function block instance when the gesture named one.
pub(super) fn change_command(
    pou: &Pou,
    target: &TextTarget,
    label: &str,
    declare_instance: Option<&InstanceDeclaration>,
    edit: Edit,
    language: Language,
) -> Command {
    let mut edits = Vec::new();
    let undo_label = match declare_instance {
        Some(instance) => {
            edits.push(declare_edit(pou, target, instance));
            DiagramText::UndoDeclareInstance.fill(
                language,
                &[
                    ("name", label),
                    ("instance", &instance.name),
                    ("type", &instance.type_name),
                ],
            )
        }
        None => Text::UndoEdit.fill(language, &[("name", label)]),
    };
    edits.push(edit);
    Command::Edit(undo_label, edits)
}

/// The edit declaring a box's instance where the body's variables are: in the method for a
/// method's body, else in the POU, after the last `VAR` variable so the sections stay grouped.
pub(super) fn declare_edit(pou: &Pou, target: &TextTarget, instance: &InstanceDeclaration) -> Edit {
    let (owner, variables) = match target {
        TextTarget::Method { method, .. } => match pou.methods.iter().find(|m| m.name == *method) {
            Some(found) => (
                VarOwner::Method {
                    pou: pou.name.clone(),
                    method: method.clone(),
                },
                &found.variables,
            ),
            None => (VarOwner::Pou(pou.name.clone()), &pou.variables),
        },
        _ => (VarOwner::Pou(pou.name.clone()), &pou.variables),
    };
    let index = variables
        .iter()
        .rposition(|variable| variable.section == VarSection::Var)
        .map_or(variables.len(), |last| last + 1);
    Edit::Variables {
        owner,
        edit: ListEdit::Insert {
            index,
            item: Variable::new(&instance.name, &instance.type_name),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_instance_is_declared_after_the_last_var_of_its_pou() {
        let project = project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"));
        let Some(project_model::Object::Pou(pou)) = project.application.object("Interlock") else {
            panic!("no Interlock");
        };
        let instance = InstanceDeclaration {
            name: "tonHorn".to_owned(),
            type_name: "TON".to_owned(),
        };
        let edit = declare_edit(pou, &TextTarget::Pou("Interlock".into()), &instance);
        let Edit::Variables { owner, edit } = edit else {
            panic!("not a declaration: {edit:?}");
        };
        assert_eq!(owner, VarOwner::Pou("Interlock".into()));
        let ListEdit::Insert { index, item } = edit else {
            panic!("not an insertion");
        };
        assert_eq!(index, pou.variables.len());
        assert_eq!(item.name, "tonHorn");
        assert_eq!(item.ty, "TON");
        assert_eq!(item.section, VarSection::Var);
    }
}

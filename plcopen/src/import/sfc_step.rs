//! A step of an SFC graph with its action blocks → a [`Step`] (docs/plcopen-xml.md §4.3).

use project_model::{ActionAssociation, ActionQualifier, Step};

use super::body_fault::BodyFault;
use super::converter::comment;
use super::pous::BodyAt;
use super::rivet_attributes::rivet_attributes;
use super::sfc_chart::SfcChartBuilder;
use crate::body::BodyContent;
use crate::body_object::{BodyObject, ObjectKind};
use crate::sfc::{ActionBlockAction, ActionContent, Qualifier};

impl SfcChartBuilder<'_, '_> {
    /// The step `object` named `name`, with the actions of its action blocks and the times and
    /// CODESYS actions of Rivet's `…/step` entry.
    pub(super) fn step(&mut self, object: &BodyObject, name: &str) -> Result<Step, BodyFault> {
        let mut step = Step {
            id: self.fresh_id(),
            name: name.to_owned(),
            comment: comment(object.documentation.as_ref()),
            ..Step::default()
        };
        if let Some(attributes) = rivet_attributes(&object.add_data, "step") {
            let get = |key: &str| {
                attributes
                    .get(key)
                    .map(|value| value.trim().to_owned())
                    .filter(|value| !value.is_empty())
            };
            step.entry_action = get("entryAction");
            step.main_action = get("mainAction");
            step.exit_action = get("exitAction");
            step.min_time = get("minTime");
            step.max_time = get("maxTime");
            if let Some(text) = get("comment") {
                step.comment = text;
            }
        }
        for block in self.action_blocks(object.local_id) {
            self.used.insert(block.local_id);
            let ObjectKind::ActionBlock(action_block) = &block.kind else {
                continue;
            };
            // A path names the action by its index when the block holds several.
            let several = action_block.actions.len() > 1;
            for (index, action) in action_block.actions.iter().enumerate() {
                let element = if several {
                    format!("action[{}]", index + 1)
                } else {
                    "action".to_owned()
                };
                let association = self.association(block, name, action, &element)?;
                step.actions.push(association);
            }
        }
        Ok(step)
    }

    /// One action of an action block of the step `step`, named `element` in the block's path
    /// (`action`, or `action[2]` in a block of several).
    fn association(
        &mut self,
        block: &BodyObject,
        step: &str,
        action: &ActionBlockAction,
        element: &str,
    ) -> Result<ActionAssociation, BodyFault> {
        let qualifier = match action.qualifier {
            None | Some(Qualifier::N) => ActionQualifier::N,
            Some(Qualifier::P1) => ActionQualifier::P1,
            Some(Qualifier::P0) => ActionQualifier::P0,
            Some(Qualifier::R) => ActionQualifier::R,
            Some(Qualifier::S) => ActionQualifier::S,
            Some(Qualifier::L) => ActionQualifier::L,
            Some(Qualifier::D) => ActionQualifier::D,
            Some(Qualifier::P) => ActionQualifier::P,
            Some(Qualifier::Ds) => ActionQualifier::DS,
            Some(Qualifier::Sd) => ActionQualifier::SD,
            Some(Qualifier::Sl) => ActionQualifier::SL,
            Some(Qualifier::Dl) => {
                self.note(
                    block,
                    format!("action block of step '{step}'"),
                    "the qualifier DL is not IEC 61131-3 (the schema lists it); it became D, delayed by its duration",
                );
                ActionQualifier::D
            }
        };
        let name = match &action.content {
            ActionContent::Reference(name) => name.trim().to_owned(),
            ActionContent::Inline(body) => {
                if matches!(body.content, BodyContent::Sfc(_)) {
                    // The compiler runs a chart only as the body of a program or function
                    // block (E0124, docs/graphical-semantics.md §7), not inside an action.
                    return Err(BodyFault::NotConverted(format!(
                        "an inline action of step `{step}` (line {}) is an SFC chart, which Rivet runs only as the body of a program or function block, not inside an action",
                        block.line
                    )));
                }
                let body_path = format!(
                    "{}/actionBlock[@localId='{}']/{element}/inline",
                    self.body_path, block.local_id
                );
                let holder = self.place(block);
                let at = BodyAt {
                    holder: &holder,
                    objects_path: format!("{body_path}/{}", body.content.language()),
                    body_path,
                    invented: None,
                };
                let what = format!("inline action of step '{step}'");
                let converted = self
                    .bodies
                    .nested_body(body, &at, &what, self.pou_objects)
                    .map_err(|fault| match fault {
                        BodyFault::NotConverted(reason) => BodyFault::NotConverted(format!(
                            "an inline action of step `{step}` (line {}) cannot be converted: {reason}",
                            block.line
                        )),
                        error @ BodyFault::Error(..) => error,
                    })?;
                self.pou_objects.inline_action(step, converted)
            }
        };
        let text = |value: &Option<String>| {
            value
                .as_deref()
                .map(str::trim)
                .filter(|value| !value.is_empty())
                .map(str::to_owned)
        };
        Ok(ActionAssociation {
            action: name,
            qualifier,
            duration: text(&action.duration),
            indicator: text(&action.indicator),
        })
    }
}

//! A POU document: the part selector, the declarations above and the implementation below.

use egui::{RichText, Ui};
use project_model::Object;

use crate::studio::command::Commands;
use crate::studio::i18n::Text;
use crate::studio::reveal::Reveal;
use crate::studio::tree_node::TreeNode;
use crate::studio::view::StudioView;

use super::body::body_ui;
use super::declarations::declarations_ui;
use super::documents::TextDocuments;
use super::part::{Part, Shown, body_of, part_of};

/// Draws a POU document (LD and FBD bodies in the diagram editor, CFC and SFC as their data
/// until their editors come). Returns `false` when `name` is not a POU.
pub(crate) fn pou_document_ui(
    view: StudioView<'_>,
    texts: &mut TextDocuments,
    commands: &mut Commands,
    ui: &mut Ui,
    name: &str,
) -> bool {
    let Some(project) = view.project() else {
        return false;
    };
    let Some(Object::Pou(pou)) = project.application.object(name) else {
        return false;
    };
    let language = view.language;
    let mut part = texts.parts.get(name).cloned().unwrap_or_default();
    // A part that no longer exists (its addition was undone, or it was renamed in the text)
    // gives way to the POU's own implementation rather than an empty view.
    if body_of(pou, &part).is_none() {
        part = Part::Main;
    }

    // A pending reveal for this document picks its part first.
    let node = TreeNode::Object(name.to_owned());
    let reveal = match &texts.reveal {
        Some((target, reveal)) if *target == node => {
            let reveal = reveal.clone();
            texts.reveal = None;
            Some(reveal)
        }
        _ => None,
    };
    if let Some(Reveal::Body(target, _) | Reveal::Element { target, .. }) = &reveal {
        part = part_of(target);
    }
    if let Some(Reveal::Declaration {
        container: Some(container),
        ..
    }) = &reveal
        && pou.methods.iter().any(|m| m.name == *container)
    {
        part = Part::Method(container.clone());
    }

    // The part selector: the POU and each method, action and property accessor.
    ui.horizontal_wrapped(|ui| {
        ui.label(RichText::new(format!("{} {}", pou.kind.keyword(), pou.name)).strong());
        ui.separator();
        let mut choices = vec![(Part::Main, Text::Implementation.get(language).to_owned())];
        choices.extend(pou.methods.iter().map(|m| {
            (
                Part::Method(m.name.clone()),
                format!("{} {}", Text::Method.get(language), m.name),
            )
        }));
        choices.extend(pou.actions.iter().map(|a| {
            (
                Part::Action(a.name.clone()),
                format!("{} {}", Text::Action.get(language), a.name),
            )
        }));
        choices.extend(pou.transitions.iter().map(|t| {
            (
                Part::Transition(t.name.clone()),
                format!("{} {}", Text::Transition.get(language), t.name),
            )
        }));
        for property in &pou.properties {
            for (get, word) in [(true, "Get"), (false, "Set")] {
                let exists = if get {
                    property.get.is_some()
                } else {
                    property.set.is_some()
                };
                if exists {
                    choices.push((
                        Part::Property(property.name.clone(), get),
                        format!("{} {}.{word}", Text::Property.get(language), property.name),
                    ));
                }
            }
        }
        if choices.len() > 1 {
            for (choice, text) in choices {
                if ui.selectable_label(part == choice, text).clicked() {
                    part = choice;
                }
            }
        }
        ui.separator();
        let table = texts.tables.entry(name.to_owned()).or_insert(false);
        ui.selectable_value(table, false, Text::AsText.get(language));
        ui.selectable_value(table, true, Text::AsTable.get(language));
    });
    texts.parts.insert(name.to_owned(), part.clone());

    let show_table = texts.tables.get(name).copied().unwrap_or(false);
    let height = ui.available_height();
    let declaration_height = (height * 0.35).clamp(80.0, 320.0);
    egui::Panel::top(egui::Id::unique(("declarations", name)))
        .resizable(true)
        .default_size(declaration_height)
        .show(ui, |ui| {
            let shown = Shown {
                pou,
                part: &part,
                reveal: reveal.as_ref(),
            };
            declarations_ui(view, texts, commands, ui, shown, show_table);
        });
    egui::CentralPanel::default_margins().show(ui, |ui| {
        let shown = Shown {
            pou,
            part: &part,
            reveal: reveal.as_ref(),
        };
        body_ui(view, texts, commands, ui, shown);
    });
    true
}

//! Values shown inline in a body while online, as CODESYS shows them beside each variable,
//! and the prepared values typed into their boxes.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::ops::Range;

use compiler::ide::MonitoredName;
use editor::InlineValue;
use project_model::{Object, Pou, PouKind, Project, TextTarget};

use crate::studio::online::Online;

/// The monitored names of the bodies on screen and the prepared values typed inline.
#[derive(Default)]
pub struct InlineValues {
    /// Per body: the text and instance the names were found for, and the names.
    names: HashMap<TextTarget, (String, String, Vec<MonitoredName>)>,
    /// Prepared values typed in inline boxes, by variable path.
    pub prepared: BTreeMap<String, String>,
    /// The paths shown in the last frame, which are read from the target.
    shown: BTreeSet<String>,
    /// The paths shown so far in this frame.
    showing: BTreeSet<String>,
}

/// The instance whose values a function block's body shows: the first program or global
/// variable of that type (`Main.fbConveyor`).
pub(super) fn instance_of(project: &Project, pou: &Pou) -> Option<String> {
    match pou.kind {
        PouKind::Program => Some(pou.name.clone()),
        PouKind::Function | PouKind::Interface => None,
        PouKind::FunctionBlock => {
            project_model::object_files(project)
                .into_iter()
                .find_map(|(_, object)| {
                    let (owner, variables) = match object {
                        Object::Pou(owner) if owner.kind == PouKind::Program => {
                            (&owner.name, &owner.variables)
                        }
                        Object::Gvl(gvl) => (&gvl.name, &gvl.variables),
                        _ => return None,
                    };
                    variables
                        .iter()
                        .find(|v| v.ty.trim().eq_ignore_ascii_case(&pou.name))
                        .map(|v| format!("{owner}.{}", v.name))
                })
        }
    }
}

impl InlineValues {
    /// Starts a frame: the paths shown in the frame that ended are the ones to read.
    pub fn begin_frame(&mut self) {
        self.shown = std::mem::take(&mut self.showing);
    }

    /// The paths to read from the target for the values on screen.
    pub fn paths(&self) -> impl Iterator<Item = &String> {
        self.shown.iter()
    }

    /// The values to show in the body `target` (whose text is `text`) of `pou`: of the
    /// `halted` instance when a task is halted in it, else of its first instance.
    pub fn values_for(
        &mut self,
        online: &Online,
        project: &Project,
        target: &TextTarget,
        text: &str,
        pou: &Pou,
        halted: Option<&str>,
    ) -> Vec<InlineValue> {
        let Some(instance) = halted
            .map(str::to_owned)
            .or_else(|| instance_of(project, pou))
        else {
            return Vec::new();
        };
        let stale = self
            .names
            .get(target)
            .is_none_or(|(seen, seen_instance, _)| seen != text || *seen_instance != instance);
        if stale {
            // An instance called or followed by a member (`fbConveyor(`, `rtrigPackage.Q`)
            // shows no value of its own: only elementary values are shown, as CODESYS does.
            let names = compiler::ide::monitor_paths(project, target, &instance)
                .into_iter()
                .filter(|name| {
                    let next = text[name.range.end.min(text.len())..]
                        .trim_start()
                        .chars()
                        .next();
                    !matches!(next, Some('.' | '(' | '['))
                })
                .collect();
            self.names
                .insert(target.clone(), (text.to_owned(), instance, names));
        }
        let Some((_, _, names)) = self.names.get(target) else {
            return Vec::new();
        };
        let mut values = Vec::with_capacity(names.len());
        for name in names {
            self.showing.insert(name.path.clone());
            let prepared = self.prepared.get(&name.path);
            if let Some(value) = online.value(&name.path)
                && !value.text.starts_with(['(', '['])
            {
                let text = match prepared {
                    Some(prepared) => format!("{} <{prepared}>", value.text),
                    None => value.text.clone(),
                };
                values.push(InlineValue {
                    range: name.range.clone(),
                    text,
                    changed: value.changed,
                    forced: value.forced,
                });
            }
        }
        values
    }

    /// Reads `path` from the target while it is on screen (a value a diagram editor shows).
    pub fn show(&mut self, path: String) {
        self.showing.insert(path);
    }

    /// Forgets a body's names (the studio went offline).
    pub fn forget(&mut self, target: &TextTarget) {
        self.names.remove(target);
    }

    /// Keeps the value typed into the box of the name at `range` of `target` as its variable's
    /// prepared value (an empty text removes it).
    pub fn prepare(&mut self, target: &TextTarget, range: Range<usize>, value: String) {
        let Some((_, _, names)) = self.names.get(target) else {
            return;
        };
        let Some(name) = names.iter().find(|name| name.range == range) else {
            return;
        };
        if value.trim().is_empty() {
            self.prepared.remove(&name.path);
        } else {
            self.prepared
                .insert(name.path.clone(), value.trim().to_owned());
        }
    }
}

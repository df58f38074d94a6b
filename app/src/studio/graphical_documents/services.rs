//! The compiler's answers to the diagram editor: operands, blocks and their pins on the project
//! as it is now.

use compiler::ide::{self, DefinitionKind};
use editor::{BlockSignature, CompletionItem, CompletionKind, DiagramServices};
use project_model::{Project, TextTarget};

/// Completion, block signatures and declarations for one LD/FBD body of a project.
pub(super) struct DiagramBodyServices<'p> {
    /// The project, as the model holds it this frame.
    pub project: &'p Project,
    /// The body being edited.
    pub target: TextTarget,
}

impl DiagramServices for DiagramBodyServices<'_> {
    fn variables(&self, prefix: &str) -> Vec<CompletionItem> {
        ide::operand_completions(self.project, &self.target, prefix)
            .into_iter()
            .map(|completion| CompletionItem {
                kind: kind_of(completion.kind),
                label: completion.label,
                detail: completion.detail,
            })
            .collect()
    }

    fn blocks(&self, prefix: &str) -> Vec<CompletionItem> {
        ide::block_completions(self.project, prefix)
            .into_iter()
            .map(|completion| {
                let function_block = ide::block_pins(self.project, &completion.label)
                    .is_some_and(|pins| pins.function_block);
                CompletionItem {
                    kind: if function_block {
                        CompletionKind::FunctionBlock
                    } else {
                        CompletionKind::Function
                    },
                    label: completion.label,
                    detail: completion.detail,
                }
            })
            .collect()
    }

    fn signature(&self, type_name: &str) -> Option<BlockSignature> {
        ide::block_pins(self.project, type_name).map(|pins| BlockSignature {
            inputs: pins.inputs,
            outputs: pins.outputs,
            function_block: pins.function_block,
        })
    }

    fn structure_members(&self, type_name: &str) -> Option<Vec<String>> {
        ide::structure_members(self.project, type_name)
    }

    fn is_declared(&self, name: &str) -> bool {
        ide::operand_completions(self.project, &self.target, name)
            .iter()
            .any(|found| {
                found.label.eq_ignore_ascii_case(name)
                    && matches!(
                        found.kind,
                        DefinitionKind::Variable | DefinitionKind::Result
                    )
            })
    }
}

fn kind_of(kind: DefinitionKind) -> CompletionKind {
    match kind {
        DefinitionKind::Variable | DefinitionKind::Result | DefinitionKind::EnumValue => {
            CompletionKind::Variable
        }
        DefinitionKind::Member | DefinitionKind::Property => CompletionKind::Member,
        DefinitionKind::Pou => CompletionKind::FunctionBlock,
        DefinitionKind::DataType => CompletionKind::Type,
        _ => CompletionKind::Other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        project_model::load_project(&assets::example_project_dir())
            .map(|loaded| loaded.project)
            .unwrap_or_else(|error| panic!("{error}"))
    }

    #[test]
    fn the_interlock_knows_its_variables_and_the_timer() {
        let project = example();
        let services = DiagramBodyServices {
            project: &project,
            target: TextTarget::Pou("Interlock".into()),
        };
        let names: Vec<String> = services
            .variables("xRun")
            .into_iter()
            .map(|c| c.label)
            .collect();
        assert!(names.contains(&"xRunRequest".to_owned()), "{names:?}");
        assert!(services.is_declared("tonStartWarning"));
        assert!(services.is_declared("XRUNREQUEST"));
        assert!(!services.is_declared("tonOther"));
        let ton = services.signature("TON").expect("TON is standard");
        assert!(ton.function_block);
        assert_eq!(ton.inputs, ["IN", "PT"]);
        let blocks = services.blocks("LIM");
        assert_eq!(blocks.first().map(|b| b.label.as_str()), Some("LIMIT"));
        assert_eq!(blocks[0].kind, CompletionKind::Function);
    }
}

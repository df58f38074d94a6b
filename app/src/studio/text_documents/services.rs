//! The compiler's answers to the ST editor: completion and hover on the project as it is now.

use compiler::ide::{self, DefinitionKind};
use editor::{CompletionItem, CompletionKind, KeywordCompletions, LanguageServices};
use project_model::{Project, TextTarget};

/// Completion and hover for one body of a project.
pub struct BodyServices<'p> {
    /// The project, as the model holds it this frame.
    pub project: &'p Project,
    /// The body being edited.
    pub target: TextTarget,
}

impl LanguageServices for BodyServices<'_> {
    fn completions(&self, text: &str, offset: usize) -> Vec<CompletionItem> {
        let mut items: Vec<CompletionItem> = ide::completions(self.project, &self.target, offset)
            .into_iter()
            .map(|completion| CompletionItem {
                kind: kind_of(completion.kind),
                label: completion.label,
                detail: completion.detail,
            })
            .collect();
        // Keywords are offered too, after the names, unless the candidate is a member.
        let member = text[..offset.min(text.len())]
            .trim_end_matches(|c: char| c.is_alphanumeric() || c == '_')
            .ends_with('.');
        if !member {
            items.extend(KeywordCompletions.completions(text, offset));
        }
        items
    }

    fn hover(&self, _text: &str, offset: usize) -> Option<String> {
        ide::hover(self.project, &self.target, offset).map(|hover| hover.text)
    }
}

fn kind_of(kind: DefinitionKind) -> CompletionKind {
    match kind {
        DefinitionKind::Variable | DefinitionKind::Result => CompletionKind::Variable,
        DefinitionKind::Pou => CompletionKind::FunctionBlock,
        DefinitionKind::Method | DefinitionKind::Action | DefinitionKind::Property => {
            CompletionKind::Member
        }
        DefinitionKind::DataType => CompletionKind::Type,
        _ => CompletionKind::Other,
    }
}

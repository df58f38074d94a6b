//! What the graphical editors ask about names: the variables an operand may name in a body of
//! any language, the blocks a box may call, and the pins of a block.

use std::path::PathBuf;

use project_model::{
    DataType, Object, Pou, PouKind, Project, StBody, TextTarget, TypeDefinition, VarSection,
};

use crate::sema::{Completion, DefinitionKind};

/// The pins of a block as a box shows them.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BlockPins {
    /// The input pins in order, by their formal names.
    pub inputs: Vec<String>,
    /// The output pins in order (`OUT` for a function's result first).
    pub outputs: Vec<String>,
    /// Whether the block is a function block, whose box needs an instance.
    pub function_block: bool,
}

/// The POU a body belongs to.
fn pou_of<'p>(project: &'p Project, target: &TextTarget) -> Option<&'p Pou> {
    let name = match target {
        TextTarget::Pou(pou)
        | TextTarget::Method { pou, .. }
        | TextTarget::Property { pou, .. }
        | TextTarget::Action { pou, .. }
        | TextTarget::Transition { pou, .. } => pou,
    };
    match project.application.object(name)? {
        Object::Pou(pou) => Some(pou),
        _ => None,
    }
}

/// The names an operand typed as `typed` may continue with in the body `target`, whatever the
/// body's language: the body's variables, the project's globals and POUs, and after a dot the
/// members of what precedes it (`tonDelay.` offers `Q`, `ET`…); no standard functions.
pub fn operand_completions(project: &Project, target: &TextTarget, typed: &str) -> Vec<Completion> {
    let Some(pou) = pou_of(project, target) else {
        return Vec::new();
    };
    // The operand is checked as if it were the whole text of an ST body in the same place, so
    // the scope is the one the body's statements would see.
    let body = StBody {
        file: PathBuf::new(),
        pou,
        target: target.clone(),
        text: typed,
    };
    let mut found = crate::sema::completions(project, &body, typed.len());
    // Standard functions are called by boxes, never named by an operand.
    found.retain(|candidate| candidate.kind != DefinitionKind::Standard);
    found
}

/// The blocks a box may call whose names start with `prefix` (any case): the standard functions,
/// operators and function blocks, and the project's functions and function blocks.
pub fn block_completions(project: &Project, prefix: &str) -> Vec<Completion> {
    let wanted = prefix.to_ascii_lowercase();
    let mut found: Vec<Completion> = crate::sema::all_names()
        .map(|name| {
            let function_block = crate::sema::is_function_block(name);
            Completion {
                label: name.to_owned(),
                kind: DefinitionKind::Standard,
                detail: if function_block {
                    format!("FUNCTION_BLOCK {name}")
                } else {
                    format!("FUNCTION {name}")
                },
            }
        })
        .collect();
    for object in project.application.objects() {
        if let Object::Pou(pou) = object
            && matches!(
                pou.kind,
                PouKind::Function | PouKind::FunctionBlock | PouKind::Program
            )
        {
            found.push(Completion {
                label: pou.name.clone(),
                kind: DefinitionKind::Pou,
                detail: format!("{} {}", pou.kind.keyword(), pou.name),
            });
        }
    }
    found.retain(|block| block.label.to_ascii_lowercase().starts_with(&wanted));
    found.sort_by_key(|block| block.label.to_ascii_lowercase());
    found.dedup_by(|a, b| a.label.eq_ignore_ascii_case(&b.label));
    found
}

/// The pins of the block `name` (any case): a standard function's formal inputs and its `OUT`,
/// a standard function block's interface, or a project POU's inputs and outputs (a program's
/// too: its box calls the program by its own name, so it needs no instance).
pub fn block_pins(project: &Project, name: &str) -> Option<BlockPins> {
    if let Some(function) = crate::sema::signatures::function(name) {
        return Some(BlockPins {
            inputs: function.inputs.iter().map(|(pin, _)| pin.clone()).collect(),
            outputs: vec!["OUT".to_owned()],
            function_block: false,
        });
    }
    if let Some(block) = crate::sema::signatures::function_block(name) {
        let pins = |list: &[(&str, _)]| list.iter().map(|(pin, _)| (*pin).to_owned()).collect();
        return Some(BlockPins {
            inputs: pins(block.inputs),
            outputs: pins(block.outputs),
            function_block: true,
        });
    }
    let pou = project
        .application
        .objects()
        .into_iter()
        .find_map(|object| match object {
            Object::Pou(pou) if pou.name.eq_ignore_ascii_case(name) => Some(pou),
            _ => None,
        })?;
    let in_section = |sections: &[VarSection]| -> Vec<String> {
        pou.variables
            .iter()
            .filter(|variable| sections.contains(&variable.section))
            .map(|variable| variable.name.clone())
            .collect()
    };
    let inputs = in_section(&[VarSection::VarInput, VarSection::VarInOut]);
    match pou.kind {
        PouKind::Function => {
            let mut outputs = vec!["OUT".to_owned()];
            outputs.extend(in_section(&[VarSection::VarOutput]));
            Some(BlockPins {
                inputs,
                outputs,
                function_block: false,
            })
        }
        PouKind::FunctionBlock => Some(BlockPins {
            inputs,
            outputs: in_section(&[VarSection::VarOutput]),
            function_block: true,
        }),
        PouKind::Program => Some(BlockPins {
            inputs,
            outputs: in_section(&[VarSection::VarOutput]),
            function_block: false,
        }),
        PouKind::Interface => None,
    }
}

/// The members of the structure type `name` (any case) in declaration order, those of the
/// structures it extends first: the pins of a CFC composer or selector. `None` when `name` is
/// not a structure of the project (or its `EXTENDS` chain loops).
pub fn structure_members(project: &Project, name: &str) -> Option<Vec<String>> {
    let mut chain = Vec::new();
    let mut wanted = name.trim().to_owned();
    loop {
        let (extends, members) = project
            .application
            .objects()
            .into_iter()
            .find_map(|object| match object {
                Object::DataType(DataType {
                    name,
                    definition: TypeDefinition::Struct { extends, members },
                    ..
                }) if name.eq_ignore_ascii_case(&wanted) => Some((extends.clone(), members)),
                _ => None,
            })?;
        if chain.len() > 64 {
            return None;
        }
        chain.push(members.iter().map(|m| m.name.clone()).collect::<Vec<_>>());
        match extends {
            Some(base) if !base.trim().is_empty() => wanted = base.trim().to_owned(),
            _ => break,
        }
    }
    Some(chain.into_iter().rev().flatten().collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use project_model::{Body, Node, Variable};

    fn project_with(pous: Vec<Pou>) -> Project {
        let mut project = Project::default();
        project.application.children = pous
            .into_iter()
            .map(|pou| Node::Object(Object::Pou(pou)))
            .collect();
        project
    }

    fn pou(name: &str, kind: PouKind, variables: Vec<Variable>) -> Pou {
        Pou {
            name: name.to_owned(),
            kind,
            return_type: None,
            extends: None,
            implements: Vec::new(),
            comment: String::new(),
            variables,
            body: Body::Ld {
                networks: Vec::new(),
            },
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        }
    }

    fn input(name: &str) -> Variable {
        Variable {
            section: VarSection::VarInput,
            ..Variable::new(name, "BOOL")
        }
    }

    #[test]
    fn standard_blocks_have_their_formal_pins() {
        let project = project_with(Vec::new());
        let limit = block_pins(&project, "limit").expect("LIMIT is standard");
        assert_eq!(limit.inputs, ["MN", "IN", "MX"]);
        assert_eq!(limit.outputs, ["OUT"]);
        assert!(!limit.function_block);
        let ton = block_pins(&project, "TON").expect("TON is standard");
        assert_eq!(ton.inputs, ["IN", "PT"]);
        assert_eq!(ton.outputs, ["Q", "ET"]);
        assert!(ton.function_block);
        assert_eq!(block_pins(&project, "NoSuchBlock"), None);
    }

    #[test]
    fn project_blocks_have_their_declared_pins() {
        let output = Variable {
            section: VarSection::VarOutput,
            ..Variable::new("xDone", "BOOL")
        };
        let project = project_with(vec![
            pou(
                "FB_Motor",
                PouKind::FunctionBlock,
                vec![input("xRun"), Variable::new("iState", "INT"), output],
            ),
            pou("Main", PouKind::Program, Vec::new()),
        ]);
        let motor = block_pins(&project, "fb_motor").expect("a project FB");
        assert_eq!(motor.inputs, ["xRun"]);
        assert_eq!(motor.outputs, ["xDone"]);
        assert!(motor.function_block);
        // A program's box calls the program itself, so it has pins but needs no instance.
        let main = block_pins(&project, "Main").expect("a program");
        assert!(main.inputs.is_empty() && main.outputs.is_empty());
        assert!(!main.function_block);
        assert!(
            block_completions(&project, "Ma")
                .iter()
                .any(|b| b.label == "Main")
        );
        let blocks = block_completions(&project, "fb_");
        assert_eq!(blocks.len(), 1);
        assert_eq!(blocks[0].label, "FB_Motor");
        assert!(
            block_completions(&project, "TO")
                .iter()
                .any(|b| b.label == "TON")
        );
    }

    #[test]
    fn a_structure_has_its_members_those_it_extends_first() {
        use project_model::{DataType, StructMember};
        let structure = |name: &str, extends: Option<&str>, members: &[&str]| {
            Node::Object(Object::DataType(DataType {
                name: name.to_owned(),
                comment: String::new(),
                definition: TypeDefinition::Struct {
                    extends: extends.map(str::to_owned),
                    members: members
                        .iter()
                        .map(|member| StructMember {
                            name: (*member).to_owned(),
                            ty: "INT".to_owned(),
                            ..StructMember::default()
                        })
                        .collect(),
                },
            }))
        };
        let mut project = Project::default();
        project.application.children = vec![
            structure("ST_Base", None, &["a"]),
            structure("ST_Point", Some("ST_Base"), &["x", "y"]),
            structure("ST_Loop", Some("ST_Loop"), &["z"]),
        ];
        assert_eq!(
            structure_members(&project, "st_point"),
            Some(vec!["a".to_owned(), "x".to_owned(), "y".to_owned()])
        );
        assert_eq!(structure_members(&project, "ST_Loop"), None);
        assert_eq!(structure_members(&project, "TON"), None);
    }

    #[test]
    fn operands_complete_from_the_scope_of_a_graphical_body() {
        let project = project_with(vec![pou(
            "Interlock",
            PouKind::Program,
            vec![input("xStart"), Variable::new("tonDelay", "TON")],
        )]);
        let target = TextTarget::Pou("Interlock".to_owned());
        let names: Vec<String> = operand_completions(&project, &target, "xS")
            .into_iter()
            .map(|c| c.label)
            .collect();
        assert_eq!(names, ["xStart"]);
        let members: Vec<String> = operand_completions(&project, &target, "tonDelay.")
            .into_iter()
            .map(|c| c.label)
            .collect();
        assert!(members.contains(&"Q".to_owned()), "{members:?}");
    }
}

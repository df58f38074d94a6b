//! IEC 61131-3 declaration text rendered from the structured model.
//!
//! The editors show declarations as text beside the table view, and the compiler parses this same
//! text, so a declaration reads identically wherever it appears.

use std::fmt::Write as _;

use crate::{
    AccessSpecifier, DataType, GlobalVarList, Method, Pou, Property, TypeDefinition, Variable,
};

impl Pou {
    /// The POU's header and declarations, such as
    /// `FUNCTION_BLOCK FB_Conveyor\nVAR_INPUT\n    xStart : BOOL;\nEND_VAR\n`.
    pub fn declaration_text(&self) -> String {
        let mut text = String::new();
        push_comment(&mut text, &self.comment, "");
        text.push_str(self.kind.keyword());
        text.push(' ');
        text.push_str(&self.name);
        if let Some(base) = &self.extends {
            write!(text, " EXTENDS {base}").ok();
        }
        if !self.implements.is_empty() {
            write!(text, " IMPLEMENTS {}", self.implements.join(", ")).ok();
        }
        if let Some(return_type) = &self.return_type {
            write!(text, " : {return_type}").ok();
        }
        text.push('\n');
        push_variables(&mut text, &self.variables);
        text
    }
}

impl Method {
    /// The method's header and declarations.
    pub fn declaration_text(&self) -> String {
        let mut text = String::new();
        push_comment(&mut text, &self.comment, "");
        text.push_str("METHOD ");
        push_access(&mut text, self.access);
        if self.is_abstract {
            text.push_str("ABSTRACT ");
        }
        text.push_str(&self.name);
        if let Some(return_type) = &self.return_type {
            write!(text, " : {return_type}").ok();
        }
        text.push('\n');
        push_variables(&mut text, &self.variables);
        text
    }
}

impl Property {
    /// The property's header.
    pub fn declaration_text(&self) -> String {
        let mut text = String::new();
        push_comment(&mut text, &self.comment, "");
        text.push_str("PROPERTY ");
        push_access(&mut text, self.access);
        writeln!(text, "{} : {}", self.name, self.ty).ok();
        text
    }
}

impl GlobalVarList {
    /// The list as `VAR_GLOBAL … END_VAR` blocks.
    pub fn declaration_text(&self) -> String {
        let mut text = String::new();
        push_comment(&mut text, &self.comment, "");
        push_variables(&mut text, &self.variables);
        text
    }
}

impl DataType {
    /// The type as a `TYPE … END_TYPE` block.
    pub fn declaration_text(&self) -> String {
        let mut text = String::new();
        push_comment(&mut text, &self.comment, "");
        text.push_str("TYPE ");
        text.push_str(&self.name);
        match &self.definition {
            TypeDefinition::Struct { extends, members } => {
                if let Some(base) = extends {
                    write!(text, " EXTENDS {base}").ok();
                }
                text.push_str(" :\nSTRUCT\n");
                push_members(&mut text, members);
                text.push_str("END_STRUCT\n");
            }
            TypeDefinition::Union { members } => {
                text.push_str(" :\nUNION\n");
                push_members(&mut text, members);
                text.push_str("END_UNION\n");
            }
            TypeDefinition::Enum { base, values } => {
                text.push_str(" :\n(\n");
                for (index, value) in values.iter().enumerate() {
                    write!(text, "    {}", value.name).ok();
                    if let Some(number) = &value.value {
                        write!(text, " := {number}").ok();
                    }
                    if index + 1 < values.len() {
                        text.push(',');
                    }
                    push_trailing_comment(&mut text, &value.comment);
                    text.push('\n');
                }
                text.push(')');
                if let Some(base) = base {
                    write!(text, " {base}").ok();
                }
                text.push_str(";\n");
            }
            TypeDefinition::Alias { ty, initial } => {
                write!(text, " : {ty}").ok();
                if let Some(initial) = initial {
                    write!(text, " := {initial}").ok();
                }
                text.push_str(";\n");
            }
        }
        text.push_str("END_TYPE\n");
        text
    }
}

fn push_access(text: &mut String, access: AccessSpecifier) {
    let keyword = match access {
        AccessSpecifier::Public => "PUBLIC ",
        AccessSpecifier::Private => "PRIVATE ",
        AccessSpecifier::Protected => "PROTECTED ",
        AccessSpecifier::Internal => "INTERNAL ",
    };
    text.push_str(keyword);
}

/// Writes variables as sections, starting a new section whenever the section keyword or its
/// qualifiers change, so the declaration order of the model is kept exactly.
fn push_variables(text: &mut String, variables: &[Variable]) {
    let header = |v: &Variable| {
        let mut header = v.section.keyword().to_owned();
        for (flag, word) in [
            (v.constant, " CONSTANT"),
            (v.retain, " RETAIN"),
            (v.persistent, " PERSISTENT"),
        ] {
            if flag {
                header.push_str(word);
            }
        }
        header
    };
    let mut open: Option<String> = None;
    for variable in variables {
        let wanted = header(variable);
        if open.as_ref() != Some(&wanted) {
            if open.is_some() {
                text.push_str("END_VAR\n");
            }
            text.push_str(&wanted);
            text.push('\n');
            open = Some(wanted);
        }
        write!(text, "    {}", variable.name).ok();
        if let Some(address) = &variable.address {
            write!(text, " AT {address}").ok();
        }
        write!(text, " : {}", variable.ty).ok();
        if let Some(initial) = &variable.initial {
            write!(text, " := {initial}").ok();
        }
        text.push(';');
        push_trailing_comment(text, &variable.comment);
        text.push('\n');
    }
    if open.is_some() {
        text.push_str("END_VAR\n");
    }
}

fn push_members(text: &mut String, members: &[crate::StructMember]) {
    for member in members {
        write!(text, "    {} : {}", member.name, member.ty).ok();
        if let Some(initial) = &member.initial {
            write!(text, " := {initial}").ok();
        }
        text.push(';');
        push_trailing_comment(text, &member.comment);
        text.push('\n');
    }
}

/// A one-line comment goes after `//`; a longer one in `(* *)`.
fn push_trailing_comment(text: &mut String, comment: &str) {
    if comment.is_empty() {
        return;
    }
    if comment.contains('\n') {
        write!(text, " (* {} *)", comment.replace("*)", "* )")).ok();
    } else {
        write!(text, " // {comment}").ok();
    }
}

fn push_comment(text: &mut String, comment: &str, indent: &str) {
    for line in comment.lines() {
        writeln!(text, "{indent}// {line}").ok();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Body, PouKind, VarSection};

    #[test]
    fn a_function_block_renders_as_iec_declarations() {
        let pou = Pou {
            name: "FB_Conveyor".into(),
            kind: PouKind::FunctionBlock,
            return_type: None,
            extends: None,
            implements: vec!["I_Drive".into()],
            comment: "Runs the belt.".into(),
            variables: vec![
                Variable {
                    section: VarSection::VarInput,
                    comment: "start request".into(),
                    ..Variable::new("xStart", "BOOL")
                },
                Variable {
                    initial: Some("T#2s".into()),
                    ..Variable::new("tDelay", "TIME")
                },
                Variable {
                    retain: true,
                    ..Variable::new("udiCount", "UDINT")
                },
                Variable {
                    address: Some("%QX0.0".into()),
                    ..Variable::new("xMotor", "BOOL")
                },
            ],
            body: Body::st(""),
            methods: Vec::new(),
            properties: Vec::new(),
            actions: Vec::new(),
            transitions: Vec::new(),
        };
        assert_eq!(
            pou.declaration_text(),
            "// Runs the belt.\n\
             FUNCTION_BLOCK FB_Conveyor IMPLEMENTS I_Drive\n\
             VAR_INPUT\n    xStart : BOOL; // start request\nEND_VAR\n\
             VAR\n    tDelay : TIME := T#2s;\nEND_VAR\n\
             VAR RETAIN\n    udiCount : UDINT;\nEND_VAR\n\
             VAR\n    xMotor AT %QX0.0 : BOOL;\nEND_VAR\n"
        );
    }

    #[test]
    fn an_enumeration_renders_with_values_and_base_type() {
        let data_type = DataType {
            name: "E_State".into(),
            comment: String::new(),
            definition: TypeDefinition::Enum {
                base: Some("INT".into()),
                values: vec![
                    crate::EnumValue {
                        name: "Idle".into(),
                        value: Some("0".into()),
                        comment: String::new(),
                    },
                    crate::EnumValue {
                        name: "Running".into(),
                        value: None,
                        comment: "belt moves".into(),
                    },
                ],
            },
        };
        assert_eq!(
            data_type.declaration_text(),
            "TYPE E_State :\n(\n    Idle := 0,\n    Running // belt moves\n) INT;\nEND_TYPE\n"
        );
    }
}

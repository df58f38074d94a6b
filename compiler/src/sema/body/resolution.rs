//! What names resolve to, recorded for hover, go to definition and find references.

use super::*;

impl<'s, 'a, 'p> BodyChecker<'s, 'a, 'p> {
    /// Records what the name at `range` refers to, when resolutions are collected.
    pub(super) fn note(
        &mut self,
        range: Range<usize>,
        ty: &Type,
        definition: impl FnOnce(&Self) -> Definition,
    ) {
        if self.resolutions.is_none() {
            return;
        }
        let definition = definition(self);
        if let Some(resolutions) = &mut self.resolutions {
            resolutions.push(Resolution {
                range,
                definition,
                ty: ty.to_string(),
            });
        }
    }

    /// The definition of a variable, with the object (and method or property) declaring it.
    pub(super) fn variable_definition(&self, variable: &Variable) -> Definition {
        let detail = variable_detail(variable);
        let make = |object: &str, container: Option<&str>| Definition {
            kind: DefinitionKind::Variable,
            object: Some(object.to_owned()),
            container: container.map(str::to_owned),
            name: variable.name.clone(),
            detail: detail.clone(),
        };
        let is = |candidate: &Variable| std::ptr::eq(candidate, variable);
        if let Some(pou) = self.scope.pou {
            for current in inheritance_chain(self.scope.globals, pou) {
                if current.variables.iter().any(is) {
                    return make(&current.name, None);
                }
                for method in &current.methods {
                    if method.variables.iter().any(is) {
                        return make(&current.name, Some(&method.name));
                    }
                }
                for property in &current.properties {
                    if property
                        .get
                        .iter()
                        .chain(&property.set)
                        .any(|a| a.variables.iter().any(is))
                    {
                        return make(&current.name, Some(&property.name));
                    }
                }
            }
        }
        for gvl_name in self.scope.globals.gvl_names() {
            if let Some(GlobalSymbol::Gvl(gvl)) = self.scope.globals.lookup(gvl_name)
                && gvl.variables.iter().any(is)
            {
                return make(&gvl.name, None);
            }
        }
        make("", None)
    }

    /// What the name `token` (in the name expression `node`) refers to.
    pub(super) fn definition_of_name(
        &self,
        token: &SyntaxToken,
        node: &NameExpr,
    ) -> Option<Definition> {
        let name = token.text();
        let global_only = node.is_global();
        let pou_name = self.scope.pou.map(|pou| pou.name.clone());
        let simple = |kind,
                      object: Option<String>,
                      container: Option<String>,
                      name: &str,
                      detail: String| Definition {
            kind,
            object,
            container,
            name: name.to_owned(),
            detail,
        };
        if !global_only && let Some(local) = self.scope.local(name) {
            return Some(match local {
                LocalSymbol::Var(variable) => self.variable_definition(variable),
                LocalSymbol::Result(ty) => simple(
                    DefinitionKind::Result,
                    pou_name,
                    None,
                    name,
                    format!("{name} : {ty} (the result)"),
                ),
                LocalSymbol::Method(method) => simple(
                    DefinitionKind::Method,
                    self.owner_of_member(name),
                    None,
                    &method.name,
                    format!(
                        "METHOD {}{}",
                        method.name,
                        method
                            .return_type
                            .as_deref()
                            .map(|t| format!(" : {t}"))
                            .unwrap_or_default()
                    ),
                ),
                LocalSymbol::Property(property) => simple(
                    DefinitionKind::Property,
                    self.owner_of_member(name),
                    None,
                    &property.name,
                    format!("PROPERTY {} : {}", property.name, property.ty),
                ),
                LocalSymbol::Action => simple(
                    DefinitionKind::Action,
                    pou_name,
                    None,
                    name,
                    format!("ACTION {name}"),
                ),
                LocalSymbol::Step => simple(
                    DefinitionKind::Step,
                    pou_name,
                    None,
                    name,
                    format!("STEP {name}"),
                ),
                LocalSymbol::SfcAction => simple(
                    DefinitionKind::Step,
                    pou_name,
                    None,
                    name,
                    format!("{name} : SFCActionType"),
                ),
                LocalSymbol::TransitionValue => simple(
                    DefinitionKind::Step,
                    pou_name,
                    None,
                    name,
                    format!("TRANSITION {name} : BOOL"),
                ),
            });
        }
        // A project object: it is declared in its own file.
        let object =
            |kind, name: &str, detail| simple(kind, Some(name.to_owned()), None, name, detail);
        let globals = self.scope.globals;
        Some(match globals.lookup(name)? {
            GlobalSymbol::Var(variable) => self.variable_definition(variable),
            GlobalSymbol::Pou(pou) => object(DefinitionKind::Pou, &pou.name, pou_detail(pou)),
            GlobalSymbol::Gvl(gvl) => object(
                DefinitionKind::GlobalVarList,
                &gvl.name,
                format!("global variable list {}", gvl.name),
            ),
            GlobalSymbol::DataType(data_type) => object(
                DefinitionKind::DataType,
                &data_type.name,
                format!("TYPE {}", data_type.name),
            ),
            GlobalSymbol::EnumValue(data_type) => {
                let value = globals
                    .enum_value(data_type, name, 0)
                    .and_then(Const::as_int);
                let detail = match value {
                    Some(value) => format!("{}.{name} = {value}", data_type.name),
                    None => format!("{}.{name}", data_type.name),
                };
                simple(
                    DefinitionKind::EnumValue,
                    Some(data_type.name.clone()),
                    None,
                    name,
                    detail,
                )
            }
            GlobalSymbol::Axis => simple(
                DefinitionKind::Axis,
                None,
                None,
                name,
                format!("axis {name} : AXIS_REF"),
            ),
            GlobalSymbol::Cam => simple(
                DefinitionKind::CamTable,
                None,
                None,
                name,
                format!("cam table {name} : MC_CAM_REF"),
            ),
        })
    }

    /// The POU (this one or a base) that declares the method or property `name`.
    pub(super) fn owner_of_member(&self, name: &str) -> Option<String> {
        let pou = self.scope.pou?;
        inheritance_chain(self.scope.globals, pou)
            .into_iter()
            .find(|current| {
                current
                    .methods
                    .iter()
                    .any(|m| m.name.eq_ignore_ascii_case(name))
                    || current
                        .properties
                        .iter()
                        .any(|p| p.name.eq_ignore_ascii_case(name))
            })
            .map(|current| current.name.clone())
    }
}

/// `name : TYPE := initial` for hover.
pub(super) fn variable_detail(variable: &Variable) -> String {
    let mut detail = format!("{} : {}", variable.name, variable.ty);
    if let Some(initial) = &variable.initial {
        detail.push_str(&format!(" := {initial}"));
    }
    if let Some(address) = &variable.address {
        detail = format!("{} AT {address} : {}", variable.name, variable.ty);
    }
    if !variable.comment.is_empty() {
        detail.push_str(&format!(" // {}", variable.comment));
    }
    detail
}

/// `LIMIT(MN, IN, MX) : ANY_ELEMENTARY` for hover.
pub(super) fn signature_detail(name: &str, signature: &FunctionSig) -> String {
    let show = |sig: &Sig| match sig {
        Sig::E(e) => e.name().to_owned(),
        Sig::Str => "STRING".to_owned(),
        Sig::Class(g) | Sig::T(g) => Type::Generic(*g).to_string(),
        Sig::RealOfT | Sig::Power => "ANY_REAL".to_owned(),
        Sig::AnyInt => "ANY_INT".to_owned(),
        Sig::Pointer => "POINTER".to_owned(),
        Sig::Void => String::new(),
    };
    let mut inputs: Vec<String> = signature
        .inputs
        .iter()
        .map(|(input, sig)| format!("{input} : {}", show(sig)))
        .collect();
    if signature.extensible {
        inputs.push("…".to_owned());
    }
    let result = show(&signature.result);
    if result.is_empty() {
        format!(
            "FUNCTION {}({})",
            name.to_ascii_uppercase(),
            inputs.join(", ")
        )
    } else {
        format!(
            "FUNCTION {}({}) : {result}",
            name.to_ascii_uppercase(),
            inputs.join(", ")
        )
    }
}

/// `FUNCTION F_Scale : REAL` for hover.
pub(super) fn pou_detail(pou: &Pou) -> String {
    let mut detail = format!("{} {}", pou.kind.keyword(), pou.name);
    if let Some(ty) = &pou.return_type {
        detail.push_str(&format!(" : {ty}"));
    }
    detail
}

//! The standard names the checker knows but refuses, each with its own code: operators CODESYS
//! V3 no longer compiles, system operators the runtime does not provide, and `BITADR` of what
//! has no direct address. Nothing the checker lets through fails in the code generator.

use crate::diagnostic::Code;
use crate::syntax::ast::{Arg, Expr};

use super::BodyChecker;
use crate::sema::scope::{GlobalSymbol, LocalSymbol};

impl BodyChecker<'_, '_, '_> {
    /// Why a call of the standard name `upper` is refused, if it is.
    pub(super) fn refused_standard(
        &self,
        upper: &str,
        arguments: &[Arg],
    ) -> Option<(Code, String)> {
        Some(match upper {
            // CODESYS V3 error C0191: "The operator 'INDEXOF' is no longer supported. Use ADR
            // instead."
            "INDEXOF" => (
                Code::RetiredOperator,
                "CODESYS V3 no longer compiles 'INDEXOF' (its error C0191); use ADR on the POU's name".to_owned(),
            ),
            // CODESYS compiles __NEW and __DELETE only with the application's option "Use
            // dynamic memory allocation"; Rivet's runtime has no heap to enable.
            "__NEW" | "__DELETE" => (
                Code::SystemOperatorUnavailable,
                format!(
                    "'{upper}' needs dynamic memory, which Rivet's runtime does not have (CODESYS too refuses it unless the application enables dynamic memory allocation); declare the instances you need"
                ),
            ),
            // Both need an interface extending __SYSTEM.IQueryInterface, which Rivet does not
            // provide.
            "__QUERYINTERFACE" | "__QUERYPOINTER" => (
                Code::SystemOperatorUnavailable,
                format!(
                    "'{upper}' needs interfaces that extend __SYSTEM.IQueryInterface, which Rivet does not provide; call the method through the interface you hold"
                ),
            ),
            "BITADR" => {
                let located = arguments
                    .first()
                    .and_then(Arg::value)
                    .is_some_and(|value| self.is_located(&value));
                if located {
                    return None;
                }
                (
                    Code::BitAddressWithoutLocation,
                    "'BITADR' gives the bit offset of a variable in its %I, %Q or %M area: its argument must be a direct address or a variable declared AT one".to_owned(),
                )
            }
            _ => return None,
        })
    }

    /// Whether `value` is a direct address (`%IX1.2`) or names a variable declared at one.
    fn is_located(&self, value: &Expr) -> bool {
        match value {
            Expr::AddressExpr(_) => true,
            Expr::NameExpr(name) => {
                let Some(text) = name.name() else {
                    return false;
                };
                let text = text.text();
                match self.scope.local(text) {
                    Some(LocalSymbol::Var(variable)) => variable.address.is_some(),
                    Some(_) => false,
                    None => matches!(
                        self.scope.globals.lookup(text),
                        Some(GlobalSymbol::Var(variable)) if variable.address.is_some()
                    ),
                }
            }
            _ => false,
        }
    }
}

//! Types and values of the document written as the IEC text Rivet's declarations hold.

use thiserror::Error;

use crate::data_type::{DataType, Value, ValueItem};

/// Why a type of the document cannot be written where a variable's type stands.
#[derive(Debug, Error, PartialEq, Eq)]
pub(super) enum TypeTextError {
    /// A structure declared inside a variable: Rivet declares structures only as data types.
    #[error(
        "a structure declared inside a variable cannot be written as a Rivet type; declare it in `types/dataTypes`"
    )]
    InlineStruct,
}

/// The IEC text of `data_type` where a variable's type stands, or why it cannot be written
/// there (a structure declared inline).
pub(super) fn type_text(data_type: &DataType) -> Result<String, TypeTextError> {
    Ok(match data_type {
        DataType::Elementary(name) => name.clone(),
        DataType::String { wide, length } => {
            let keyword = if *wide { "WSTRING" } else { "STRING" };
            match length {
                Some(length) => format!("{keyword}({length})"),
                None => keyword.to_owned(),
            }
        }
        DataType::Array { dimensions, base } => {
            let ranges: Vec<String> = dimensions
                .iter()
                .map(|dimension| format!("{}..{}", dimension.lower, dimension.upper))
                .collect();
            format!("ARRAY[{}] OF {}", ranges.join(", "), type_text(base)?)
        }
        // A user type's name is kept as written even when the document does not declare it: the
        // checker names it later, where the user can fix it.
        DataType::Derived { name } => name.clone(),
        DataType::Enum { values, base } => {
            let items: Vec<String> = values
                .iter()
                .map(|value| match &value.value {
                    Some(number) => format!("{} := {number}", value.name),
                    None => value.name.clone(),
                })
                .collect();
            match base {
                Some(base) => format!("({}) {}", items.join(", "), type_text(base)?),
                None => format!("({})", items.join(", ")),
            }
        }
        DataType::Struct { .. } => {
            return Err(TypeTextError::InlineStruct);
        }
        DataType::Subrange {
            lower, upper, base, ..
        } => format!("{}({lower}..{upper})", type_text(base)?),
        DataType::Pointer { base } => format!("POINTER TO {}", type_text(base)?),
    })
}

/// The IEC text of an initial value: a literal as written, `[1, 2, 3(0)]` for arrays (a
/// repetition as `count(value)`), `(a := 1, b := 2)` for structures.
pub(super) fn value_text(value: &Value) -> String {
    match value {
        Value::Simple(text) => text.clone(),
        Value::Array(items) => {
            let written: Vec<String> = items.iter().map(array_item_text).collect();
            format!("[{}]", written.join(", "))
        }
        Value::Struct(items) => {
            let written: Vec<String> = items
                .iter()
                .map(|item| match &item.key {
                    Some(member) => format!("{member} := {}", value_text(&item.value)),
                    None => value_text(&item.value),
                })
                .collect();
            format!("({})", written.join(", "))
        }
    }
}

fn array_item_text(item: &ValueItem) -> String {
    match &item.key {
        Some(count) => format!("{count}({})", value_text(&item.value)),
        None => value_text(&item.value),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data_type::{Dimension, EnumValue};

    #[test]
    fn types_are_written_as_iec_text() {
        let array = DataType::Array {
            dimensions: vec![
                Dimension {
                    lower: "0".into(),
                    upper: "9".into(),
                },
                Dimension {
                    lower: "1".into(),
                    upper: "N".into(),
                },
            ],
            base: Box::new(DataType::String {
                wide: false,
                length: Some("20".into()),
            }),
        };
        assert_eq!(
            type_text(&array).as_deref(),
            Ok("ARRAY[0..9, 1..N] OF STRING(20)")
        );
        let subrange = DataType::Subrange {
            signed: true,
            lower: "-5".into(),
            upper: "5".into(),
            base: Box::new(DataType::Elementary("INT".into())),
        };
        assert_eq!(type_text(&subrange).as_deref(), Ok("INT(-5..5)"));
        let colours = DataType::Enum {
            values: vec![
                EnumValue {
                    name: "Red".into(),
                    value: Some("1".into()),
                },
                EnumValue {
                    name: "Green".into(),
                    value: None,
                },
            ],
            base: None,
        };
        assert_eq!(type_text(&colours).as_deref(), Ok("(Red := 1, Green)"));
        assert_eq!(
            type_text(&DataType::Struct { members: vec![] }),
            Err(TypeTextError::InlineStruct)
        );
        assert_eq!(
            TypeTextError::InlineStruct.to_string(),
            "a structure declared inside a variable cannot be written as a Rivet type; declare it in `types/dataTypes`"
        );
    }

    #[test]
    fn values_are_written_as_iec_text() {
        let array = Value::Array(vec![
            ValueItem {
                key: None,
                value: Value::Simple("1".into()),
            },
            ValueItem {
                key: Some("3".into()),
                value: Value::Simple("0".into()),
            },
        ]);
        assert_eq!(value_text(&array), "[1, 3(0)]");
        let point = Value::Struct(vec![ValueItem {
            key: Some("x".into()),
            value: Value::Simple("2".into()),
        }]);
        assert_eq!(value_text(&point), "(x := 2)");
    }
}

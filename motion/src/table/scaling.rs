//! The eight scaling fields of the CODESYS point tables (`docs/cam-formats.md` §3.1).

use super::TableError;
use super::number::st_real;
use crate::curve::CamPoint;

/// The technical ("editor") and table units of a CODESYS `SMC_CAMTable_…` structure, one field
/// per `REAL` member of the same name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CodesysScaling {
    /// `fEditorMasterMin`: the master start in technical units.
    pub editor_master_min: f64,
    /// `fEditorMasterMax`: the master end in technical units.
    pub editor_master_max: f64,
    /// `fEditorSlaveMin`: the slave position the table slave minimum stands for.
    pub editor_slave_min: f64,
    /// `fEditorSlaveMax`: the slave position the table slave maximum stands for.
    pub editor_slave_max: f64,
    /// `fTableMasterMin`: the master start in table units.
    pub table_master_min: f64,
    /// `fTableMasterMax`: the master end in table units.
    pub table_master_max: f64,
    /// `fTableSlaveMin`: the table value that stands for `editor_slave_min`.
    pub table_slave_min: f64,
    /// `fTableSlaveMax`: the table value that stands for `editor_slave_max`.
    pub table_slave_max: f64,
}

impl CodesysScaling {
    /// The scaling of a table written in technical units, as the CODESYS cam editor writes it:
    /// table fields equal editor fields, the master fields are the first and last master
    /// position, the slave fields the smallest and largest slave position. A flat table gets
    /// the slave fields `y` and `y + 1`, so its scale is 1 rather than 0/0.
    pub fn technical_units(points: &[CamPoint]) -> Self {
        let master_min = points.first().map_or(0.0, |p| p.master);
        let master_max = points.last().map_or(0.0, |p| p.master);
        let slave_min = points.iter().map(|p| p.slave).fold(f64::INFINITY, f64::min);
        let slave_max = points
            .iter()
            .map(|p| p.slave)
            .fold(f64::NEG_INFINITY, f64::max);
        let (slave_min, slave_max) = if slave_min.is_finite() && slave_max > slave_min {
            (slave_min, slave_max)
        } else if slave_min.is_finite() {
            (slave_min, slave_min + 1.0)
        } else {
            (0.0, 1.0)
        };
        Self {
            editor_master_min: master_min,
            editor_master_max: master_max,
            editor_slave_min: slave_min,
            editor_slave_max: slave_max,
            table_master_min: master_min,
            table_master_max: master_max,
            table_slave_min: slave_min,
            table_slave_max: slave_max,
        }
    }

    /// The slave position in technical units for a value stored in the table:
    /// `value·fSlaveScale + fSlaveOffset` with
    /// `fSlaveScale = (fEditorSlaveMax − fEditorSlaveMin)/(fTableSlaveMax − fTableSlaveMin)` and
    /// `fSlaveOffset = fEditorSlaveMin − fTableSlaveMin·fSlaveScale`.
    pub fn slave_from_table(&self, table_value: f64) -> Result<f64, TableError> {
        let table_width = self.table_slave_max - self.table_slave_min;
        if table_width == 0.0 {
            return Err(TableError::EmptyTableSlaveRange {
                value: self.table_slave_min,
            });
        }
        let scale = (self.editor_slave_max - self.editor_slave_min) / table_width;
        let offset = self.editor_slave_min - self.table_slave_min * scale;
        Ok(table_value * scale + offset)
    }

    /// The fields as Structured Text assignments in the order of the CODESYS structure, each on
    /// its own line with `indent` before it and `,` after all but the last.
    pub(crate) fn st_assignments(&self, indent: &str) -> String {
        self.named_fields()
            .iter()
            .map(|(name, value)| format!("{indent}{name} := {}", st_real(*value)))
            .collect::<Vec<_>>()
            .join(",\n")
    }

    /// The fields with their CODESYS names, in the order of the structure.
    pub(crate) fn named_fields(&self) -> [(&'static str, f64); 8] {
        [
            ("fEditorMasterMin", self.editor_master_min),
            ("fEditorMasterMax", self.editor_master_max),
            ("fEditorSlaveMin", self.editor_slave_min),
            ("fEditorSlaveMax", self.editor_slave_max),
            ("fTableMasterMin", self.table_master_min),
            ("fTableMasterMax", self.table_master_max),
            ("fTableSlaveMin", self.table_slave_min),
            ("fTableSlaveMax", self.table_slave_max),
        ]
    }
}

/// The declaration of a CODESYS table type: `Table` with the given type, then the eight
/// scaling fields as `REAL`.
pub(crate) fn table_type_declaration(type_name: &str, table_type: &str) -> String {
    let mut text = format!("TYPE {type_name} :\nSTRUCT\n    Table : {table_type};\n");
    for (name, _) in CodesysScaling::technical_units(&[]).named_fields() {
        text.push_str(&format!("    {name} : REAL;\n"));
    }
    text.push_str("END_STRUCT\nEND_TYPE\n");
    text
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    fn t20() -> CodesysScaling {
        CodesysScaling {
            editor_master_min: 0.0,
            editor_master_max: 360.0,
            editor_slave_min: 180.0,
            editor_slave_max: 270.0,
            table_master_min: 0.0,
            table_master_max: 360.0,
            table_slave_min: 0.0,
            table_slave_max: 1.0,
        }
    }

    #[test]
    fn t20_table_value_one_half_is_slave_225() {
        assert_eq!(t20().slave_from_table(0.5).unwrap(), 225.0);
        assert_eq!(t20().slave_from_table(0.0).unwrap(), 180.0);
        assert_eq!(t20().slave_from_table(1.0).unwrap(), 270.0);
    }

    #[test]
    fn technical_units_leave_table_values_unchanged() {
        let points = [
            CamPoint {
                master: 0.0,
                slave: -20.0,
                ..CamPoint::default()
            },
            CamPoint {
                master: 360.0,
                slave: 80.0,
                ..CamPoint::default()
            },
        ];
        let scaling = CodesysScaling::technical_units(&points);
        assert_eq!(scaling.editor_slave_min, -20.0);
        assert_eq!(scaling.table_slave_max, 80.0);
        assert_eq!(scaling.editor_master_max, 360.0);
        assert_eq!(scaling.slave_from_table(37.5).unwrap(), 37.5);
    }

    #[test]
    fn a_flat_table_gets_a_slave_scale_of_one() {
        let points = [
            CamPoint {
                master: 0.0,
                slave: 5.0,
                ..CamPoint::default()
            },
            CamPoint {
                master: 1.0,
                slave: 5.0,
                ..CamPoint::default()
            },
        ];
        let scaling = CodesysScaling::technical_units(&points);
        assert_eq!(
            (scaling.table_slave_min, scaling.table_slave_max),
            (5.0, 6.0)
        );
        assert_eq!(scaling.slave_from_table(5.0).unwrap(), 5.0);
    }

    #[test]
    fn an_empty_table_slave_range_is_refused() {
        let scaling = CodesysScaling {
            table_slave_min: 2.0,
            table_slave_max: 2.0,
            ..t20()
        };
        let error = scaling.slave_from_table(2.0).unwrap_err();
        assert_eq!(
            error.to_string(),
            "fTableSlaveMin and fTableSlaveMax are both 2: the slave scale would divide by zero"
        );
    }
}

//! The CODESYS 2-D point table `SMC_CAMTable_LREAL_<N>_2` (`docs/cam-formats.md` §3.2).

use super::TableError;
use super::number::{check_identifier, st_real};
use super::sampling::{CODESYS_MAX_ELEMENTS, check_count, check_points, sample_equidistant};
use super::scaling::{CodesysScaling, table_type_declaration};
use crate::curve::{CamCurve, CamPoint};

/// How errors name CODESYS when a table is too long for it.
const CODESYS_SYSTEM: &str = "CODESYS (nElements is an INT)";

/// Master/slave pairs for a CODESYS `SMC_CAMTable_LREAL_<N>_2`, in technical units.
#[derive(Clone, Debug, PartialEq)]
pub struct CodesysTable2d {
    /// The pairs; only master and slave are written, the derivatives are ignored.
    points: Vec<CamPoint>,
    /// The eight scaling fields written with the table.
    scaling: CodesysScaling,
}

impl CodesysTable2d {
    /// `count` equidistant samples of `curve`, both ends included.
    pub fn from_curve(curve: &dyn CamCurve, count: usize) -> Result<Self, TableError> {
        check_count(count, CODESYS_MAX_ELEMENTS, CODESYS_SYSTEM)?;
        Self::from_points(&sample_equidistant(curve, count)?)
    }

    /// The given points, which must be at least two, finite and strictly increasing in master.
    pub fn from_points(points: &[CamPoint]) -> Result<Self, TableError> {
        check_count(points.len(), CODESYS_MAX_ELEMENTS, CODESYS_SYSTEM)?;
        check_points(points)?;
        Ok(Self {
            points: points.to_vec(),
            scaling: CodesysScaling::technical_units(points),
        })
    }

    /// The points of the table.
    pub fn points(&self) -> &[CamPoint] {
        &self.points
    }

    /// The scaling fields written with the table.
    pub fn scaling(&self) -> &CodesysScaling {
        &self.scaling
    }

    /// The name of the structure type, `SMC_CAMTable_LREAL_<N>_2`.
    pub fn type_name(&self) -> String {
        format!("SMC_CAMTable_LREAL_{}_2", self.points.len())
    }

    /// Whether SM3_Basic already defines the type (N = 128 or 256), so the project needs no DUT.
    pub fn type_is_predefined(&self) -> bool {
        matches!(self.points.len(), 128 | 256)
    }

    /// The DUT declaring the structure type, for N that SM3_Basic does not define.
    pub fn type_declaration(&self) -> String {
        let table_type = format!(
            "ARRAY[0..{}] OF ARRAY[0..1] OF LREAL",
            self.points.len() - 1
        );
        table_type_declaration(&self.type_name(), &table_type)
    }

    /// A global variable list declaring `variable` with the table as its initial value.
    pub fn gvl(&self, variable: &str) -> Result<String, TableError> {
        check_identifier(variable)?;
        let rows = self
            .points
            .iter()
            .map(|p| format!("            [{}, {}]", st_real(p.master), st_real(p.slave)))
            .collect::<Vec<_>>()
            .join(",\n");
        Ok(format!(
            "VAR_GLOBAL\n    {variable} : {} := (\n        Table := [\n{rows}\n        ],\n{}\n    );\nEND_VAR\n",
            self.type_name(),
            self.scaling.st_assignments("        "),
        ))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;
    use crate::table::test_curve::Poly345;

    #[test]
    fn the_gvl_of_five_samples_matches_the_golden_text() {
        let table = CodesysTable2d::from_curve(&Poly345, 5).unwrap();
        assert_eq!(
            table.gvl("Cam_Table").unwrap(),
            "VAR_GLOBAL
    Cam_Table : SMC_CAMTable_LREAL_5_2 := (
        Table := [
            [0.0, 0.0],
            [90.0, 18.6328125],
            [180.0, 90.0],
            [270.0, 161.3671875],
            [360.0, 180.0]
        ],
        fEditorMasterMin := 0.0,
        fEditorMasterMax := 360.0,
        fEditorSlaveMin := 0.0,
        fEditorSlaveMax := 180.0,
        fTableMasterMin := 0.0,
        fTableMasterMax := 360.0,
        fTableSlaveMin := 0.0,
        fTableSlaveMax := 180.0
    );
END_VAR
"
        );
    }

    #[test]
    fn the_type_declaration_matches_the_golden_text() {
        let table = CodesysTable2d::from_curve(&Poly345, 5).unwrap();
        assert!(!table.type_is_predefined());
        assert_eq!(
            table.type_declaration(),
            "TYPE SMC_CAMTable_LREAL_5_2 :
STRUCT
    Table : ARRAY[0..4] OF ARRAY[0..1] OF LREAL;
    fEditorMasterMin : REAL;
    fEditorMasterMax : REAL;
    fEditorSlaveMin : REAL;
    fEditorSlaveMax : REAL;
    fTableMasterMin : REAL;
    fTableMasterMax : REAL;
    fTableSlaveMin : REAL;
    fTableSlaveMax : REAL;
END_STRUCT
END_TYPE
"
        );
    }

    #[test]
    fn sm3_basic_defines_the_128_and_256_element_types() {
        let table = CodesysTable2d::from_curve(&Poly345, 128).unwrap();
        assert!(table.type_is_predefined());
        assert_eq!(table.type_name(), "SMC_CAMTable_LREAL_128_2");
    }

    #[test]
    fn more_elements_than_an_int_counts_are_refused() {
        assert_eq!(
            CodesysTable2d::from_curve(&Poly345, 32_768)
                .unwrap_err()
                .to_string(),
            "CODESYS (nElements is an INT) holds at most 32767 points in one cam table, but 32768 were given"
        );
        assert_eq!(
            CodesysTable2d::from_curve(&Poly345, 32_767)
                .unwrap()
                .points()
                .len(),
            32_767
        );
    }

    #[test]
    fn a_variable_name_that_is_not_an_identifier_is_refused() {
        let table = CodesysTable2d::from_curve(&Poly345, 2).unwrap();
        assert_eq!(
            table.gvl("2nd cam").unwrap_err().to_string(),
            "\"2nd cam\" cannot be a variable name in Structured Text: use letters, digits and _, start with a letter or _, and do not use __ or end with _"
        );
    }
}

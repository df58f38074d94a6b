//! The CODESYS 1-D equidistant table `SMC_CAMTable_LREAL_<N>_1` (`docs/cam-formats.md` §3.3).

use super::TableError;
use super::number::{check_identifier, st_real};
use super::sampling::{CODESYS_MAX_ELEMENTS, check_count, sample_equidistant};
use super::scaling::{CodesysScaling, table_type_declaration};
use crate::curve::{CamCurve, CamPoint};

/// How many table values one line of the initialiser holds, so long tables stay readable.
const VALUES_PER_LINE: usize = 5;

/// Equidistant slave positions for a CODESYS `SMC_CAMTable_LREAL_<N>_1`, in technical units;
/// element 0 belongs to the master start and element N − 1 to the master end.
#[derive(Clone, Debug, PartialEq)]
pub struct CodesysTable1d {
    /// The sampled points; their master positions are implied by the table's position.
    points: Vec<CamPoint>,
    /// The eight scaling fields written with the table.
    scaling: CodesysScaling,
}

impl CodesysTable1d {
    /// `count` equidistant samples of `curve`, both ends included.
    pub fn from_curve(curve: &dyn CamCurve, count: usize) -> Result<Self, TableError> {
        check_count(count, CODESYS_MAX_ELEMENTS, "CODESYS (nElements is an INT)")?;
        let points = sample_equidistant(curve, count)?;
        let scaling = CodesysScaling::technical_units(&points);
        Ok(Self { points, scaling })
    }

    /// The sampled points, with the master position each table element belongs to.
    pub fn points(&self) -> &[CamPoint] {
        &self.points
    }

    /// The scaling fields written with the table.
    pub fn scaling(&self) -> &CodesysScaling {
        &self.scaling
    }

    /// The name of the structure type, `SMC_CAMTable_LREAL_<N>_1`.
    pub fn type_name(&self) -> String {
        format!("SMC_CAMTable_LREAL_{}_1", self.points.len())
    }

    /// Whether SM3_Basic already defines the type (N = 128 or 256), so the project needs no DUT.
    pub fn type_is_predefined(&self) -> bool {
        matches!(self.points.len(), 128 | 256)
    }

    /// The DUT declaring the structure type, for N that SM3_Basic does not define.
    pub fn type_declaration(&self) -> String {
        let table_type = format!("ARRAY[0..{}] OF LREAL", self.points.len() - 1);
        table_type_declaration(&self.type_name(), &table_type)
    }

    /// A global variable list declaring `variable` with the table as its initial value.
    pub fn gvl(&self, variable: &str) -> Result<String, TableError> {
        check_identifier(variable)?;
        let lines = self
            .points
            .chunks(VALUES_PER_LINE)
            .map(|chunk| {
                let values: Vec<String> = chunk.iter().map(|p| st_real(p.slave)).collect();
                format!("            {}", values.join(", "))
            })
            .collect::<Vec<_>>()
            .join(",\n");
        Ok(format!(
            "VAR_GLOBAL\n    {variable} : {} := (\n        Table := [\n{lines}\n        ],\n{}\n    );\nEND_VAR\n",
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
    fn the_gvl_of_nine_samples_matches_the_golden_text() {
        // Y(45) = 2.889404… is the value of the T6 example of the CODESYS manual.
        let table = CodesysTable1d::from_curve(&Poly345, 9).unwrap();
        assert_eq!(
            table.gvl("Cam_Table").unwrap(),
            "VAR_GLOBAL
    Cam_Table : SMC_CAMTable_LREAL_9_1 := (
        Table := [
            0.0, 2.889404296875, 18.6328125, 49.537353515625, 90.0,
            130.462646484375, 161.3671875, 177.110595703125, 180.0
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
        let table = CodesysTable1d::from_curve(&Poly345, 3).unwrap();
        assert_eq!(
            table.type_declaration(),
            "TYPE SMC_CAMTable_LREAL_3_1 :
STRUCT
    Table : ARRAY[0..2] OF LREAL;
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
        assert!(
            CodesysTable1d::from_curve(&Poly345, 256)
                .unwrap()
                .type_is_predefined()
        );
    }
}

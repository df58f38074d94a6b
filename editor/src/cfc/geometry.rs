//! Where an element is and where its pins are, in grid units, from its texts.
//!
//! Sizes come from the texts the element shows in the monospace font, measured as the LD/FBD
//! layouts measure theirs (`diagram::measure`), so the same chart has the same shape on every
//! machine. A single-pin element is one row (two grid units) high with its pin in the middle
//! of its left or right side; a box, composer or selector has a head row with its type and one
//! row per pin below it.

use project_model::{CfcElement, CfcElementKind, GridPoint};
use project_model::{cfc_input_pins, cfc_output_pins};

use super::router::GridRect;
use crate::diagram::measure::{BOX_LEAD_PX, box_cells, operand_width_px};

/// The size of a grid unit at zoom 1, in points.
pub const GRID_PX: f32 = 12.0;
/// The height of a row (a single-pin element, a box's head or one of its pins), in grid
/// units.
pub const ROW_UNITS: i32 = 2;
/// The narrowest element, in grid units.
const MIN_WIDTH_UNITS: i32 = 4;
/// The width of the cell the LD/FBD measure counts box widths in, in points.
const MEASURE_CELL_PX: f32 = 84.0;
/// The space left and right of a text inside its frame, in points.
const TEXT_PADDING_PX: f32 = 6.0;

/// An element's place on the grid and its pins.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ElementShape {
    /// The frame.
    pub rect: GridRect,
    /// The input pins, top to bottom, with the grid point each is at (on the left side).
    pub inputs: Vec<(String, GridPoint)>,
    /// The output pins, top to bottom, with the grid point each is at (on the right side).
    pub outputs: Vec<(String, GridPoint)>,
}

impl ElementShape {
    /// The grid point of the input pin `name`.
    pub fn input(&self, name: &str) -> Option<GridPoint> {
        self.inputs
            .iter()
            .find(|(pin, _)| pin == name)
            .map(|(_, at)| *at)
    }

    /// The grid point of the output pin `name`.
    pub fn output(&self, name: &str) -> Option<GridPoint> {
        self.outputs
            .iter()
            .find(|(pin, _)| pin == name)
            .map(|(_, at)| *at)
    }
}

/// The width in grid units of a frame around `text`.
fn text_units(text: &str) -> i32 {
    let px = operand_width_px(text) + 2.0 * TEXT_PADDING_PX;
    ((px / GRID_PX).ceil() as i32).max(MIN_WIDTH_UNITS)
}

/// The text an element shows in its frame (its head for a box, composer or selector).
pub fn element_title(kind: &CfcElementKind) -> &str {
    match kind {
        CfcElementKind::Input { expression } | CfcElementKind::Output { expression, .. } => {
            expression
        }
        CfcElementKind::Box(block) => &block.type_name,
        CfcElementKind::Jump { label } => label,
        CfcElementKind::Label { name }
        | CfcElementKind::ConnectionSource { name }
        | CfcElementKind::ConnectionSink { name } => name,
        CfcElementKind::Composer { type_name, .. } | CfcElementKind::Selector { type_name, .. } => {
            type_name
        }
        CfcElementKind::Comment { text, .. } => text,
        CfcElementKind::Return => "RETURN",
    }
}

/// The shape of `element`, moved by `offset` grid units (the drag in progress, or zero).
pub fn element_shape(element: &CfcElement, offset: GridPoint) -> ElementShape {
    let (x, y) = (element.x + offset.x, element.y + offset.y);
    let inputs = cfc_input_pins(&element.kind);
    let outputs = cfc_output_pins(&element.kind);
    let (width, height, first_pin_row) = match &element.kind {
        CfcElementKind::Comment { width, height, .. } => {
            ((*width as i32).max(1), (*height as i32).max(1), 0)
        }
        CfcElementKind::Box(_)
        | CfcElementKind::Composer { .. }
        | CfcElementKind::Selector { .. } => {
            let instance = match &element.kind {
                CfcElementKind::Box(block) => block.instance.as_str(),
                _ => "",
            };
            let cells = box_cells(
                element_title(&element.kind),
                instance,
                inputs.iter().copied(),
                outputs.iter().copied(),
                0.0,
            );
            let px = cells * MEASURE_CELL_PX - 2.0 * BOX_LEAD_PX;
            let width = ((px / GRID_PX).ceil() as i32).max(MIN_WIDTH_UNITS + 2);
            let rows = inputs.len().max(outputs.len()).max(1) as i32;
            (width, ROW_UNITS * (rows + 1), ROW_UNITS)
        }
        CfcElementKind::Jump { label } => (text_units(label) + 1, ROW_UNITS, 0),
        kind => (text_units(element_title(kind)), ROW_UNITS, 0),
    };
    let pin_at = |index: usize, column: i32| GridPoint {
        x: column,
        y: y + first_pin_row + ROW_UNITS * index as i32 + ROW_UNITS / 2,
    };
    ElementShape {
        rect: GridRect {
            left: x,
            top: y,
            right: x + width,
            bottom: y + height,
        },
        inputs: inputs
            .iter()
            .enumerate()
            .map(|(index, name)| ((*name).to_owned(), pin_at(index, x)))
            .collect(),
        outputs: outputs
            .iter()
            .enumerate()
            .map(|(index, name)| ((*name).to_owned(), pin_at(index, x + width)))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use project_model::{CfcBox, CfcPin, ElementId};

    use super::*;

    fn placed(kind: CfcElementKind) -> CfcElement {
        CfcElement {
            id: ElementId(0),
            x: 10,
            y: 20,
            order: None,
            kind,
        }
    }

    #[test]
    fn a_box_has_a_row_per_pin_under_its_head_and_grows_with_its_names() {
        let pins = |names: &[&str]| names.iter().map(|name| CfcPin::named(*name)).collect();
        let timer = placed(CfcElementKind::Box(CfcBox {
            type_name: "TON".to_owned(),
            instance: "t".to_owned(),
            inputs: pins(&["IN", "PT"]),
            outputs: pins(&["Q", "ET"]),
        }));
        let shape = element_shape(&timer, GridPoint::default());
        assert_eq!(shape.rect.top, 20);
        assert_eq!(shape.rect.bottom - shape.rect.top, 3 * ROW_UNITS);
        assert_eq!(shape.input("PT"), Some(GridPoint { x: 10, y: 25 }));
        assert_eq!(shape.output("Q").map(|p| p.x), Some(shape.rect.right));
        let mut long = timer.clone();
        if let CfcElementKind::Box(block) = &mut long.kind {
            block.type_name = "A_VERY_LONG_FUNCTION_BLOCK".to_owned();
        }
        assert!(element_shape(&long, GridPoint::default()).rect.right > shape.rect.right);
    }

    #[test]
    fn an_input_is_as_wide_as_its_expression_and_moves_with_the_offset() {
        let short = element_shape(
            &placed(CfcElementKind::Input {
                expression: "a".to_owned(),
            }),
            GridPoint::default(),
        );
        let long = element_shape(
            &placed(CfcElementKind::Input {
                expression: "GVL.motor_speed_setpoint".to_owned(),
            }),
            GridPoint { x: 1, y: 2 },
        );
        assert_eq!(short.rect.right - short.rect.left, MIN_WIDTH_UNITS);
        assert!(long.rect.right - long.rect.left > MIN_WIDTH_UNITS);
        assert_eq!(long.rect.left, 11);
        assert_eq!(
            long.output(""),
            Some(GridPoint {
                x: long.rect.right,
                y: 23
            })
        );
        assert!(short.inputs.is_empty());
    }
}

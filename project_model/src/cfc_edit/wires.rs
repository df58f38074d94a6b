//! Connecting and disconnecting pins, and the control points of a wire.

use super::{CfcEditError, element};
use crate::{CfcChart, CfcElementKind, GridPoint, PinRef, Wire};
use crate::{cfc_input_pins, cfc_output_pins};

/// Wires the output pin `from` to the input pin `to`. A wire already driving `to` is
/// replaced (as in CODESYS); a wire from an element to itself is allowed only on a box, where
/// it is a feedback.
pub fn connect(chart: &CfcChart, from: &PinRef, to: &PinRef) -> Result<CfcChart, CfcEditError> {
    let source = element(chart, from.element)?;
    if !cfc_output_pins(&source.kind).contains(&from.pin.as_str()) {
        return Err(CfcEditError::NotAnOutput(from.clone()));
    }
    let target = element(chart, to.element)?;
    if !cfc_input_pins(&target.kind).contains(&to.pin.as_str()) {
        return Err(CfcEditError::NotAnInput(to.clone()));
    }
    if from.element == to.element && !matches!(source.kind, CfcElementKind::Box(_)) {
        return Err(CfcEditError::SelfConnection(from.element));
    }
    let mut chart = chart.clone();
    chart.wires.retain(|wire| wire.to != *to);
    chart.wires.push(Wire::routed(from.clone(), to.clone()));
    Ok(chart)
}

/// Removes the wire that drives the input pin `to`.
pub fn disconnect(chart: &CfcChart, to: &PinRef) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let before = chart.wires.len();
    chart.wires.retain(|wire| wire.to != *to);
    if chart.wires.len() == before {
        return Err(CfcEditError::NoWire(to.clone()));
    }
    Ok(chart)
}

/// The wire into `to`, to change.
fn wire_mut<'a>(chart: &'a mut CfcChart, to: &PinRef) -> Result<&'a mut Wire, CfcEditError> {
    chart
        .wires
        .iter_mut()
        .find(|wire| wire.to == *to)
        .ok_or_else(|| CfcEditError::NoWire(to.clone()))
}

/// Puts a control point at `point` into the wire driving `to`, as its `index`th point
/// (clamped to the end).
pub fn add_control_point(
    chart: &CfcChart,
    to: &PinRef,
    index: usize,
    point: GridPoint,
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let wire = wire_mut(&mut chart, to)?;
    let index = index.min(wire.points.len());
    wire.points.insert(index, point);
    Ok(chart)
}

/// Moves the `index`th control point of the wire driving `to` to `point`.
pub fn move_control_point(
    chart: &CfcChart,
    to: &PinRef,
    index: usize,
    point: GridPoint,
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let wire = wire_mut(&mut chart, to)?;
    let slot = wire
        .points
        .get_mut(index)
        .ok_or_else(|| CfcEditError::NoControlPoint {
            to: to.clone(),
            index,
        })?;
    *slot = point;
    Ok(chart)
}

/// Removes the `index`th control point of the wire driving `to`.
pub fn remove_control_point(
    chart: &CfcChart,
    to: &PinRef,
    index: usize,
) -> Result<CfcChart, CfcEditError> {
    let mut chart = chart.clone();
    let wire = wire_mut(&mut chart, to)?;
    if index >= wire.points.len() {
        return Err(CfcEditError::NoControlPoint {
            to: to.clone(),
            index,
        });
    }
    wire.points.remove(index);
    Ok(chart)
}

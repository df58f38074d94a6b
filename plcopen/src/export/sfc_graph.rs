//! SFC charts as PLCopen SFC bodies in Beremiz's form (`docs/plcopen-xml.md` §5.2): steps,
//! transitions with their condition inline in ST or as a reference to a transition object,
//! selection and simultaneous divergences and convergences with their branches left to right,
//! jump steps, macro steps with their body, an action block per step with actions, and what
//! PLCopen has no attribute for (minimum and maximum times, CODESYS's entry, step and exit
//! actions, the step's comment) in the step's `…/step` entry.

use project_model::{SfcBranches, SfcChart, SfcNode, Step, Transition, same_identifier};

use super::error::ExportError;
use super::xml_writer::XmlWriter;
use crate::rivet_data::{RIVET_NAMESPACE, STEP_ENTRY};

/// Grid units between two columns and two rows (positions are grid units × 10).
const COLUMN_WIDTH: i64 = 20;
const ROW_HEIGHT: i64 = 8;

/// The writer of one SFC body.
pub(super) struct SfcGraph<'x, 'n> {
    xml: &'x mut XmlWriter,
    /// The names of the POU's transition objects, which a condition may name.
    transitions: &'n [String],
    /// The next fresh `localId`.
    next_id: u64,
    /// The next free column for a branch.
    next_column: i64,
}

impl<'x, 'n> SfcGraph<'x, 'n> {
    /// A writer of `chart` into `xml`.
    pub fn new(xml: &'x mut XmlWriter, chart: &SfcChart, transitions: &'n [String]) -> Self {
        Self {
            xml,
            transitions,
            next_id: max_id(&chart.sequence) + 1,
            next_column: 1,
        }
    }

    /// Writes the chart's objects (inside the `SFC` element).
    pub fn write(&mut self, chart: &SfcChart) -> Result<(), ExportError> {
        self.sequence(&chart.sequence, Vec::new(), 0, 0, true)?;
        Ok(())
    }

    /// Writes a sequence fed by `input` at `column` from `row`; gives the ids its end feeds on
    /// from (none after a jump) and the row after it.
    fn sequence(
        &mut self,
        nodes: &[SfcNode],
        mut input: Vec<u64>,
        column: i64,
        mut row: i64,
        initial: bool,
    ) -> Result<(Vec<u64>, i64), ExportError> {
        for (index, node) in nodes.iter().enumerate() {
            match node {
                SfcNode::Step(step) => {
                    input = vec![self.step(step, &input, column, row, initial && index == 0)?];
                    row += 1;
                }
                SfcNode::Transition(transition) => {
                    input = vec![self.transition(transition, &input, column, row)?];
                    row += 1;
                }
                SfcNode::Jump(jump) => {
                    let id = jump.id.0.to_string();
                    self.xml.start(
                        "jumpStep",
                        &[("localId", &id), ("targetName", &jump.target)],
                    )?;
                    self.position(column, row)?;
                    self.connection_in(&input)?;
                    self.xml.end("jumpStep")?;
                    input = Vec::new();
                    row += 1;
                }
                SfcNode::Macro(macro_step) => {
                    let id = u64::from(macro_step.id.0);
                    let id_text = id.to_string();
                    self.xml.start(
                        "macroStep",
                        &[("localId", &id_text), ("name", &macro_step.name)],
                    )?;
                    self.position(column, row)?;
                    self.connection_in(&input)?;
                    self.xml.empty("connectionPointOut", &[])?;
                    self.xml.start("body", &[])?;
                    self.xml.start("SFC", &[])?;
                    self.sequence(&macro_step.body, Vec::new(), 0, 0, false)?;
                    self.xml.end("SFC")?;
                    self.xml.end("body")?;
                    documentation(self.xml, &macro_step.comment)?;
                    self.xml.end("macroStep")?;
                    input = vec![id];
                    row += 1;
                }
                SfcNode::Alternative(branches) => {
                    (input, row) = self.branches(branches, &input, column, row, false)?;
                }
                SfcNode::Parallel(branches) => {
                    (input, row) = self.branches(branches, &input, column, row, true)?;
                }
            }
        }
        Ok((input, row))
    }

    /// Writes a divergence, its branches left to right and, when a branch goes on, the
    /// convergence where they meet again.
    fn branches(
        &mut self,
        branches: &SfcBranches,
        input: &[u64],
        column: i64,
        row: i64,
        simultaneous: bool,
    ) -> Result<(Vec<u64>, i64), ExportError> {
        let (divergence, convergence) = if simultaneous {
            ("simultaneousDivergence", "simultaneousConvergence")
        } else {
            ("selectionDivergence", "selectionConvergence")
        };
        let id = u64::from(branches.id.0);
        self.xml
            .start(divergence, &[("localId", &id.to_string())])?;
        self.position(column, row)?;
        self.connection_in(input)?;
        for _ in &branches.branches {
            self.xml
                .empty("connectionPointOut", &[("formalParameter", "")])?;
        }
        self.xml.end(divergence)?;
        let mut ends = Vec::new();
        let mut last_row = row + 1;
        for (index, branch) in branches.branches.iter().enumerate() {
            let branch_column = if index == 0 {
                column
            } else {
                let next = self.next_column.max(column + 1);
                self.next_column = next + 1;
                next
            };
            let (end, after) =
                self.sequence(&branch.nodes, vec![id], branch_column, row + 1, false)?;
            last_row = last_row.max(after);
            if !end.is_empty() {
                ends.push(end);
            }
        }
        if ends.is_empty() {
            return Ok((Vec::new(), last_row));
        }
        let joined = self.fresh();
        self.xml
            .start(convergence, &[("localId", &joined.to_string())])?;
        self.position(column, last_row)?;
        for end in &ends {
            self.connection_in(end)?;
        }
        self.xml.empty("connectionPointOut", &[])?;
        self.xml.end(convergence)?;
        Ok((vec![joined], last_row + 1))
    }

    fn step(
        &mut self,
        step: &Step,
        input: &[u64],
        column: i64,
        row: i64,
        initial: bool,
    ) -> Result<u64, ExportError> {
        let id = u64::from(step.id.0);
        let id_text = id.to_string();
        let mut attributes = vec![("localId", id_text.as_str()), ("name", step.name.as_str())];
        if initial {
            attributes.push(("initialStep", "true"));
        }
        self.xml.start("step", &attributes)?;
        self.position(column, row)?;
        if !input.is_empty() {
            self.connection_in(input)?;
        }
        self.xml
            .empty("connectionPointOut", &[("formalParameter", "")])?;
        if !step.actions.is_empty() {
            self.xml
                .empty("connectionPointOutAction", &[("formalParameter", "")])?;
        }
        let details = [
            ("minTime", step.min_time.as_deref()),
            ("maxTime", step.max_time.as_deref()),
            ("entryAction", step.entry_action.as_deref()),
            ("mainAction", step.main_action.as_deref()),
            ("exitAction", step.exit_action.as_deref()),
            (
                "comment",
                Some(step.comment.as_str()).filter(|comment| !comment.is_empty()),
            ),
        ];
        if details.iter().any(|(_, value)| value.is_some()) {
            let mut attributes = vec![("xmlns", RIVET_NAMESPACE)];
            attributes.extend(
                details
                    .iter()
                    .filter_map(|(name, value)| value.map(|value| (*name, value))),
            );
            self.xml.start("addData", &[])?;
            self.xml.start(
                "data",
                &[("name", STEP_ENTRY), ("handleUnknown", "preserve")],
            )?;
            self.xml.empty("step", &attributes)?;
            self.xml.end("data")?;
            self.xml.end("addData")?;
        }
        self.xml.end("step")?;
        if !step.actions.is_empty() {
            let block = self.fresh();
            self.xml
                .start("actionBlock", &[("localId", &block.to_string())])?;
            self.position(column + 1, row)?;
            self.connection_in(&[id])?;
            for association in &step.actions {
                let mut attributes = vec![
                    ("localId", "0"),
                    ("qualifier", association.qualifier.as_str()),
                ];
                if let Some(duration) = &association.duration {
                    attributes.push(("duration", duration));
                }
                if let Some(indicator) = &association.indicator {
                    attributes.push(("indicator", indicator));
                }
                self.xml.start("action", &attributes)?;
                self.xml.empty("relPosition", &[("x", "0"), ("y", "0")])?;
                self.xml
                    .empty("reference", &[("name", &association.action)])?;
                self.xml.end("action")?;
            }
            self.xml.end("actionBlock")?;
        }
        Ok(id)
    }

    fn transition(
        &mut self,
        transition: &Transition,
        input: &[u64],
        column: i64,
        row: i64,
    ) -> Result<u64, ExportError> {
        let id = u64::from(transition.id.0);
        let id_text = id.to_string();
        let priority = transition.priority.map(|priority| priority.to_string());
        let mut attributes = vec![("localId", id_text.as_str())];
        if let Some(priority) = &priority {
            attributes.push(("priority", priority));
        }
        self.xml.start("transition", &attributes)?;
        self.position(column, row)?;
        self.connection_in(input)?;
        self.xml.empty("connectionPointOut", &[])?;
        self.xml.start("condition", &[])?;
        let condition = transition.condition.trim();
        let named = self
            .transitions
            .iter()
            .any(|name| same_identifier(name, condition));
        if named {
            self.xml.empty("reference", &[("name", condition)])?;
        } else {
            self.xml.start("inline", &[("name", "")])?;
            self.xml.start("ST", &[])?;
            self.xml.start("xhtml:p", &[])?;
            self.xml.cdata(&transition.condition)?;
            self.xml.end("xhtml:p")?;
            self.xml.end("ST")?;
            self.xml.end("inline")?;
        }
        self.xml.end("condition")?;
        documentation(self.xml, &transition.comment)?;
        self.xml.end("transition")?;
        Ok(id)
    }

    fn connection_in(&mut self, input: &[u64]) -> Result<(), ExportError> {
        self.xml.start("connectionPointIn", &[])?;
        for id in input {
            self.xml
                .empty("connection", &[("refLocalId", &id.to_string())])?;
        }
        self.xml.end("connectionPointIn")
    }

    fn position(&mut self, column: i64, row: i64) -> Result<(), ExportError> {
        let x = (column * COLUMN_WIDTH * 10).to_string();
        let y = (row * ROW_HEIGHT * 10).to_string();
        self.xml.empty("position", &[("x", &x), ("y", &y)])
    }

    fn fresh(&mut self) -> u64 {
        let id = self.next_id;
        self.next_id += 1;
        id
    }
}

/// Writes `documentation` with `text`, unless it is empty.
fn documentation(xml: &mut XmlWriter, text: &str) -> Result<(), ExportError> {
    if text.is_empty() {
        return Ok(());
    }
    xml.start("documentation", &[])?;
    xml.start("xhtml:p", &[])?;
    xml.cdata(text)?;
    xml.end("xhtml:p")?;
    xml.end("documentation")
}

/// The largest element id of a sequence and everything in it.
fn max_id(nodes: &[SfcNode]) -> u64 {
    nodes
        .iter()
        .map(|node| match node {
            SfcNode::Step(step) => u64::from(step.id.0),
            SfcNode::Transition(transition) => u64::from(transition.id.0),
            SfcNode::Jump(jump) => u64::from(jump.id.0),
            SfcNode::Macro(macro_step) => u64::from(macro_step.id.0).max(max_id(&macro_step.body)),
            SfcNode::Alternative(branches) | SfcNode::Parallel(branches) => branches
                .branches
                .iter()
                .map(|branch| max_id(&branch.nodes))
                .fold(u64::from(branches.id.0), u64::max),
        })
        .max()
        .unwrap_or(0)
}

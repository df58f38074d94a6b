//! Code generation for one body: the generator's state, temporaries, places and statements.
//! Expressions are in `expr.rs`, calls in `call.rs` and `std_call.rs`.

use std::collections::HashMap;
use std::rc::Rc;

use program_image::{Elementary as IE, Instr, LineEntry, Operand};
use project_model::{Pou, Variable};

use super::error::{CodegenError, fail};
use super::layout::{Instance, Lay, LayShape};
use super::program::Build;
use crate::origin::Origin;
use crate::sema::scope::Scope;
use crate::sema::ty::Type;
use crate::syntax::SyntaxNode;
use crate::syntax::ast::{
    AstNode, CaseLabel, CaseStmt, Expr, ForStmt, IfStmt, StatementList, Stmt,
};

/// A result of code generation: an error saying what cannot be compiled, and where.
pub(crate) type Gen<T> = Result<T, CodegenError>;

/// Where a value is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    /// At an operand.
    Direct(Operand),
    /// Where the pointer held at the operand points.
    Indirect(Operand),
    /// One bit of a value of type `ty` at the operand (located BOOLs, `x.3`).
    Bit { operand: Operand, ty: IE, bit: u8 },
    /// One bit of a value of type `ty` where the pointer held at the operand points
    /// (`p^.3`, `r.%X1` with `r : REFERENCE TO WORD`): read by loading the value, written by
    /// loading, setting the bit and storing the value back.
    PointedBit { pointer: Operand, ty: IE, bit: u8 },
    /// An element, or a member of an element, of an array at a direct place, indexed by one
    /// value only known when the code runs (`a[i]`, `a[i].x`, `s[i]` of a STRING): read with
    /// `LoadElement` and written with `StoreElement` when it is elementary, and reached through
    /// the pointer `Address` and `Element` give when its address is needed
    /// (`docs/native-engine.md` §10).
    Element(ElementPlace),
}

/// Where an element of an array at a direct place is, with the bounds its index is checked
/// against: the fields of `Instr::LoadElement` and `Instr::StoreElement`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct ElementPlace {
    /// The array's first element.
    pub(crate) array: Operand,
    /// The index, of type `index_ty`.
    pub(crate) index: Operand,
    /// The integer type of the index.
    pub(crate) index_ty: IE,
    /// The lowest index.
    pub(crate) low: i64,
    /// The number of elements.
    pub(crate) count: u64,
    /// Bytes per element.
    pub(crate) stride: u32,
    /// Bytes from the element's start to the place (a member of a structure element).
    pub(crate) offset: u32,
}

/// A place with its type.
#[derive(Clone, Debug)]
pub(crate) struct Typed {
    pub(crate) place: Place,
    pub(crate) ty: Type,
    pub(crate) lay: Lay,
}

/// A variable in the frame of a function, method or body (VAR_TEMP).
#[derive(Clone, Debug)]
pub(crate) struct FrameVar {
    pub(crate) offset: u32,
    pub(crate) ty: Type,
    pub(crate) lay: Lay,
    pub(crate) by_ref: bool,
}

/// The frame layout of a function, method or body: its own variables and result.
#[derive(Clone, Debug, Default)]
pub(crate) struct Frame<'p> {
    pub(crate) vars: Vec<(&'p Variable, FrameVar)>,
    pub(crate) result: Option<FrameVar>,
    /// Bytes taken by the variables and the result; temporaries follow.
    pub(crate) size: u32,
}

impl Frame<'_> {
    /// The variable `name` (any case).
    pub(crate) fn var(&self, name: &str) -> Option<&FrameVar> {
        self.vars
            .iter()
            .find(|(v, _)| v.name.eq_ignore_ascii_case(name))
            .map(|(_, fv)| fv)
    }
}

/// Jumps to patch at the end of a loop, and where CONTINUE goes.
struct Loop {
    exits: Vec<usize>,
    continues: Vec<usize>,
}

/// Generates the code of one body.
pub(crate) struct BodyGen<'b, 'g, 'p> {
    pub(crate) build: &'b mut Build<'g, 'p>,
    pub(crate) scope: Scope<'g, 'p>,
    pub(crate) pou: &'p Pou,
    pub(crate) types: crate::sema::expression_types::ExpressionTypes,
    /// The instance whose variables `Operand::Instance` addresses.
    pub(crate) instance: Option<Rc<Instance<'p>>>,
    pub(crate) frame: Frame<'p>,
    pub(crate) code: Vec<Instr>,
    pub(crate) lines: Vec<LineEntry>,
    temp_top: u32,
    pub(crate) frame_max: u32,
    loops: Vec<Loop>,
    file: u32,
    line_starts: Vec<usize>,
    /// Lines of the file before the body's first line.
    line_offset: u32,
    /// Set while resolving the target of `REF=`: references are not followed.
    pub(crate) raw_references: bool,
    /// Every instruction index some jump goes to.
    jump_targets: std::collections::HashSet<u32>,
    /// Labels by lower-case name, and the jumps waiting for them.
    labels: HashMap<String, u32>,
    jumps: Vec<(usize, String)>,
}

/// The lower-case name of a label or of the label a JMP names.
fn label_name(name: Option<String>) -> Gen<String> {
    name.map(|name| name.to_lowercase())
        .ok_or_else(|| "a label without a name".into())
}

impl<'b, 'g, 'p> BodyGen<'b, 'g, 'p> {
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        build: &'b mut Build<'g, 'p>,
        scope: Scope<'g, 'p>,
        pou: &'p Pou,
        types: crate::sema::expression_types::ExpressionTypes,
        instance: Option<Rc<Instance<'p>>>,
        frame: Frame<'p>,
        file: u32,
        text: &str,
        line_offset: u32,
    ) -> Self {
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(at, _)| at + 1));
        let temp_top = frame.size.next_multiple_of(8);
        Self {
            build,
            scope,
            pou,
            types,
            instance,
            frame,
            code: Vec::new(),
            lines: Vec::new(),
            temp_top,
            frame_max: temp_top,
            loops: Vec::new(),
            file,
            line_starts,
            line_offset,
            raw_references: false,
            jump_targets: std::collections::HashSet::new(),
            labels: HashMap::new(),
            jumps: Vec::new(),
        }
    }

    /// Makes temporaries start at the frame offset `offset`: a breakpoint condition keeps
    /// them in its scratch area after the POU's frame, where the POU's own are not touched.
    pub(crate) fn start_temporaries_at(&mut self, offset: u32) {
        self.temp_top = offset;
        self.frame_max = self.frame_max.max(offset);
    }

    /// Emits an instruction and returns its index.
    pub(crate) fn emit(&mut self, instr: Instr) -> usize {
        if let Instr::Jump { target }
        | Instr::JumpIf { target, .. }
        | Instr::JumpIfNot { target, .. } = &instr
        {
            self.jump_targets.insert(*target);
        }
        self.code.push(instr);
        self.code.len() - 1
    }

    /// The index the next instruction will have.
    pub(crate) fn here(&self) -> u32 {
        self.code.len() as u32
    }

    /// Points the jump at `at` to `target`.
    pub(crate) fn patch(&mut self, at: usize, target: u32) {
        match &mut self.code[at] {
            Instr::Jump { target: t }
            | Instr::JumpIf { target: t, .. }
            | Instr::JumpIfNot { target: t, .. } => *t = target,
            _ => {}
        }
        self.jump_targets.insert(target);
    }

    /// Makes the last instruction write `dst` instead of the temporary `src`, when that
    /// instruction computed `src` as a value of `ty` and nothing jumps past it: then
    /// `x := a + b` is one instruction rather than an operation and a move.
    pub(crate) fn retarget_last(&mut self, dst: Operand, src: Operand, ty: IE) -> bool {
        let Operand::Frame(offset) = src else {
            return false;
        };
        // Only temporaries, never a function's own variables.
        if offset < self.frame.size || self.jump_targets.contains(&self.here()) {
            return false;
        }
        let Some(last) = self.code.last_mut() else {
            return false;
        };
        let (written, result_ty) = match last {
            Instr::Binary { dst, ty, .. }
            | Instr::Unary { dst, ty, .. }
            | Instr::Move { dst, ty, .. } => (dst, *ty),
            Instr::Compare { dst, .. } => (dst, IE::Bool),
            Instr::Convert { dst, to, .. } | Instr::Trunc { dst, to, .. } => (dst, *to),
            Instr::LoadElement { dst, ty, .. } => (dst, *ty),
            _ => return false,
        };
        if *written != src || result_ty != ty {
            return false;
        }
        *written = dst;
        true
    }

    /// A frame temporary of `size` bytes, alive until the statement ends.
    pub(crate) fn temp(&mut self, size: u32) -> Operand {
        let at = self.temp_top;
        self.temp_top = (at + size.max(1)).next_multiple_of(8);
        self.frame_max = self.frame_max.max(self.temp_top);
        Operand::Frame(at)
    }

    /// The checker's type of an expression.
    pub(crate) fn type_of(&self, node: &Expr) -> Type {
        self.types
            .get(node.syntax())
            .cloned()
            .unwrap_or(Type::Error)
    }

    /// Generates every statement under `root`.
    pub(crate) fn body(&mut self, root: &SyntaxNode) -> Gen<()> {
        if let Some(top) = super::sfc::top_level(root) {
            if top.steps().next().is_some() {
                self.chart(root)?;
            } else {
                self.statement_list(&top)?;
            }
        }
        // JMP goes to a label anywhere in the body, before or after it.
        for (at, name) in std::mem::take(&mut self.jumps) {
            let target = *self
                .labels
                .get(&name)
                .ok_or_else(|| fail!("JMP to '{name}', which is no label of this body"))?;
            self.patch(at, target);
        }
        Ok(())
    }

    /// Generates the statements of a list; a missing list (broken input) generates nothing.
    pub(crate) fn statement_list(&mut self, list: &StatementList) -> Gen<()> {
        for statement in list.statements() {
            self.statement_with_line(&statement)?;
        }
        Ok(())
    }

    fn optional_list(&mut self, list: Option<StatementList>) -> Gen<()> {
        match list {
            Some(list) => self.statement_list(&list),
            None => Ok(()),
        }
    }

    /// Generates one statement, with its line-table entry and its temporaries freed after it.
    pub(crate) fn statement_with_line(&mut self, statement: &Stmt) -> Gen<()> {
        let node = statement.syntax();
        let mark = self.temp_top;
        let line = self.line_of(node);
        let index = self.here();
        if self.lines.last().is_none_or(|last| last.line != line) {
            self.lines.push(LineEntry {
                index,
                file: self.file,
                line,
            });
        }
        let result = self
            .statement(statement)
            .map_err(|error| error.in_statement(line, Origin::of_node(node)));
        self.temp_top = mark;
        result
    }

    /// Records the next instruction as a statement start at `node`'s line, even when the entry
    /// before has the same line: an `ELSIF` condition, a loop's test and an SFC transition's
    /// test are places where the debugger halts (`docs/program-image.md` §11). When the entry
    /// before starts at the same instruction, its statement generated no code, so the
    /// instruction is this place's.
    pub(crate) fn mark_statement_start(&mut self, node: &SyntaxNode) {
        let line = self.line_of(node);
        self.mark_line_start(line);
    }

    /// Records the next instruction as a statement start at the line of the source's byte
    /// `offset`, as [`Self::mark_statement_start`] does for a node: an SFC step, known by its
    /// name's place, is a statement start where its active pass begins.
    pub(crate) fn mark_statement_start_at(&mut self, offset: usize) {
        let line = self.line_of_offset(offset);
        self.mark_line_start(line);
    }

    fn mark_line_start(&mut self, line: u32) {
        let index = self.here();
        match self.lines.last_mut() {
            Some(last) if last.index == index => last.line = line,
            _ => self.lines.push(LineEntry {
                index,
                file: self.file,
                line,
            }),
        }
    }

    fn line_of(&self, node: &SyntaxNode) -> u32 {
        let offset = usize::from(node.text_range().start());
        let trimmed = node
            .first_token()
            .map_or(offset, |t| usize::from(t.text_range().start()));
        self.line_of_offset(offset.max(trimmed))
    }

    fn line_of_offset(&self, offset: usize) -> u32 {
        self.line_starts.partition_point(|&start| start <= offset) as u32 + self.line_offset
    }

    fn statement(&mut self, statement: &Stmt) -> Gen<()> {
        match statement {
            Stmt::AssignStmt(assign) => match (assign.target(), assign.value()) {
                (Some(target), Some(value)) => self.assign(&target, &value),
                (Some(only), None) => self.call_statement(&only),
                _ => Ok(()),
            },
            Stmt::SetStmt(set) => self.set_or_reset(set.target(), set.value(), true),
            Stmt::ResetStmt(reset) => self.set_or_reset(reset.target(), reset.value(), false),
            Stmt::RefAssignStmt(assign) => {
                let (Some(target), Some(value)) = (assign.target(), assign.value()) else {
                    return Ok(());
                };
                self.raw_references = true;
                let slot = self.place(&target);
                self.raw_references = false;
                let mut slot = slot?;
                if self.may_run_code(&value) {
                    slot = self.settled(slot)?;
                }
                let pointer = self.address_of(&value)?;
                self.store(&slot, pointer)
            }
            Stmt::CallStmt(call) => match call.call() {
                Some(call) => self.call_statement(&Expr::CallExpr(call)),
                None => Ok(()),
            },
            Stmt::IfStmt(stmt) => self.if_statement(stmt),
            Stmt::CaseStmt(stmt) => self.case_statement(stmt),
            Stmt::ForStmt(stmt) => self.for_statement(stmt),
            Stmt::WhileStmt(stmt) => {
                // The back edge jumps to the test, which is where the statement starts.
                self.mark_statement_start(stmt.syntax());
                let start = self.here();
                let mut exit = None;
                self.loops.push(Loop {
                    exits: Vec::new(),
                    continues: Vec::new(),
                });
                if let Some(condition) = stmt.condition() {
                    let condition = self.expr_as(&condition, &Type::BOOL)?;
                    exit = Some(self.emit(Instr::JumpIfNot {
                        cond: condition,
                        target: 0,
                    }));
                }
                self.optional_list(stmt.body())?;
                self.emit(Instr::Jump { target: start });
                let end = self.here();
                let finished = self.loops.pop().unwrap_or(Loop {
                    exits: Vec::new(),
                    continues: Vec::new(),
                });
                for at in exit.into_iter().chain(finished.exits) {
                    self.patch(at, end);
                }
                for at in finished.continues {
                    self.patch(at, start);
                }
                Ok(())
            }
            Stmt::RepeatStmt(stmt) => {
                let start = self.here();
                self.loops.push(Loop {
                    exits: Vec::new(),
                    continues: Vec::new(),
                });
                let mut condition_at = start;
                self.optional_list(stmt.body())?;
                if let Some(condition) = stmt.condition() {
                    self.mark_statement_start(condition.syntax());
                    condition_at = self.here();
                    let condition = self.expr_as(&condition, &Type::BOOL)?;
                    self.emit(Instr::JumpIfNot {
                        cond: condition,
                        target: start,
                    });
                }
                let end = self.here();
                let finished = self.loops.pop().unwrap_or(Loop {
                    exits: Vec::new(),
                    continues: Vec::new(),
                });
                for at in finished.exits {
                    self.patch(at, end);
                }
                for at in finished.continues {
                    self.patch(at, condition_at);
                }
                Ok(())
            }
            Stmt::ExitStmt(_) | Stmt::ContinueStmt(_) => {
                let exit = matches!(statement, Stmt::ExitStmt(_));
                let at = self.emit(Instr::Jump { target: 0 });
                let Some(current) = self.loops.last_mut() else {
                    return Err(fail!(
                        "{} outside a loop",
                        if exit { "EXIT" } else { "CONTINUE" }
                    ));
                };
                if exit {
                    current.exits.push(at);
                } else {
                    current.continues.push(at);
                }
                Ok(())
            }
            Stmt::ReturnStmt(_) => {
                self.emit(Instr::Return);
                Ok(())
            }
            Stmt::EmptyStmt(_) => Ok(()),
            Stmt::LabelStmt(label) => {
                let name = label_name(label.name().map(|name| name.text()))?;
                let here = self.here();
                if self.labels.insert(name.clone(), here).is_some() {
                    return Err(fail!("the label '{name}' is declared twice"));
                }
                Ok(())
            }
            Stmt::JmpStmt(jump) => {
                let name = label_name(jump.label().map(|name| name.text()))?;
                let at = self.emit(Instr::Jump { target: 0 });
                self.jumps.push((at, name));
                Ok(())
            }
            Stmt::StepDecl(_) | Stmt::TransitionDecl(_) => {
                Err("SFC steps, transitions and actions belong at the top of a body".into())
            }
            Stmt::AttemptAssignStmt(_) => Err("cannot compile a ATTEMPT_ASSIGN_STMT".into()),
        }
    }

    /// `target S= value` (`set`) or `target R= value`: the target is written only when the
    /// value is TRUE.
    fn set_or_reset(&mut self, target: Option<Expr>, value: Option<Expr>, set: bool) -> Gen<()> {
        let (Some(target), Some(value)) = (target, value) else {
            return Ok(());
        };
        // The element's index is checked whether or not the value sets it, as it always was.
        let target = self.place(&target)?;
        let target = self.settled(target)?;
        let condition = self.expr_as(&value, &Type::BOOL)?;
        let skip = self.emit(Instr::JumpIfNot {
            cond: condition,
            target: 0,
        });
        let constant = self.build.constant(&[u8::from(set)]);
        self.store(&target, constant)?;
        let end = self.here();
        self.patch(skip, end);
        Ok(())
    }

    fn assign(&mut self, target: &Expr, value: &Expr) -> Gen<()> {
        if let Some((owner, property, instance)) = self.property_of(target)? {
            return self.property_set(owner, property, instance, value);
        }
        let mut target = self.place(target)?;
        if self.may_run_code(value) {
            target = self.settled(target)?;
        }
        let operand = self.expr_as(value, &target.ty)?;
        self.store(&target, operand)
    }

    fn call_statement(&mut self, node: &Expr) -> Gen<()> {
        match node {
            Expr::CallExpr(call) => self.call(call, None).map(|_| ()),
            // A bare name such as `Action;` or `fb;` is a call without arguments.
            Expr::NameExpr(_) | Expr::FieldExpr(_) => self.call_without_arguments(node),
            _ => self.expr(node, None).map(|_| ()),
        }
    }

    fn if_statement(&mut self, stmt: &IfStmt) -> Gen<()> {
        let mut ends = Vec::new();
        let mut pending: Option<usize> = None;
        let branches = std::iter::once((None, stmt.condition(), stmt.then_branch())).chain(
            stmt.elsif_branches().map(|branch| {
                (
                    Some(branch.syntax().clone()),
                    branch.condition(),
                    branch.body(),
                )
            }),
        );
        for (elsif, condition, body) in branches {
            if let Some(elsif) = &elsif {
                self.mark_statement_start(elsif);
            }
            if let Some(condition) = condition {
                let condition = self.expr_as(&condition, &Type::BOOL)?;
                pending = Some(self.emit(Instr::JumpIfNot {
                    cond: condition,
                    target: 0,
                }));
            }
            if let Some(body) = body {
                self.statement_list(&body)?;
                ends.push(self.emit(Instr::Jump { target: 0 }));
                if let Some(at) = pending.take() {
                    let next = self.here();
                    self.patch(at, next);
                }
            }
        }
        if let Some(branch) = stmt.else_branch() {
            self.optional_list(branch.body())?;
        }
        let end = self.here();
        if let Some(at) = pending {
            self.patch(at, end);
        }
        for at in ends {
            self.patch(at, end);
        }
        Ok(())
    }

    fn case_statement(&mut self, stmt: &CaseStmt) -> Gen<()> {
        let Some(selector) = stmt.selector() else {
            return Ok(());
        };
        let (value, ty) = self.expr(&selector, None)?;
        let scalar = self
            .scalar_of(&ty)
            .ok_or_else(|| fail!("a CASE selector of type {ty}"))?;
        // The selector is kept in a temporary so the branches cannot change it.
        let kept = self.temp(8);
        self.emit(Instr::Move {
            ty: scalar,
            dst: kept,
            src: value,
        });
        let mut ends = Vec::new();
        for branch in stmt.branches() {
            let mut matches = Vec::new();
            for label in branch.labels() {
                let hit = self.temp(1);
                match label {
                    CaseLabel::Range(range) => {
                        let (Some(low), Some(high)) = (range.low(), range.high()) else {
                            continue;
                        };
                        let low = self.expr_as(&low, &ty)?;
                        let high = self.expr_as(&high, &ty)?;
                        let above = self.temp(1);
                        self.emit(Instr::Compare {
                            op: program_image::CompareOp::Ge,
                            ty: scalar,
                            dst: above,
                            a: kept,
                            b: low,
                        });
                        self.emit(Instr::Compare {
                            op: program_image::CompareOp::Le,
                            ty: scalar,
                            dst: hit,
                            a: kept,
                            b: high,
                        });
                        self.emit(Instr::Binary {
                            op: program_image::BinaryOp::And,
                            ty: IE::Bool,
                            dst: hit,
                            a: hit,
                            b: above,
                        });
                    }
                    CaseLabel::Value(label) => {
                        let label = self.expr_as(&label, &ty)?;
                        self.emit(Instr::Compare {
                            op: program_image::CompareOp::Eq,
                            ty: scalar,
                            dst: hit,
                            a: kept,
                            b: label,
                        });
                    }
                }
                matches.push(self.emit(Instr::JumpIf {
                    cond: hit,
                    target: 0,
                }));
            }
            let skip = self.emit(Instr::Jump { target: 0 });
            let start = self.here();
            for at in matches {
                self.patch(at, start);
            }
            self.optional_list(branch.body())?;
            ends.push(self.emit(Instr::Jump { target: 0 }));
            let next = self.here();
            self.patch(skip, next);
        }
        if let Some(branch) = stmt.else_branch() {
            self.optional_list(branch.body())?;
        }
        let end = self.here();
        for at in ends {
            self.patch(at, end);
        }
        Ok(())
    }

    /// `FOR i := a TO b BY s`: the end and step are evaluated once, before the first
    /// iteration; after the loop `i` holds the first value past the end, as in CODESYS.
    fn for_statement(&mut self, stmt: &ForStmt) -> Gen<()> {
        let (Some(variable), Some(start), Some(end)) = (stmt.variable(), stmt.from(), stmt.to())
        else {
            return Err("a FOR loop needs a variable, a start and an end".into());
        };
        let step_node = stmt.by();
        // The counter's place is computed once for the whole loop, whatever the body does to
        // an index in it.
        let counter = self.place(&variable)?;
        let counter = self.settled(counter)?;
        let ty = counter.ty.clone();
        let scalar = self
            .scalar_of(&ty)
            .ok_or("the FOR variable must be an integer")?;
        let first = self.expr_as(&start, &ty)?;
        self.store(&counter, first)?;
        // The end and step are kept where the body cannot change them: a constant stays in
        // the pool, anything else is copied once.
        let end_value = self.expr_as(&end, &ty)?;
        let last = if matches!(end_value, Operand::Const(_)) {
            end_value
        } else {
            let kept = self.temp(8);
            self.emit(Instr::Move {
                ty: scalar,
                dst: kept,
                src: end_value,
            });
            kept
        };
        let step_value = match &step_node {
            Some(step_node) => self.expr_as(step_node, &ty)?,
            None => self.build.scalar_constant(1, scalar),
        };
        let constant_step = match &step_node {
            Some(step_node) => {
                match super::constant::evaluate_node(step_node, self.scope.globals) {
                    Some(super::constant::Value::Int(v)) => Some(v),
                    _ => None,
                }
            }
            None => Some(1),
        };
        let step = if matches!(step_value, Operand::Const(_)) {
            step_value
        } else {
            let kept = self.temp(8);
            self.emit(Instr::Move {
                ty: scalar,
                dst: kept,
                src: step_value,
            });
            kept
        };
        let top;
        let done = self.temp(1);
        if let Some(step) = constant_step {
            // A constant step has a known direction: one comparison an iteration. The test,
            // where the back edge jumps, is a statement start of the FOR line.
            self.mark_statement_start(stmt.syntax());
            top = self.here();
            let current = self.load(&counter)?;
            let op = if step < 0 {
                program_image::CompareOp::Lt
            } else {
                program_image::CompareOp::Gt
            };
            self.emit(Instr::Compare {
                op,
                ty: scalar,
                dst: done,
                a: current,
                b: last,
            });
        } else {
            let zero = self.build.scalar_constant(0, scalar);
            let negative = self.temp(1);
            self.emit(Instr::Compare {
                op: program_image::CompareOp::Lt,
                ty: scalar,
                dst: negative,
                a: step,
                b: zero,
            });
            self.mark_statement_start(stmt.syntax());
            top = self.here();
            let current = self.load(&counter)?;
            // Counting up ends past the end; counting down ends below it.
            let down = self.emit(Instr::JumpIf {
                cond: negative,
                target: 0,
            });
            self.emit(Instr::Compare {
                op: program_image::CompareOp::Gt,
                ty: scalar,
                dst: done,
                a: current,
                b: last,
            });
            let checked = self.emit(Instr::Jump { target: 0 });
            let down_at = self.here();
            self.patch(down, down_at);
            self.emit(Instr::Compare {
                op: program_image::CompareOp::Lt,
                ty: scalar,
                dst: done,
                a: current,
                b: last,
            });
            let after_check = self.here();
            self.patch(checked, after_check);
        }
        let exit = self.emit(Instr::JumpIf {
            cond: done,
            target: 0,
        });
        self.loops.push(Loop {
            exits: Vec::new(),
            continues: Vec::new(),
        });
        self.optional_list(stmt.body())?;
        let finished = self.loops.pop().unwrap_or(Loop {
            exits: Vec::new(),
            continues: Vec::new(),
        });
        let increment = self.here();
        let current = self.load(&counter)?;
        let next = self.temp(8);
        self.emit(Instr::Binary {
            op: program_image::BinaryOp::Add,
            ty: scalar,
            dst: next,
            a: current,
            b: step,
        });
        self.store(&counter, next)?;
        self.emit(Instr::Jump { target: top });
        let end_at = self.here();
        self.patch(exit, end_at);
        for at in finished.exits {
            self.patch(at, end_at);
        }
        for at in finished.continues {
            self.patch(at, increment);
        }
        Ok(())
    }

    /// The instruction type of a scalar type: elementary types, subranges and enumerations.
    pub(crate) fn scalar_of(&mut self, ty: &Type) -> Option<IE> {
        match self.build.layouts.of(ty).ok()?.shape {
            LayShape::Scalar(e) | LayShape::Enum(e) => Some(e),
            _ => None,
        }
    }
}

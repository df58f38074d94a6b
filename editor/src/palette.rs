//! The colours the editors draw with beyond egui's visuals. The application fills an
//! [`EditorPalette`] from its theme and installs it in the egui context; without one the
//! editors fall back to colours taken from the visuals, so they never hold colour literals.

use egui::{Color32, Context, Id, Ui, Visuals};

/// The colours of Structured Text by what a token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SyntaxColors {
    /// Keywords (`IF`, `VAR`).
    pub keyword: Color32,
    /// Comments.
    pub comment: Color32,
    /// String literals.
    pub string: Color32,
    /// Number literals.
    pub number: Color32,
    /// Constants and enumeration values.
    pub constant: Color32,
    /// Type names.
    pub type_name: Color32,
    /// Function and function block names.
    pub function: Color32,
    /// Members and properties.
    pub property: Color32,
    /// Pragmas and attributes.
    pub attribute: Color32,
    /// Labels and direct addresses (`%IX0.0`).
    pub label: Color32,
}

/// The colours of the editors for one theme. It lives in the egui context's temporary data,
/// replaced whenever the application installs another, and is never saved.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct EditorPalette {
    /// Structured Text.
    pub syntax: SyntaxColors,
    /// The background of the find bar's matches.
    pub find_match: Color32,
    /// The background of an inline value that changed since the last reading.
    pub changed_value: Color32,
    /// The background of the `F` badge of a forced value.
    pub forced_fill: Color32,
    /// The letter of the `F` badge of a forced value.
    pub forced_text: Color32,
    /// Error marks.
    pub error: Color32,
    /// Warning marks.
    pub warning: Color32,
    /// Information marks.
    pub info: Color32,
    /// The declaration table's overlap warning mark.
    pub table_warning: Color32,
    /// Energised contacts, coils and lines of a diagram while online.
    pub power_on: Color32,
    /// The background of selected diagram elements.
    pub diagram_selection: Color32,
    /// The "+" marks where a dragged diagram element can go.
    pub insert_point: Color32,
    /// The fill of an active SFC step while online (CODESYS shows them blue).
    pub active_step: Color32,
    /// The name and time written on an active SFC step, readable on its fill.
    pub active_step_text: Color32,
    /// A breakpoint's circle (CODESYS draws them red).
    pub breakpoint: Color32,
    /// The bar or dot inside a conditional or counted breakpoint's circle.
    pub breakpoint_symbol: Color32,
    /// The arrow at a halted task's current statement (CODESYS draws it yellow).
    pub halt_marker: Color32,
    /// The outline of the halt arrow, so it shows on the breakpoint's red.
    pub halt_outline: Color32,
    /// The background of a halted task's current statement or element.
    pub halt_line: Color32,
    /// The flow-control marks of the statements that ran in the last cycle.
    pub flow_mark: Color32,
}

impl EditorPalette {
    /// The key the palette is kept under in the context.
    fn id() -> Id {
        Id::unique("editor::EditorPalette")
    }

    /// Makes `palette` the one the editors drawn in `ctx` use.
    pub fn install(ctx: &Context, palette: Self) {
        ctx.data_mut(|data| data.insert_temp(Self::id(), palette));
    }

    /// The installed palette, or one taken from the visuals of `ui`.
    pub fn of(ui: &Ui) -> Self {
        ui.ctx()
            .data(|data| data.get_temp::<Self>(Self::id()))
            .unwrap_or_else(|| Self::from_visuals(ui.visuals()))
    }

    /// The installed palette, or one taken from the visuals of `ctx`.
    pub fn in_context(ctx: &Context) -> Self {
        ctx.data(|data| data.get_temp::<Self>(Self::id()))
            .unwrap_or_else(|| Self::from_visuals(&ctx.global_style().visuals))
    }

    /// A palette made of egui's visuals, for editors drawn without an application theme.
    pub fn from_visuals(visuals: &Visuals) -> Self {
        let strong = visuals.strong_text_color();
        let weak = visuals.weak_text_color();
        let link = visuals.hyperlink_color;
        let warn = visuals.warn_fg_color;
        Self {
            syntax: SyntaxColors {
                keyword: link,
                comment: weak,
                string: warn,
                number: strong,
                constant: link,
                type_name: strong,
                function: strong,
                property: visuals.text_color(),
                attribute: weak,
                label: warn,
            },
            find_match: visuals.selection.bg_fill.gamma_multiply(0.5),
            changed_value: visuals.selection.bg_fill,
            forced_fill: visuals.error_fg_color,
            forced_text: visuals.extreme_bg_color,
            error: visuals.error_fg_color,
            warning: warn,
            info: link,
            table_warning: warn,
            power_on: link,
            diagram_selection: visuals.selection.bg_fill.gamma_multiply(0.6),
            insert_point: visuals.warn_fg_color,
            active_step: link.gamma_multiply(0.6),
            active_step_text: visuals.strong_text_color(),
            breakpoint: visuals.error_fg_color,
            breakpoint_symbol: visuals.extreme_bg_color,
            halt_marker: warn,
            halt_outline: strong,
            halt_line: warn.gamma_multiply(0.3),
            flow_mark: link,
        }
    }
}

//! The words the CFC editor shows, so the app can give them in the user's language.

/// The user-visible words of the CFC editor. The default is English (for tests and
/// benchmarks); the app sets its translation with [`super::CfcEditor::set_texts`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CfcTexts {
    /// The toolbox's heading.
    pub toolbox: String,
    /// The toolbox's input.
    pub input: String,
    /// The toolbox's output.
    pub output: String,
    /// The toolbox's box.
    pub block: String,
    /// The toolbox's jump.
    pub jump: String,
    /// The toolbox's label.
    pub label: String,
    /// The toolbox's return.
    pub return_: String,
    /// The toolbox's composer.
    pub composer: String,
    /// The toolbox's selector.
    pub selector: String,
    /// The toolbox's comment.
    pub comment: String,
    /// The toolbox's connection mark (source).
    pub connection_source: String,
    /// The toolbox's connection mark (sink).
    pub connection_sink: String,
    /// The toolbox's input pin (extends a box).
    pub input_pin: String,
    /// The toolbox's control point.
    pub control_point: String,
    /// The toggle and menu entry that shows the execution order numbers.
    pub display_execution_order: String,
    /// The context menu's execution order submenu.
    pub execution_order: String,
    /// Send to Front.
    pub send_to_front: String,
    /// Send to Back.
    pub send_to_back: String,
    /// Move Up.
    pub move_up: String,
    /// Move Down.
    pub move_down: String,
    /// Set Execution Order….
    pub set_execution_order: String,
    /// Order by Data Flow.
    pub order_by_data_flow: String,
    /// Order by Topology.
    pub order_by_topology: String,
    /// The context menu's negation of a pin.
    pub negate: String,
    /// The context menu's rising edge on an input pin.
    pub rising_edge: String,
    /// The context menu's falling edge on an input pin.
    pub falling_edge: String,
    /// The context menu's removal of an edge from an input pin.
    pub no_edge: String,
    /// The context menu's set output.
    pub set_output: String,
    /// The context menu's reset output.
    pub reset_output: String,
    /// The context menu's plain output.
    pub plain_output: String,
    /// The context menu's removal of a control point.
    pub remove_control_point: String,
    /// The context menu's deletion.
    pub delete: String,
    /// Shown for an empty text that can be typed in.
    pub placeholder: String,
    /// The accessible label of the field over an input or output.
    pub expression_field: String,
    /// The accessible label of the field where a box's type is typed.
    pub block_type_field: String,
    /// The accessible label of the field where a box's instance is typed.
    pub instance_field: String,
    /// The accessible label of the field of a name (label, jump, connection mark, type).
    pub name_field: String,
    /// The accessible label of the field of a comment.
    pub comment_field: String,
    /// The accessible label of the field where an execution order number is typed.
    pub order_field: String,
    /// The label of the field where a value is prepared for writing or forcing.
    pub prepared_value: String,
    /// The zoom percentage's tooltip.
    pub zoom: String,
    /// The context menu's entry that sets or clears the breakpoint of the selected element.
    pub toggle_breakpoint: String,
}

impl Default for CfcTexts {
    fn default() -> Self {
        let text = |words: &str| words.to_owned();
        Self {
            toolbox: text("Toolbox"),
            input: text("Input"),
            output: text("Output"),
            block: text("Box"),
            jump: text("Jump"),
            label: text("Label"),
            return_: text("Return"),
            composer: text("Composer"),
            selector: text("Selector"),
            comment: text("Comment"),
            connection_source: text("Connection mark (source)"),
            connection_sink: text("Connection mark (sink)"),
            input_pin: text("Input pin"),
            control_point: text("Control point"),
            display_execution_order: text("Display Execution Order"),
            execution_order: text("Execution Order"),
            send_to_front: text("Send to Front"),
            send_to_back: text("Send to Back"),
            move_up: text("Move Up"),
            move_down: text("Move Down"),
            set_execution_order: text("Set Execution Order…"),
            order_by_data_flow: text("Order by Data Flow"),
            order_by_topology: text("Order by Topology"),
            negate: text("Negate"),
            rising_edge: text("Rising edge"),
            falling_edge: text("Falling edge"),
            no_edge: text("No edge"),
            set_output: text("Set output"),
            reset_output: text("Reset output"),
            plain_output: text("Plain output"),
            remove_control_point: text("Remove control point"),
            delete: text("Delete"),
            placeholder: text("???"),
            expression_field: text("Expression"),
            block_type_field: text("Box type"),
            instance_field: text("Instance"),
            name_field: text("Name"),
            comment_field: text("Comment"),
            order_field: text("Execution order"),
            prepared_value: text("Prepared value"),
            zoom: text("Zoom (Ctrl+wheel)"),
            toggle_breakpoint: text("Toggle breakpoint"),
        }
    }
}

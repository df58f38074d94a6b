//! The words of the device editors, so the app can show them in the user's language.
//! Templates hold `{name}`-style placeholders, as languages order the parts differently.

use super::refusal::RefusalWords;

/// Every word the controller, I/O area, serial port, Modbus device and axis editors show;
/// `Default` is English.
#[derive(Clone, Debug)]
pub struct DeviceTexts {
    /// Field: a node's name.
    pub name: String,
    /// Field: a host name or IP address.
    pub host: String,
    /// Field: a TCP port.
    pub port: String,
    /// The controller's note that the password is typed when logging in and never stored.
    pub password_note: String,
    /// Check box: the controller uses its own Modbus map instead of the default one.
    pub modbus_map_override: String,
    /// Note under the check box when the default map is used.
    pub default_map_note: String,
    /// Heading of the map's ranges.
    pub map_ranges: String,
    /// Column: a Modbus table.
    pub table: String,
    /// Column: the first Modbus address of a map range.
    pub start: String,
    /// Column: the number of coils or registers of a map range.
    pub count: String,
    /// Column: the located address a map range starts at.
    pub area_address: String,
    /// Button: add a map range.
    pub add_range: String,
    /// Field: the variable of a new channel, added when the field is left.
    pub new_channel: String,
    /// Button: delete a row.
    pub delete: String,
    /// Field: an I/O area's direction.
    pub direction: String,
    /// Field: an I/O area's first byte.
    pub start_byte: String,
    /// Field: an I/O area's size.
    pub size: String,
    /// The unit after a size: bytes.
    pub bytes: String,
    /// The unit after a time: milliseconds.
    pub milliseconds: String,
    /// Field and column: a comment.
    pub comment: String,
    /// Direction: inputs.
    pub inputs: String,
    /// Direction: outputs.
    pub outputs: String,
    /// Direction: markers.
    pub markers: String,
    /// Field: a Modbus unit identifier.
    pub unit_id: String,
    /// Field: the word order of wide values.
    pub word_order: String,
    /// Word order: high word first.
    pub high_first: String,
    /// Word order: low word first.
    pub low_first: String,
    /// Field: the poll interval.
    pub poll_interval: String,
    /// Undo label's value of an emptied poll interval: none.
    pub no_poll_interval: String,
    /// Field: the response timeout.
    pub timeout: String,
    /// Heading of a device's channel table.
    pub channels: String,
    /// Column: a channel's variable.
    pub variable: String,
    /// Column: a channel's address.
    pub address: String,
    /// Column: a channel's data type.
    pub data_type: String,
    /// Table: coils.
    pub coil: String,
    /// Table: discrete inputs.
    pub discrete_input: String,
    /// Table: holding registers.
    pub holding_register: String,
    /// Table: input registers.
    pub input_register: String,
    /// Field: an axis's kind.
    pub kind: String,
    /// Axis kind: virtual.
    pub virtual_axis: String,
    /// Field: the task that updates an axis.
    pub task: String,
    /// Field: the user unit.
    pub unit: String,
    /// Check box: the axis is rotary with a modulo period.
    pub modulo: String,
    /// Field: the modulo period.
    pub modulo_period: String,
    /// Check box: software limits are checked.
    pub software_limits: String,
    /// Field: the negative software limit.
    pub negative_limit: String,
    /// Field: the positive software limit.
    pub positive_limit: String,
    /// Field: the velocity limit.
    pub velocity: String,
    /// Field: the acceleration limit.
    pub acceleration: String,
    /// Field: the deceleration limit.
    pub deceleration: String,
    /// Field: the jerk limit.
    pub jerk: String,
    /// Field: drive increments of the scaling.
    pub increments: String,
    /// Field: user units of the scaling.
    pub units: String,
    /// Heading of the scaling fields.
    pub scaling: String,
    /// Field: the language rules the project is checked by (its dialect).
    pub dialect: String,
    /// Choice of the dialect: CODESYS V3.5's rules, with warnings.
    pub dialect_codesys: String,
    /// Choice of the dialect: IEC 61131-3 only.
    pub dialect_iec_strict: String,
    /// Note under the dialect: what it decides.
    pub dialect_note: String,
    /// Field: how a Modbus device is reached (TCP or a serial port).
    pub link: String,
    /// Link: Modbus TCP.
    pub link_tcp: String,
    /// Link: Modbus RTU on a serial port.
    pub link_rtu: String,
    /// Field: a Modbus RTU device's serial port.
    pub serial_port: String,
    /// Field: the task whose cycles copy a Modbus device's values (the runtime masters it).
    pub io_task: String,
    /// Choice of the I/O task: none, the studio polls the device.
    pub no_task: String,
    /// Note beside a studio device's task: what choosing a task does.
    pub studio_device_note: String,
    /// Field: when the runtime starts a round of a device.
    pub schedule: String,
    /// Schedule: a round every poll interval.
    pub schedule_interval: String,
    /// Schedule: a round after each cycle of the I/O task.
    pub schedule_every_cycle: String,
    /// Field: how many unused addresses a read request may bridge.
    pub max_read_gap: String,
    /// The unit after the read gap: coils or registers.
    pub addresses: String,
    /// Field: the device's `MODBUS_DEVICE_STATUS` variable.
    pub status_variable: String,
    /// Note after an optional field left empty.
    pub optional: String,
    /// How many requests a round of the device sends, for one: `{count}`.
    pub request_per_round: String,
    /// How many requests a round of the device sends: `{count}`.
    pub requests_per_round: String,
    /// Field: the requests of a round.
    pub round: String,
    /// Channel direction: read from the device.
    pub read: String,
    /// Channel direction: written to the device.
    pub write: String,
    /// Column: a write channel's function code.
    pub function_code: String,
    /// Function code: none chosen, the table's own (`{code}`).
    pub default_code: String,
    /// Function code 5.
    pub write_single_coil: String,
    /// Function code 15.
    pub write_multiple_coils: String,
    /// Function code 6.
    pub write_single_register: String,
    /// Function code 16.
    pub write_multiple_registers: String,
    /// Column: when a channel is sent or read.
    pub trigger: String,
    /// Trigger: in every round.
    pub cyclic: String,
    /// Trigger: on a rising edge of the trigger variable.
    pub rising_edge: String,
    /// Column: the BOOL whose rising edge triggers a channel.
    pub trigger_variable: String,
    /// The hint beside the trigger variable while "Rising edge" waits for one.
    pub trigger_variable_hint: String,
    /// Column: what a read channel's variable holds after a failed request.
    pub on_error: String,
    /// On error: the last value.
    pub keep_last_value: String,
    /// On error: zero.
    pub set_to_zero: String,
    /// Column: the BOOL that is TRUE while a channel's last request failed.
    pub error_flag: String,
    /// A cell that does not apply to the row.
    pub not_applicable: String,
    /// Field: a serial port's device file.
    pub device_file: String,
    /// Field: a serial port's baud rate.
    pub baud_rate: String,
    /// Field: a serial port's parity.
    pub parity: String,
    /// Parity: none.
    pub parity_none: String,
    /// Parity: even.
    pub parity_even: String,
    /// Parity: odd.
    pub parity_odd: String,
    /// Field: data bits per character.
    pub data_bits: String,
    /// Field: stop bits per character.
    pub stop_bits: String,
    /// Field: the silence before each request.
    pub inter_frame_delay: String,
    /// The unit after a time: microseconds.
    pub microseconds: String,
    /// Note after the inter-frame delay: what 0 means at this baud rate, `{us}`.
    pub standard_delay: String,
    /// Field: the Modbus devices on a serial port.
    pub devices_on_port: String,
    /// Shown when no device uses a serial port.
    pub no_devices_on_port: String,
    /// Accessible label of a field: `{field}`, `{node}`.
    pub field_of: String,
    /// Accessible label of a cell of a table row: `{field}`, `{row}`.
    pub field_of_row: String,
    /// Undo label of a changed field: `{field}`, `{node}`, `{value}`.
    pub set_field: String,
    /// Undo label of an added row: `{node}`.
    pub add_row: String,
    /// Undo label of a deleted row: `{row}`, `{node}`.
    pub delete_row: String,
    /// Why a value was refused, in the user's language.
    pub refusal: RefusalWords,
}

impl Default for DeviceTexts {
    fn default() -> Self {
        let s = |text: &str| text.to_owned();
        Self {
            name: s("Name"),
            host: s("Host"),
            port: s("Port"),
            password_note: s(
                "The password is typed when logging in and is never stored in the project",
            ),
            modbus_map_override: s("Own Modbus map"),
            default_map_note: s("The runtime's default Modbus map is used"),
            map_ranges: s("Map ranges"),
            table: s("Table"),
            start: s("Start"),
            count: s("Count"),
            area_address: s("Located address"),
            add_range: s("Add range"),
            new_channel: s("Add channel for variable"),
            delete: s("Delete"),
            direction: s("Direction"),
            start_byte: s("Start byte"),
            size: s("Size"),
            bytes: s("bytes"),
            milliseconds: s("ms"),
            comment: s("Comment"),
            inputs: s("Inputs"),
            outputs: s("Outputs"),
            markers: s("Markers"),
            unit_id: s("Unit id"),
            word_order: s("Word order"),
            high_first: s("High word first"),
            low_first: s("Low word first"),
            poll_interval: s("Poll interval"),
            no_poll_interval: s("none"),
            timeout: s("Timeout"),
            channels: s("Channels"),
            variable: s("Variable"),
            address: s("Address"),
            data_type: s("Data type"),
            coil: s("Coil"),
            discrete_input: s("Discrete input"),
            holding_register: s("Holding register"),
            input_register: s("Input register"),
            kind: s("Kind"),
            virtual_axis: s("Virtual"),
            task: s("Task"),
            unit: s("Unit"),
            modulo: s("Modulo (rotary)"),
            modulo_period: s("Modulo period"),
            software_limits: s("Software limits"),
            negative_limit: s("Negative limit"),
            positive_limit: s("Positive limit"),
            velocity: s("Velocity"),
            acceleration: s("Acceleration"),
            deceleration: s("Deceleration"),
            jerk: s("Jerk"),
            increments: s("Increments"),
            units: s("Per units"),
            scaling: s("Scaling"),
            dialect: s("Language rules"),
            dialect_codesys: s("CODESYS V3.5"),
            dialect_iec_strict: s("IEC 61131-3 only"),
            dialect_note: s(
                "Where CODESYS accepts what IEC 61131-3 refuses, CODESYS V3.5 compiles it with a warning and IEC 61131-3 only refuses it; the next build checks by the rules chosen",
            ),
            link: s("Link"),
            link_tcp: s("Modbus TCP"),
            link_rtu: s("Modbus RTU (serial port)"),
            serial_port: s("Serial port"),
            io_task: s("I/O task"),
            no_task: s("None: polled by the studio"),
            studio_device_note: s(
                "Choose an I/O task to have the runtime master the device in that task's cycles",
            ),
            schedule: s("Schedule"),
            schedule_interval: s("Every poll interval"),
            schedule_every_cycle: s("Every cycle of the task"),
            max_read_gap: s("Maximum read gap"),
            addresses: s("coils or registers"),
            status_variable: s("Status variable"),
            optional: s("optional"),
            request_per_round: s("{count} request per round"),
            requests_per_round: s("{count} requests per round"),
            round: s("Round"),
            read: s("Read"),
            write: s("Write"),
            function_code: s("Function code"),
            default_code: s("Default ({code})"),
            write_single_coil: s("5: write single coil"),
            write_multiple_coils: s("15: write multiple coils"),
            write_single_register: s("6: write single register"),
            write_multiple_registers: s("16: write multiple registers"),
            trigger: s("Trigger"),
            cyclic: s("Cyclic"),
            rising_edge: s("Rising edge"),
            trigger_variable: s("Trigger variable"),
            trigger_variable_hint: s("Name the BOOL variable whose rising edge sends the channel"),
            on_error: s("On error"),
            keep_last_value: s("Keep last value"),
            set_to_zero: s("Set to zero"),
            error_flag: s("Error flag"),
            not_applicable: s("—"),
            device_file: s("Device file"),
            baud_rate: s("Baud rate"),
            parity: s("Parity"),
            parity_none: s("None"),
            parity_even: s("Even"),
            parity_odd: s("Odd"),
            data_bits: s("Data bits"),
            stop_bits: s("Stop bits"),
            inter_frame_delay: s("Inter-frame delay"),
            microseconds: s("µs"),
            standard_delay: s("0 = 3.5 characters ({us} µs)"),
            devices_on_port: s("Devices"),
            no_devices_on_port: s("No Modbus device uses this port"),
            field_of: s("{field} of {node}"),
            field_of_row: s("{field} of row {row}"),
            set_field: s("Set {field} of {node} to {value}"),
            add_row: s("Add row to {node}"),
            delete_row: s("Delete row {row} of {node}"),
            refusal: RefusalWords::default(),
        }
    }
}

/// `template` with each `{key}` replaced by its value.
pub(crate) fn fill(template: &str, pairs: &[(&str, &str)]) -> String {
    pairs
        .iter()
        .fold(template.to_owned(), |text, (key, value)| {
            text.replace(&format!("{{{key}}}"), value)
        })
}

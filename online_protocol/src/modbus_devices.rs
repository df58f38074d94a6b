//! The answer of `MODBUS_DEVICES` (0x52, `docs/modbus-master.md` §9.1): what the runtime's
//! Modbus master says about each device it polls, and the page of them one answer carries.

use crate::error::DecodeError;
use crate::framing::{
    MAX_COUNT, MAX_MODBUS_DEVICE_DETAIL_BYTES, MAX_MODBUS_DEVICE_ENTRY_BYTES,
    MAX_MODBUS_DEVICE_NAME_BYTES, MAX_PAYLOAD_BYTES, MODBUS_DEVICE_FIXED_BYTES, NO_ERROR_YET_MS,
};
use crate::reader::Reader;
use crate::response::Response;
use crate::writer::{cut, put_str8};

/// The bytes of a `MODBUS_DEVICES` answer before its devices: `total` and `count`.
const PAGE_HEADER_BYTES: usize = 2;

// The protocol promises that one answer holds at least two devices; the cut texts make sure.
const _: () = assert!(PAGE_HEADER_BYTES + 2 * MAX_MODBUS_DEVICE_ENTRY_BYTES <= MAX_PAYLOAD_BYTES);

/// The state of a device the runtime masters, numbered as `MODBUS_DEVICES` sends it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[repr(u8)]
pub enum ModbusDeviceState {
    /// No round has ended yet.
    Starting = 0,
    /// The last round had no failure.
    Communicating = 1,
    /// The device answers, but with exceptions or invalid answers.
    AnsweringWithErrors = 2,
    /// No answer in time, or no connection: the master reconnects.
    NotAnswering = 3,
    /// The device's serial port cannot be opened or failed.
    SerialPortError = 4,
    /// The master is off (`rivet-runtime --modbus-master off`).
    Off = 5,
}

impl ModbusDeviceState {
    /// Every state, in the order of their numbers.
    pub const ALL: [ModbusDeviceState; 6] = [
        ModbusDeviceState::Starting,
        ModbusDeviceState::Communicating,
        ModbusDeviceState::AnsweringWithErrors,
        ModbusDeviceState::NotAnswering,
        ModbusDeviceState::SerialPortError,
        ModbusDeviceState::Off,
    ];
}

/// One device's entry in a `MODBUS_DEVICES` answer: its state and the master's counters,
/// kept by the runtime whether or not the project names a status variable.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModbusDeviceReport {
    /// The device's name in the project (the runtime sends at most
    /// [`MAX_MODBUS_DEVICE_NAME_BYTES`]).
    pub name: String,
    /// What the device is doing.
    pub state: ModbusDeviceState,
    /// The last failure as an `MB_ErrorCodes` value (0: none).
    pub last_error: u8,
    /// The last Modbus exception code the device answered (0: none).
    pub last_exception: u8,
    /// Failed requests since the last success.
    pub consecutive_errors: u32,
    /// Requests sent since the master started.
    pub requests: u32,
    /// Requests failed since the master started.
    pub errors: u32,
    /// Rounds ended since the master started.
    pub rounds: u32,
    /// Rounds dropped or merged because the previous one was still running.
    pub overruns: u32,
    /// The time the last answer took, in microseconds.
    pub last_response_us: u32,
    /// Milliseconds since the last failure, `None` before the first ([`NO_ERROR_YET_MS`] on
    /// the wire).
    pub since_last_error_ms: Option<u32>,
    /// The last failure in words ("connection refused by 127.0.0.1:5502"), empty without one
    /// (the runtime sends at most [`MAX_MODBUS_DEVICE_DETAIL_BYTES`]).
    pub detail: String,
}

impl ModbusDeviceReport {
    /// The bytes of its entry in a `MODBUS_DEVICES` answer: the two texts and the fixed fields.
    pub fn wire_bytes(&self) -> usize {
        MODBUS_DEVICE_FIXED_BYTES + self.name.len() + self.detail.len()
    }

    /// The report as the runtime sends it: the texts cut at a character boundary to their
    /// limits, and a time since the last failure that reaches [`NO_ERROR_YET_MS`] held just
    /// below it, so that it is not read as "no failure yet".
    fn for_the_wire(&self) -> Self {
        Self {
            name: cut(&self.name, MAX_MODBUS_DEVICE_NAME_BYTES).to_owned(),
            detail: cut(&self.detail, MAX_MODBUS_DEVICE_DETAIL_BYTES).to_owned(),
            since_last_error_ms: self
                .since_last_error_ms
                .map(|ms| ms.min(NO_ERROR_YET_MS - 1)),
            ..self.clone()
        }
    }

    /// Appends the entry's fields in the order of `docs/protocol.md` §3.
    pub(crate) fn encode(&self, out: &mut Vec<u8>) {
        put_str8(out, &self.name);
        out.push(self.state as u8);
        out.push(self.last_error);
        out.push(self.last_exception);
        for number in [
            self.consecutive_errors,
            self.requests,
            self.errors,
            self.rounds,
            self.overruns,
            self.last_response_us,
            self.since_last_error_ms.unwrap_or(NO_ERROR_YET_MS),
        ] {
            out.extend_from_slice(&number.to_le_bytes());
        }
        put_str8(out, &self.detail);
    }

    /// Reads one entry; a state that is not one of the six is out of range.
    pub(crate) fn decode(r: &mut Reader<'_>) -> Result<Self, DecodeError> {
        Ok(Self {
            name: r.str8("device name")?,
            state: r.choice("device state", &ModbusDeviceState::ALL, "0 to 5")?,
            last_error: r.u8("last error")?,
            last_exception: r.u8("last exception")?,
            consecutive_errors: r.u32("consecutive errors")?,
            requests: r.u32("requests")?,
            errors: r.u32("errors")?,
            rounds: r.u32("rounds")?,
            overruns: r.u32("overruns")?,
            last_response_us: r.u32("last response time")?,
            since_last_error_ms: Some(r.u32("time since the last error")?)
                .filter(|&ms| ms != NO_ERROR_YET_MS),
            detail: r.str8("device detail")?,
        })
    }
}

/// The `MODBUS_DEVICES` answer to `from`: `total` is how many `devices` there are (in the
/// image's order), and the page lists those from the `from`-th on that fit one answer, each
/// with its texts cut to their limits, so that at least two always fit. `total` is one byte:
/// of more than 255 devices the last ones are never listed (the image allows 256).
pub fn modbus_devices_page(devices: &[ModbusDeviceReport], from: u8) -> Response {
    let total = u8::try_from(devices.len()).unwrap_or(u8::MAX);
    let listed = &devices[..usize::from(total)];
    let mut used = PAGE_HEADER_BYTES;
    let mut page = Vec::new();
    for device in listed.iter().skip(usize::from(from)) {
        let entry = device.for_the_wire();
        if used + entry.wire_bytes() > MAX_PAYLOAD_BYTES || page.len() == MAX_COUNT {
            break;
        }
        used += entry.wire_bytes();
        page.push(entry);
    }
    Response::ModbusDevices {
        total,
        devices: page,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Request;

    /// A device named `name` whose last failure is `detail`.
    fn device(name: &str, detail: &str) -> ModbusDeviceReport {
        ModbusDeviceReport {
            name: name.to_owned(),
            state: ModbusDeviceState::NotAnswering,
            last_error: 3,
            last_exception: 0,
            consecutive_errors: 4,
            requests: 100,
            errors: 4,
            rounds: 50,
            overruns: 1,
            last_response_us: 1200,
            since_last_error_ms: Some(35),
            detail: detail.to_owned(),
        }
    }

    /// The devices of a page answer.
    #[track_caller]
    fn page_of(response: &Response) -> (u8, &[ModbusDeviceReport]) {
        match response {
            Response::ModbusDevices { total, devices } => (*total, devices),
            other => panic!("not a MODBUS_DEVICES answer: {other:?}"),
        }
    }

    #[test]
    fn an_entry_is_its_fields_in_the_documented_order() {
        let mut report = device("Belt", "timeout");
        report.since_last_error_ms = None;
        let mut out = Vec::new();
        report.encode(&mut out);
        let mut expected = vec![4, b'B', b'e', b'l', b't', 3, 3, 0];
        for number in [4u32, 100, 4, 50, 1, 1200, u32::MAX] {
            expected.extend_from_slice(&number.to_le_bytes());
        }
        expected.push(7);
        expected.extend_from_slice(b"timeout");
        assert_eq!(out, expected);
        assert_eq!(report.wire_bytes(), expected.len());
    }

    #[test]
    fn a_state_that_is_not_one_of_the_six_is_refused_at_its_byte() {
        let mut frame = Response::ModbusDevices {
            total: 1,
            devices: vec![device("A", "")],
        }
        .encode();
        // Service, status, total, count, then the name's length and its one byte.
        let state_at = 6;
        assert_eq!(frame[state_at], ModbusDeviceState::NotAnswering as u8);
        frame[state_at] = 6;
        let request = Request::ModbusDevices { from: 0 };
        assert_eq!(
            Response::decode(&request, &frame),
            Err(DecodeError::OutOfRange {
                field: "device state",
                at: state_at,
                value: 6,
                expected: "0 to 5",
            })
        );
    }

    #[test]
    fn names_and_details_are_cut_at_a_character_boundary_to_their_limits() {
        // 31 ASCII bytes then a 3-byte character: the character would end at byte 34.
        let name = format!("{}€tail", "n".repeat(31));
        let detail = "é".repeat(40);
        let response = modbus_devices_page(&[device(&name, &detail)], 0);
        let (_, devices) = page_of(&response);
        assert_eq!(devices[0].name, "n".repeat(31));
        assert_eq!(devices[0].detail, "é".repeat(24));
        assert_eq!(devices[0].detail.len(), MAX_MODBUS_DEVICE_DETAIL_BYTES);
    }

    #[test]
    fn a_time_since_the_last_error_that_reaches_the_none_marker_stays_a_time() {
        let mut old = device("Old", "");
        old.since_last_error_ms = Some(u32::MAX);
        let response = modbus_devices_page(&[old], 0);
        let (_, devices) = page_of(&response);
        assert_eq!(devices[0].since_last_error_ms, Some(u32::MAX - 1));
    }

    #[test]
    fn a_page_holds_as_many_devices_as_fit_and_at_least_two_of_the_longest() {
        let long = device(&"N".repeat(100), &"D".repeat(100));
        let devices = vec![long; 5];
        let response = modbus_devices_page(&devices, 0);
        let (total, page) = page_of(&response);
        assert_eq!(total, 5);
        assert_eq!(
            page.len(),
            2,
            "113-byte entries: two fit 250 bytes, three do not"
        );
        // The service, the status and at most 250 bytes of answer.
        assert!(response.encode().len() <= 2 + MAX_PAYLOAD_BYTES);
        let short = device("A", "");
        let many = vec![short.clone(); 20];
        let response = modbus_devices_page(&many, 0);
        let (_, page) = page_of(&response);
        let fit = (MAX_PAYLOAD_BYTES - PAGE_HEADER_BYTES) / short.wire_bytes();
        assert_eq!(page.len(), fit);
        assert!(response.encode().len() <= 2 + MAX_PAYLOAD_BYTES);
    }

    #[test]
    fn a_page_starts_at_from_and_asking_again_where_it_ended_lists_every_device() {
        let devices: Vec<ModbusDeviceReport> = (0..30)
            .map(|index| device(&format!("Device{index}"), "connection refused"))
            .collect();
        let mut listed = Vec::new();
        let mut pages = 0;
        loop {
            let from = u8::try_from(listed.len()).unwrap_or(u8::MAX);
            let response = modbus_devices_page(&devices, from);
            let (total, page) = page_of(&response);
            assert_eq!(total, 30);
            assert!(response.encode().len() <= 2 + MAX_PAYLOAD_BYTES);
            listed.extend_from_slice(page);
            pages += 1;
            if page.is_empty() || listed.len() >= usize::from(total) {
                break;
            }
        }
        assert_eq!(listed, devices);
        assert!(pages > 1);
        let past_the_end = modbus_devices_page(&devices, 200);
        let (total, page) = page_of(&past_the_end);
        assert_eq!((total, page.len()), (30, 0), "from past the end lists none");
        let none = modbus_devices_page(&[], 0);
        let (total, page) = page_of(&none);
        assert_eq!((total, page.len()), (0, 0), "no runtime devices: total 0");
    }

    #[test]
    fn of_more_than_255_devices_the_total_says_255_and_no_page_goes_past_it() {
        let devices = vec![device("X", ""); 256];
        let response = modbus_devices_page(&devices, 255);
        let (total, page) = page_of(&response);
        assert_eq!(total, 255);
        assert!(page.is_empty());
    }

    #[test]
    fn an_older_runtime_s_unknown_service_status_decodes_as_its_refusal() {
        let refusal = crate::Refusal::new(
            crate::Status::UnknownService,
            "service 0x52 is unknown to protocol version 3",
        );
        let frame = refusal.encode(crate::Service::ModbusDevices.number());
        let request = Request::ModbusDevices { from: 0 };
        assert_eq!(Response::decode(&request, &frame), Ok(Err(refusal)));
    }

    #[test]
    fn the_states_are_listed_in_the_order_of_their_wire_numbers() {
        for (index, state) in ModbusDeviceState::ALL.iter().enumerate() {
            assert_eq!(*state as usize, index);
        }
    }
}

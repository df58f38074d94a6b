//! The numbers of the framing (`docs/protocol.md` §1): every size a peer relies on has a name
//! here, so that the runtime and the client cannot disagree about it.

/// The user-defined Modbus function code that carries the online services (100).
pub const FUNCTION_CODE: u8 = 0x64;

/// The protocol version both sides speak; `IDENTIFY` refuses any other.
pub const PROTOCOL_VERSION: u16 = 3;

/// The most bytes of payload a request or response carries: a Modbus PDU is at most 253
/// bytes, less the function code, the service and (in a response) the status.
pub const MAX_PAYLOAD_BYTES: usize = 250;

/// The most entries a list carries, as its count is one byte.
pub const MAX_COUNT: usize = u8::MAX as usize;

/// The most bytes an `str8` holds, as its length is one byte.
pub const MAX_STR8_BYTES: usize = u8::MAX as usize;

/// The most bytes of a text the runtime sends (a refusal's message, its version, the
/// project's name, a task's name): cut there so that the response fits.
pub const MAX_TEXT_BYTES: usize = 200;

/// The most bytes of each text of a `FAULTS` entry, so that one fault always fits a response.
pub const MAX_FAULT_TEXT_BYTES: usize = 48;

/// The most bytes of a device's name in a `MODBUS_DEVICES` entry (`docs/modbus-master.md` §9.1).
pub const MAX_MODBUS_DEVICE_NAME_BYTES: usize = 32;

/// The most bytes of a device's `detail` (its last failure in words) in a `MODBUS_DEVICES`
/// entry.
pub const MAX_MODBUS_DEVICE_DETAIL_BYTES: usize = 48;

/// The bytes of a `MODBUS_DEVICES` entry besides its two texts: the texts' two length bytes,
/// `state`, `last_error`, `last_exception` and seven `u32` counters.
pub const MODBUS_DEVICE_FIXED_BYTES: usize = 2 + 3 + 7 * 4;

/// The most bytes of one `MODBUS_DEVICES` entry, with both texts cut to their limits (113).
pub const MAX_MODBUS_DEVICE_ENTRY_BYTES: usize =
    MODBUS_DEVICE_FIXED_BYTES + MAX_MODBUS_DEVICE_NAME_BYTES + MAX_MODBUS_DEVICE_DETAIL_BYTES;

/// The `since_last_error_ms` of a `MODBUS_DEVICES` entry whose device has not failed yet.
pub const NO_ERROR_YET_MS: u32 = u32::MAX;

/// The bytes of a place on the wire: region, offset, bit and size.
pub const PLACE_BYTES: usize = 8;

/// The bytes of a token, which every changing service carries first.
pub const TOKEN_BYTES: usize = 16;

/// The `bit` byte of a place that is not a single bit.
pub const NO_BIT: u8 = 0xFF;

/// The highest bit number of a bit place.
pub const MAX_BIT: u8 = 7;

/// The bytes of a `DOWNLOAD_CHUNK` before its data: token, transfer and offset.
pub const CHUNK_HEADER_BYTES: usize = TOKEN_BYTES + 6;

/// The chunk size the runtime offers in `DOWNLOAD_BEGIN`: what is left of a payload after a
/// chunk's header, rounded down.
pub const CHUNK_BYTES: u16 = 224;

/// The most places a `TRACE_CONFIGURE` frame holds; more are added with `TRACE_ADD`.
pub const TRACE_CONFIGURE_PLACES: usize = 27;

/// The most places a `TRACE_ADD` frame holds.
pub const TRACE_ADD_PLACES: usize = 29;

/// The bytes of a trace sample before its values: the cycle and the time.
pub const SAMPLE_HEADER_BYTES: usize = 16;

/// The most bytes of one sample's values, so that a sample fits one `TRACE_UPLOAD` answer.
pub const MAX_SAMPLE_VALUE_BYTES: usize = MAX_PAYLOAD_BYTES - 1 - SAMPLE_HEADER_BYTES;

/// The most percent of a trace's samples kept before the trigger.
pub const MAX_PRETRIGGER_PERCENT: u8 = 100;

/// The `trigger_sample` of `TRACE_STATUS` before the trigger came.
pub const NO_TRIGGER_SAMPLE: u32 = u32::MAX;

/// The `RESOLVE` type of a STRING.
pub const TYPE_STRING: u8 = 0x20;

/// The `RESOLVE` type of a WSTRING.
pub const TYPE_WSTRING: u8 = 0x21;

/// The `RESOLVE` type of an enumeration: its values by name come from `ENUMERATION`.
pub const TYPE_ENUM: u8 = 0x22;

/// The `RESOLVE` type of anything neither elementary nor a string.
pub const TYPE_OTHER: u8 = 0xFF;

// The sizes of the debugging services (§6, version 3).

/// The most seconds a debug session lingers without its connection (`DEBUG_ATTACH`).
pub const MAX_LINGER_S: u16 = 300;

/// The `task` byte that means every task (`CONTINUE`, `HALT`) or any task (`BREAK_SET`).
pub const ALL_TASKS: u8 = 0xFF;

/// The `id` of `BREAK_CLEAR` that clears every breakpoint.
pub const ALL_BREAKPOINTS: u16 = 0xFFFF;

/// The `breakpoint` of a `HALT_STATE` entry that names no breakpoint.
pub const NO_BREAKPOINT: u16 = 0xFFFF;

/// The `frame` of `FRAME_READ` and `FRAME_WRITE` that means the task's whole stack.
pub const WHOLE_STACK: u16 = 0xFFFF;

/// The most breakpoints a debug session holds.
pub const MAX_BREAKPOINTS: usize = 128;

/// The payload bytes of a `BREAK_SET` request before its condition: token, `pou`,
/// `instruction`, `instance`, `task`, `hit_mode`, `hit_target` and `condition_length`.
pub const BREAK_SET_HEADER_BYTES: usize = TOKEN_BYTES + 4 + 4 + 8 + 1 + 1 + 4 + 1;

/// The most bytes of a compiled breakpoint condition: what is left of a payload after the
/// `BREAK_SET` header (211).
pub const MAX_CONDITION_BYTES: usize = MAX_PAYLOAD_BYTES - BREAK_SET_HEADER_BYTES;

/// The bytes of one breakpoint in a `BREAK_LIST` answer.
pub const BREAKPOINT_ENTRY_BYTES: usize = 2 + 4 + 4 + 8 + 1 + 1 + 4 + 4 + 1;

/// The most breakpoints one `BREAK_LIST` answer carries (after `total` and `count`).
pub const BREAK_LIST_ENTRIES: usize = (MAX_PAYLOAD_BYTES - 3) / BREAKPOINT_ENTRY_BYTES;

/// The bytes of one task in a `HALT_STATE` answer.
pub const HALT_ENTRY_BYTES: usize = 1 + 1 + 1 + 2 + 4 + 4 + 2 + 8 + 4;

/// The bytes of a `HALT_STATE` answer before its tasks: session, options, generation, total
/// and count.
pub const HALT_STATE_HEADER_BYTES: usize = 1 + 1 + 4 + 1 + 1;

/// The most tasks one `HALT_STATE` answer carries.
pub const HALT_STATE_ENTRIES: usize =
    (MAX_PAYLOAD_BYTES - HALT_STATE_HEADER_BYTES) / HALT_ENTRY_BYTES;

/// The bytes of one frame in a `STACK` answer.
pub const STACK_FRAME_BYTES: usize = 4 + 4 + 8 + 4 + 4;

/// The most frames one `STACK` answer carries (after `total` and `count`).
pub const STACK_ENTRIES: usize = (MAX_PAYLOAD_BYTES - 3) / STACK_FRAME_BYTES;

/// The bytes of one range of a frame in `FRAME_READ` and `FRAME_WRITE`: offset and size.
pub const FRAME_RANGE_BYTES: usize = 6;

/// The most POUs one `FLOW_CONFIGURE` records.
pub const MAX_FLOW_ENTRIES: usize = 8;

/// The most bitmap bytes one `FLOW_READ` answer carries.
pub const MAX_FLOW_BITMAP_BYTES: usize = 224;

//! Proptest strategies for every request and response, for the round-trip tests.

use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::select;
use proptest::strategy::{BoxedStrategy, Union};

use crate::framing::{NO_BIT, NO_ERROR_YET_MS, NO_TRIGGER_SAMPLE};
use crate::{
    Fault, Identity, ModbusDeviceReport, ModbusDeviceState, Place, Refusal, Request, ResetKind,
    Resolved, Response, Service, Snapshot, Status, TargetState, TaskInfo, TraceConfig, TraceSample,
    TraceState, TraceStatus, TriggerKind,
};

/// A text that fits an `str8` and a refusal's message: at most 40 characters of 4 bytes.
fn text() -> impl Strategy<Value = String> {
    ".{0,40}"
}

/// A place with any fields the wire can carry (`Some(NO_BIT)` cannot be sent).
fn place() -> impl Strategy<Value = Place> {
    (
        any::<u8>(),
        any::<u32>(),
        prop::option::of(0..NO_BIT),
        any::<u16>(),
    )
        .prop_map(|(region, offset, bit, size)| Place {
            region,
            offset,
            bit,
            size,
        })
}

/// A place of at most 16 bytes, for lists that carry values.
fn small_place() -> impl Strategy<Value = Place> {
    (place(), 0u16..=16).prop_map(|(place, size)| Place { size, ..place })
}

fn places() -> impl Strategy<Value = Vec<Place>> {
    vec(place(), 0..32)
}

/// Places with values of their `size` bytes, as `WRITE` and `FORCE` carry them.
fn sized_values() -> impl Strategy<Value = Vec<(Place, Vec<u8>)>> {
    vec(
        small_place()
            .prop_flat_map(|place| (Just(place), vec(any::<u8>(), usize::from(place.size)))),
        0..16,
    )
}

/// Places with values of their value bytes, as answers carry them.
fn answered_values() -> impl Strategy<Value = Vec<(Place, Vec<u8>)>> {
    vec(
        small_place().prop_flat_map(|place| (Just(place), vec(any::<u8>(), place.value_bytes()))),
        0..16,
    )
}

fn target_state() -> impl Strategy<Value = TargetState> {
    select(TargetState::ALL.to_vec())
}

fn trace_config() -> impl Strategy<Value = TraceConfig> {
    (
        any::<u8>(),
        1..=u16::MAX,
        1..=u32::MAX,
        0u8..=100,
        select(TriggerKind::ALL.to_vec()),
        place(),
        places(),
    )
        .prop_map(
            |(task, every, samples, pretrigger, trigger, trigger_place, places)| TraceConfig {
                task,
                every,
                samples,
                pretrigger,
                trigger,
                trigger_place,
                places,
            },
        )
}

/// Any request.
pub fn request() -> impl Strategy<Value = Request> {
    let token = any::<u128>;
    let arms: Vec<BoxedStrategy<Request>> = vec![
        any::<u16>()
            .prop_map(|protocol| Request::Identify { protocol })
            .boxed(),
        text()
            .prop_map(|password| Request::Login { password })
            .boxed(),
        Just(Request::Logout).boxed(),
        (token(), any::<u32>(), any::<[u8; 32]>())
            .prop_map(|(token, size, hash)| Request::DownloadBegin { token, size, hash })
            .boxed(),
        (
            token(),
            any::<u16>(),
            any::<u32>(),
            vec(any::<u8>(), 0..240),
        )
            .prop_map(|(token, transfer, offset, bytes)| Request::DownloadChunk {
                token,
                transfer,
                offset,
                bytes,
            })
            .boxed(),
        (token(), any::<u16>(), any::<bool>())
            .prop_map(|(token, transfer, start)| Request::DownloadCommit {
                token,
                transfer,
                start,
            })
            .boxed(),
        (token(), any::<u16>())
            .prop_map(|(token, transfer)| Request::DownloadAbort { token, transfer })
            .boxed(),
        (token(), any::<u16>())
            .prop_map(|(token, transfer)| Request::OnlineChangeCheck { token, transfer })
            .boxed(),
        (token(), any::<u16>(), any::<u16>())
            .prop_map(|(token, transfer, from)| Request::OnlineChangeDetails {
                token,
                transfer,
                from,
            })
            .boxed(),
        (token(), any::<u16>())
            .prop_map(|(token, transfer)| Request::OnlineChangeApply { token, transfer })
            .boxed(),
        token().prop_map(|token| Request::Start { token }).boxed(),
        token().prop_map(|token| Request::Stop { token }).boxed(),
        (token(), select(ResetKind::ALL.to_vec()))
            .prop_map(|(token, kind)| Request::Reset { token, kind })
            .boxed(),
        text().prop_map(|path| Request::Resolve { path }).boxed(),
        (text(), any::<u16>())
            .prop_map(|(path, from)| Request::Enumeration { path, from })
            .boxed(),
        places().prop_map(|places| Request::Read { places }).boxed(),
        (token(), sized_values())
            .prop_map(|(token, values)| Request::Write { token, values })
            .boxed(),
        (token(), sized_values())
            .prop_map(|(token, values)| Request::Force { token, values })
            .boxed(),
        (token(), places())
            .prop_map(|(token, places)| Request::Unforce { token, places })
            .boxed(),
        any::<u16>()
            .prop_map(|from| Request::Forces { from })
            .boxed(),
        (token(), trace_config())
            .prop_map(|(token, config)| Request::TraceConfigure { token, config })
            .boxed(),
        token()
            .prop_map(|token| Request::TraceArm { token })
            .boxed(),
        Just(Request::TraceStatus).boxed(),
        any::<u32>()
            .prop_map(|from| Request::TraceUpload { from })
            .boxed(),
        (token(), places())
            .prop_map(|(token, places)| Request::TraceAdd { token, places })
            .boxed(),
        Just(Request::Tasks).boxed(),
        any::<u16>()
            .prop_map(|from| Request::Faults { from })
            .boxed(),
        any::<u8>()
            .prop_map(|from| Request::ModbusDevices { from })
            .boxed(),
    ];
    prop_oneof![Union::new(arms), crate::debug_arb::request()]
}

/// A request of `service`, for the answers that need nothing from their request.
pub fn request_of(service: Service) -> Request {
    match service {
        Service::Identify => Request::Identify {
            protocol: crate::PROTOCOL_VERSION,
        },
        Service::Logout => Request::Logout,
        Service::Login => Request::Login {
            password: String::new(),
        },
        Service::DownloadBegin => Request::DownloadBegin {
            token: 0,
            size: 1,
            hash: [0; 32],
        },
        Service::DownloadChunk => Request::DownloadChunk {
            token: 0,
            transfer: 1,
            offset: 0,
            bytes: Vec::new(),
        },
        Service::DownloadCommit => Request::DownloadCommit {
            token: 0,
            transfer: 1,
            start: false,
        },
        Service::DownloadAbort => Request::DownloadAbort {
            token: 0,
            transfer: 1,
        },
        Service::OnlineChangeCheck => Request::OnlineChangeCheck {
            token: 0,
            transfer: 1,
        },
        Service::OnlineChangeDetails => Request::OnlineChangeDetails {
            token: 0,
            transfer: 1,
            from: 0,
        },
        Service::OnlineChangeApply => Request::OnlineChangeApply {
            token: 0,
            transfer: 1,
        },
        Service::Start => Request::Start { token: 0 },
        Service::Stop => Request::Stop { token: 0 },
        Service::Reset => Request::Reset {
            token: 0,
            kind: ResetKind::Warm,
        },
        Service::Resolve => Request::Resolve {
            path: String::new(),
        },
        Service::Enumeration => Request::Enumeration {
            path: String::new(),
            from: 0,
        },
        Service::Read => Request::Read { places: Vec::new() },
        Service::Write => Request::Write {
            token: 0,
            values: Vec::new(),
        },
        Service::Force => Request::Force {
            token: 0,
            values: Vec::new(),
        },
        Service::Unforce => Request::Unforce {
            token: 0,
            places: Vec::new(),
        },
        Service::Forces => Request::Forces { from: 0 },
        Service::TraceConfigure => Request::TraceConfigure {
            token: 0,
            config: TraceConfig {
                task: 0,
                every: 1,
                samples: 1,
                pretrigger: 0,
                trigger: TriggerKind::None,
                trigger_place: Place {
                    region: 0,
                    offset: 0,
                    bit: None,
                    size: 1,
                },
                places: Vec::new(),
            },
        },
        Service::TraceArm => Request::TraceArm { token: 0 },
        Service::TraceStatus => Request::TraceStatus,
        Service::TraceUpload => Request::TraceUpload { from: 0 },
        Service::TraceAdd => Request::TraceAdd {
            token: 0,
            places: Vec::new(),
        },
        Service::Tasks => Request::Tasks,
        Service::Faults => Request::Faults { from: 0 },
        Service::ModbusDevices => Request::ModbusDevices { from: 0 },
        debug => crate::debug_arb::request_of(debug),
    }
}

fn task() -> impl Strategy<Value = TaskInfo> {
    (text(), any::<[u64; 6]>(), any::<bool>()).prop_map(|(name, numbers, faulted)| TaskInfo {
        name,
        cycles: numbers[0],
        last_ns: numbers[1],
        min_ns: numbers[2],
        max_ns: numbers[3],
        average_ns: numbers[4],
        jitter_max_ns: numbers[5],
        faulted,
    })
}

fn fault() -> impl Strategy<Value = Fault> {
    (text(), text(), text(), text(), any::<u32>(), any::<u64>()).prop_map(
        |(task, kind, pou, file, line, cycle)| Fault {
            task,
            kind,
            pou,
            file,
            line,
            cycle,
        },
    )
}

/// A device report with any fields the wire can carry (`Some(NO_ERROR_YET_MS)` cannot be
/// sent: it reads back as `None`).
fn modbus_device() -> impl Strategy<Value = ModbusDeviceReport> {
    (
        (
            text(),
            select(ModbusDeviceState::ALL.to_vec()),
            any::<[u8; 2]>(),
        ),
        any::<[u32; 6]>(),
        (proptest::option::of(0..NO_ERROR_YET_MS), text()),
    )
        .prop_map(
            |((name, state, codes), numbers, (since_last_error_ms, detail))| ModbusDeviceReport {
                name,
                state,
                last_error: codes[0],
                last_exception: codes[1],
                consecutive_errors: numbers[0],
                requests: numbers[1],
                errors: numbers[2],
                rounds: numbers[3],
                overruns: numbers[4],
                last_response_us: numbers[5],
                since_last_error_ms,
                detail,
            },
        )
}

/// `READ` with places and its answer with their values.
fn read() -> impl Strategy<Value = (Request, Response)> {
    vec(small_place(), 0..20)
        .prop_flat_map(|places| {
            let values = places
                .iter()
                .map(|place| (vec(any::<u8>(), place.value_bytes()), any::<bool>()))
                .collect::<Vec<_>>();
            (Just(places), any::<u64>(), values)
        })
        .prop_map(|(places, cycle, values)| {
            (
                Request::Read { places },
                Response::Read(Snapshot { cycle, values }),
            )
        })
}

/// Samples of one size, as one `TRACE_UPLOAD` answer carries them.
fn samples() -> impl Strategy<Value = Vec<TraceSample>> {
    (0usize..40).prop_flat_map(|size| {
        vec(
            (any::<u64>(), any::<u64>(), vec(any::<u8>(), size)).prop_map(
                |(cycle, time_ns, values)| TraceSample {
                    cycle,
                    time_ns,
                    values,
                },
            ),
            0..8,
        )
    })
}

/// Any answer of a service done, with a request it answers.
pub fn response() -> impl Strategy<Value = (Request, Response)> {
    let arms: Vec<BoxedStrategy<Response>> = vec![
        (
            any::<u16>(),
            text(),
            target_state(),
            prop::option::of(any::<[u8; 32]>().prop_filter("zeros mean none", |h| *h != [0; 32])),
            text(),
            any::<bool>(),
            any::<u8>().prop_map(crate::DebugStatus::from_bits),
        )
            .prop_map(
                |(
                    protocol,
                    runtime_version,
                    state,
                    image_hash,
                    project,
                    password_required,
                    debug,
                )| {
                    Response::Identify(Identity {
                        protocol,
                        runtime_version,
                        state,
                        image_hash,
                        project,
                        password_required,
                        debug,
                    })
                },
            )
            .boxed(),
        any::<u128>()
            .prop_map(|token| Response::Login { token })
            .boxed(),
        Just(Response::Logout).boxed(),
        (any::<u16>(), any::<u16>())
            .prop_map(|(transfer, chunk_size)| Response::DownloadBegin {
                transfer,
                chunk_size,
            })
            .boxed(),
        any::<u32>()
            .prop_map(|received| Response::DownloadChunk { received })
            .boxed(),
        any::<bool>()
            .prop_map(|retained| Response::DownloadCommit { retained })
            .boxed(),
        Just(Response::DownloadAbort).boxed(),
        (
            (
                any::<bool>(),
                0..7u8,
                any::<u16>(),
                any::<u16>(),
                any::<u16>(),
            ),
            (any::<u32>(), any::<u32>(), any::<u32>(), any::<u32>()),
            (
                any::<u32>(),
                any::<u32>(),
                any::<u16>(),
                any::<u16>(),
                text(),
            ),
        )
            .prop_map(
                |(
                    (possible, reason, pous_changed, pous_added, pous_removed),
                    (carried, added, removed, reinitialised),
                    (pointers_moved, pointers_cleared, forces_released, details, why),
                )| {
                    Response::OnlineChangeCheck(crate::ChangeCheck {
                        possible,
                        reason,
                        pous_changed,
                        pous_added,
                        pous_removed,
                        carried,
                        added,
                        removed,
                        reinitialised,
                        pointers_moved,
                        pointers_cleared,
                        forces_released,
                        details,
                        why,
                    })
                },
            )
            .boxed(),
        (
            any::<u16>(),
            vec((0..=crate::MAX_DETAIL_KIND, text()), 0..4),
        )
            .prop_map(|(total, details)| Response::OnlineChangeDetails {
                total,
                details: details
                    .into_iter()
                    .map(|(kind, name)| crate::ChangeDetailEntry { kind, name })
                    .collect(),
            })
            .boxed(),
        (any::<u64>(), any::<u32>(), any::<bool>(), any::<u32>())
            .prop_map(|(cycles, carried, retained, switch_us)| {
                Response::OnlineChangeApply(crate::ChangeApplied {
                    cycles,
                    carried,
                    retained,
                    switch_us,
                })
            })
            .boxed(),
        target_state()
            .prop_map(|state| Response::Start { state })
            .boxed(),
        target_state()
            .prop_map(|state| Response::Stop { state })
            .boxed(),
        target_state()
            .prop_map(|state| Response::Reset { state })
            .boxed(),
        (place(), any::<u8>(), any::<u16>())
            .prop_map(|(place, type_tag, length)| {
                Response::Resolve(Resolved {
                    place,
                    type_tag,
                    length,
                })
            })
            .boxed(),
        (any::<u8>(), any::<u16>(), vec((text(), any::<i64>()), 0..4))
            .prop_map(|(base, total, values)| Response::Enumeration {
                base,
                total,
                values,
            })
            .boxed(),
        Just(Response::Write).boxed(),
        Just(Response::Force).boxed(),
        Just(Response::Unforce).boxed(),
        (any::<u16>(), answered_values())
            .prop_map(|(total, forces)| Response::Forces { total, forces })
            .boxed(),
        any::<u16>()
            .prop_map(|sample_bytes| Response::TraceConfigure { sample_bytes })
            .boxed(),
        Just(Response::TraceArm).boxed(),
        (
            select(TraceState::ALL.to_vec()),
            any::<u32>(),
            prop::option::of(0..NO_TRIGGER_SAMPLE),
        )
            .prop_map(|(state, recorded, trigger_sample)| {
                Response::TraceStatus(TraceStatus {
                    state,
                    recorded,
                    trigger_sample,
                })
            })
            .boxed(),
        samples()
            .prop_map(|samples| Response::TraceUpload { samples })
            .boxed(),
        any::<u16>()
            .prop_map(|sample_bytes| Response::TraceAdd { sample_bytes })
            .boxed(),
        vec(task(), 0..4)
            .prop_map(|tasks| Response::Tasks { tasks })
            .boxed(),
        (any::<u16>(), vec(fault(), 0..4))
            .prop_map(|(total, faults)| Response::Faults { total, faults })
            .boxed(),
        (any::<u8>(), vec(modbus_device(), 0..4))
            .prop_map(|(total, devices)| Response::ModbusDevices { total, devices })
            .boxed(),
    ];
    let others = Union::new(arms).prop_map(|response| (request_of(response.service()), response));
    prop_oneof![read(), others, crate::debug_arb::response()]
}

/// Any refusal (a status other than done, a message that fits).
pub fn refusal() -> impl Strategy<Value = Refusal> {
    (select(Status::ALL[1..].to_vec()), text())
        .prop_map(|(status, message)| Refusal { status, message })
}

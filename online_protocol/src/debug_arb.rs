//! Proptest strategies for the debugging requests and answers, for the round-trip tests.

use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::select;
use proptest::strategy::{BoxedStrategy, Union};

use crate::framing::{MAX_CONDITION_BYTES, MAX_FLOW_ENTRIES, NO_BREAKPOINT};
use crate::{
    BreakpointInfo, BreakpointSpec, DebugOptions, DebugRequest, DebugResponse, FlowCycle,
    FlowEntry, FrameRange, HaltReason, HaltState, HitMode, HitRule, Request, Response, Service,
    SessionState, StackFrame, StepKind, TaskDebugState, TaskHalt,
};

fn hit_rule() -> impl Strategy<Value = HitRule> {
    prop_oneof![
        any::<u32>().prop_map(|target| HitRule {
            mode: HitMode::Always,
            target
        }),
        (select(HitMode::ALL[1..].to_vec()), 1..=u32::MAX)
            .prop_map(|(mode, target)| HitRule { mode, target }),
    ]
}

fn options() -> impl Strategy<Value = DebugOptions> {
    any::<bool>().prop_map(|halt_all_on_halt| DebugOptions { halt_all_on_halt })
}

fn range() -> impl Strategy<Value = FrameRange> {
    (any::<u32>(), any::<u16>()).prop_map(|(offset, size)| FrameRange { offset, size })
}

/// A range of at most 16 bytes, for lists that carry values.
fn small_range() -> impl Strategy<Value = FrameRange> {
    (any::<u32>(), 0u16..=16).prop_map(|(offset, size)| FrameRange { offset, size })
}

/// Any debugging request.
pub fn request() -> impl Strategy<Value = Request> {
    let token = any::<u128>;
    let arms: Vec<BoxedStrategy<DebugRequest>> = vec![
        (token(), 0..=crate::MAX_LINGER_S, options())
            .prop_map(|(token, linger_s, options)| DebugRequest::Attach {
                token,
                linger_s,
                options,
            })
            .boxed(),
        token()
            .prop_map(|token| DebugRequest::Detach { token })
            .boxed(),
        (
            token(),
            any::<(u32, u32, u64, u8)>(),
            hit_rule(),
            vec(any::<u8>(), 0..=MAX_CONDITION_BYTES),
        )
            .prop_map(
                |(token, (pou, instruction, instance, task), hit, condition)| {
                    DebugRequest::BreakSet {
                        token,
                        breakpoint: BreakpointSpec {
                            pou,
                            instruction,
                            instance,
                            task,
                            hit,
                            condition,
                        },
                    }
                },
            )
            .boxed(),
        (token(), any::<u16>())
            .prop_map(|(token, id)| DebugRequest::BreakClear { token, id })
            .boxed(),
        any::<u16>()
            .prop_map(|from| DebugRequest::BreakList { from })
            .boxed(),
        any::<u8>()
            .prop_map(|from| DebugRequest::HaltState { from })
            .boxed(),
        (token(), any::<u8>(), select(StepKind::ALL.to_vec()))
            .prop_map(|(token, task, kind)| DebugRequest::Step { token, task, kind })
            .boxed(),
        (token(), any::<u8>(), any::<u32>(), any::<u32>())
            .prop_map(|(token, task, pou, instruction)| DebugRequest::RunTo {
                token,
                task,
                pou,
                instruction,
            })
            .boxed(),
        (token(), any::<u8>())
            .prop_map(|(token, task)| DebugRequest::Continue { token, task })
            .boxed(),
        (token(), any::<u8>())
            .prop_map(|(token, task)| DebugRequest::Halt { token, task })
            .boxed(),
        (any::<u8>(), any::<u16>())
            .prop_map(|(task, from)| DebugRequest::Stack { task, from })
            .boxed(),
        (any::<u8>(), any::<u16>(), vec(range(), 0..40))
            .prop_map(|(task, frame, ranges)| DebugRequest::FrameRead {
                task,
                frame,
                ranges,
            })
            .boxed(),
        (
            token(),
            any::<u8>(),
            any::<u16>(),
            vec(
                small_range().prop_flat_map(|range| {
                    (Just(range), vec(any::<u8>(), usize::from(range.size)))
                }),
                0..12,
            ),
        )
            .prop_map(|(token, task, frame, values)| DebugRequest::FrameWrite {
                token,
                task,
                frame,
                values,
            })
            .boxed(),
        (
            token(),
            any::<u8>(),
            vec(
                any::<(u32, u64)>().prop_map(|(pou, instance)| FlowEntry { pou, instance }),
                0..=MAX_FLOW_ENTRIES,
            ),
        )
            .prop_map(|(token, task, entries)| DebugRequest::FlowConfigure {
                token,
                task,
                entries,
            })
            .boxed(),
        (
            any::<u8>(),
            select(FlowCycle::ALL.to_vec()),
            any::<u32>().prop_map(|from| from & !7),
        )
            .prop_map(|(entry, which, from)| DebugRequest::FlowRead { entry, which, from })
            .boxed(),
    ];
    Union::new(arms).prop_map(Request::Debug)
}

/// A request of the debugging `service`, for the answers that need nothing from their request.
pub fn request_of(service: Service) -> Request {
    let token = 0;
    let task = 0;
    Request::Debug(match service {
        Service::DebugAttach => DebugRequest::Attach {
            token,
            linger_s: 0,
            options: DebugOptions::default(),
        },
        Service::DebugDetach => DebugRequest::Detach { token },
        Service::BreakSet => DebugRequest::BreakSet {
            token,
            breakpoint: BreakpointSpec {
                pou: 0,
                instruction: 0,
                instance: 0,
                task,
                hit: HitRule::ALWAYS,
                condition: Vec::new(),
            },
        },
        Service::BreakClear => DebugRequest::BreakClear { token, id: 0 },
        Service::BreakList => DebugRequest::BreakList { from: 0 },
        Service::HaltState => DebugRequest::HaltState { from: 0 },
        Service::Step => DebugRequest::Step {
            token,
            task,
            kind: StepKind::Into,
        },
        Service::RunTo => DebugRequest::RunTo {
            token,
            task,
            pou: 0,
            instruction: 0,
        },
        Service::Continue => DebugRequest::Continue { token, task },
        Service::Stack => DebugRequest::Stack { task, from: 0 },
        Service::FrameRead => DebugRequest::FrameRead {
            task,
            frame: 0,
            ranges: Vec::new(),
        },
        Service::FrameWrite => DebugRequest::FrameWrite {
            token,
            task,
            frame: 0,
            values: Vec::new(),
        },
        Service::FlowConfigure => DebugRequest::FlowConfigure {
            token,
            task,
            entries: Vec::new(),
        },
        Service::FlowRead => DebugRequest::FlowRead {
            entry: 0,
            which: FlowCycle::LastComplete,
            from: 0,
        },
        // `HALT`, and what no debugging service is.
        _ => DebugRequest::Halt { token, task },
    })
}

fn task_halt() -> impl Strategy<Value = TaskHalt> {
    (
        any::<u8>(),
        select(TaskDebugState::ALL.to_vec()),
        select(HaltReason::ALL.to_vec()),
        prop::option::of(0..NO_BREAKPOINT),
        any::<(u32, u32, u16, u64, u32)>(),
    )
        .prop_map(
            |(task, state, reason, breakpoint, (pou, instruction, depth, cycle, halted_ms))| {
                TaskHalt {
                    task,
                    state,
                    reason,
                    breakpoint,
                    pou,
                    instruction,
                    depth,
                    cycle,
                    halted_ms,
                }
            },
        )
}

fn breakpoint_info() -> impl Strategy<Value = BreakpointInfo> {
    (
        any::<(u16, u32, u32, u64, u8)>(),
        hit_rule(),
        any::<u32>(),
        any::<bool>(),
    )
        .prop_map(
            |((id, pou, instruction, instance, task), hit, hits, conditional)| BreakpointInfo {
                id,
                pou,
                instruction,
                instance,
                task,
                hit,
                hits,
                conditional,
            },
        )
}

/// A `FRAME_READ` request with an answer of the sizes it asks for.
fn frame_read() -> impl Strategy<Value = (Request, Response)> {
    (any::<u8>(), any::<u16>(), vec(small_range(), 0..12)).prop_flat_map(|(task, frame, ranges)| {
        let size: usize = ranges.iter().map(|range| usize::from(range.size)).sum();
        let request = Request::Debug(DebugRequest::FrameRead {
            task,
            frame,
            ranges,
        });
        vec(any::<u8>(), size).prop_map(move |bytes| {
            (
                request.clone(),
                Response::Debug(DebugResponse::FrameRead { bytes }),
            )
        })
    })
}

/// Any answer of a debugging service done, with a request it answers.
pub fn response() -> impl Strategy<Value = (Request, Response)> {
    let arms: Vec<BoxedStrategy<DebugResponse>> = vec![
        (any::<bool>(), any::<u8>(), any::<u16>())
            .prop_map(|(took_over, halted, breakpoints)| DebugResponse::Attach {
                took_over,
                halted,
                breakpoints,
            })
            .boxed(),
        Just(DebugResponse::Detach).boxed(),
        (any::<u16>(), any::<bool>())
            .prop_map(|(id, replaced)| DebugResponse::BreakSet { id, replaced })
            .boxed(),
        Just(DebugResponse::BreakClear).boxed(),
        (
            any::<u16>(),
            vec(breakpoint_info(), 0..=crate::BREAK_LIST_ENTRIES),
        )
            .prop_map(|(total, breakpoints)| DebugResponse::BreakList { total, breakpoints })
            .boxed(),
        (
            select(SessionState::ALL.to_vec()),
            options(),
            any::<u32>(),
            any::<u8>(),
            vec(task_halt(), 0..=crate::HALT_STATE_ENTRIES),
        )
            .prop_map(|(session, options, generation, total, tasks)| {
                DebugResponse::HaltState(HaltState {
                    session,
                    options,
                    generation,
                    total,
                    tasks,
                })
            })
            .boxed(),
        Just(DebugResponse::Step).boxed(),
        Just(DebugResponse::RunTo).boxed(),
        Just(DebugResponse::Continue).boxed(),
        Just(DebugResponse::Halt).boxed(),
        (
            any::<u16>(),
            vec(
                any::<(u32, u32, u64, u32, u32)>().prop_map(
                    |(pou, instruction, instance, frame, frame_bytes)| StackFrame {
                        pou,
                        instruction,
                        instance,
                        frame,
                        frame_bytes,
                    },
                ),
                0..=crate::STACK_ENTRIES,
            ),
        )
            .prop_map(|(total, frames)| DebugResponse::Stack { total, frames })
            .boxed(),
        Just(DebugResponse::FrameWrite).boxed(),
        Just(DebugResponse::FlowConfigure).boxed(),
        (
            any::<u64>(),
            any::<u32>(),
            vec(any::<u8>(), 0..=crate::MAX_FLOW_BITMAP_BYTES),
        )
            .prop_map(|(cycle, statements, bitmap)| DebugResponse::FlowRead {
                cycle,
                statements,
                bitmap,
            })
            .boxed(),
    ];
    let others = Union::new(arms)
        .prop_map(|response| (request_of(response.service()), Response::Debug(response)));
    prop_oneof![frame_read(), others]
}

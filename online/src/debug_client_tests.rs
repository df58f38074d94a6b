//! The debugging methods against a small fake runtime on loopback that answers with
//! `online_protocol`'s encoders: paging, batching and refusals.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::sync::{Arc, Mutex};

use online_protocol::{
    BreakpointInfo, HaltReason, HitRule, SessionState, TaskDebugState, TaskHalt,
};

use super::*;

/// What the fake runtime answers to a request other than `IDENTIFY`.
type Answerer = Box<dyn Fn(&DebugRequest) -> Result<DebugResponse, Refusal> + Send>;

/// Serves one connection on 127.0.0.1 with `answer`, recording each debugging request it
/// gets, and returns a client connected to it with the record.
async fn fake(answer: Answerer) -> (Client, Arc<Mutex<Vec<DebugRequest>>>) {
    let seen = Arc::new(Mutex::new(Vec::new()));
    let record = Arc::clone(&seen);
    let address = crate::fake_target::serve(move |debug| {
        record.lock().unwrap().push(debug.clone());
        answer(debug)
    })
    .await;
    let (client, _) = Client::connect(address, None).await.unwrap();
    (client, seen)
}

fn breakpoint(id: u16) -> BreakpointInfo {
    BreakpointInfo {
        id,
        pou: 1,
        instruction: u32::from(id),
        instance: 0,
        task: online_protocol::ALL_TASKS,
        hit: HitRule::ALWAYS,
        hits: 0,
        conditional: false,
    }
}

#[tokio::test]
async fn the_breakpoint_list_is_asked_again_from_where_each_answer_ended() {
    let answer: Answerer = Box::new(|request| match request {
        DebugRequest::BreakList { from } => {
            let from = *from;
            let end = (from + 8).min(20);
            Ok(DebugResponse::BreakList {
                total: 20,
                breakpoints: (from..end).map(breakpoint).collect(),
            })
        }
        _ => Err(Refusal::bad("unexpected")),
    });
    let (mut client, seen) = fake(answer).await;
    let list = client.break_list().await.unwrap();
    assert_eq!(
        list.iter().map(|b| b.id).collect::<Vec<_>>(),
        (0..20).collect::<Vec<_>>()
    );
    let froms: Vec<u16> = seen
        .lock()
        .unwrap()
        .iter()
        .map(|request| match request {
            DebugRequest::BreakList { from } => *from,
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(froms, [0, 8, 16]);
}

#[tokio::test]
async fn a_refusal_names_the_service_its_status_and_the_targets_words() {
    let answer: Answerer = Box::new(|_| {
        Err(Refusal::not_now(
            "task 'Slow' is halted beneath task 'Fast': continue 'Fast' first",
        ))
    });
    let (mut client, _) = fake(answer).await;
    let error = client.step(0, StepKind::Over).await.unwrap_err();
    let text = error.to_string();
    assert!(
        matches!(
            error,
            OnlineError::DebugRefused {
                service: "STEP",
                status: 7,
                ..
            }
        ),
        "{error:?}"
    );
    assert!(
        text.contains("STEP") && text.contains("continue 'Fast' first"),
        "{text}"
    );
}

#[tokio::test]
async fn a_condition_too_long_for_the_frame_is_refused_before_anything_is_sent() {
    let answer: Answerer = Box::new(|_| {
        Ok(DebugResponse::BreakSet {
            id: 1,
            replaced: false,
        })
    });
    let (mut client, seen) = fake(answer).await;
    let mut spec = BreakpointSpec {
        pou: 0,
        instruction: 0,
        instance: 0,
        task: online_protocol::ALL_TASKS,
        hit: HitRule::ALWAYS,
        condition: vec![0; MAX_CONDITION_BYTES + 49],
    };
    let error = client.break_set(&spec).await.unwrap_err();
    assert_eq!(
        error.to_string(),
        "this condition compiles to 260 bytes; the target takes at most 211: split it or watch a variable instead"
    );
    assert!(seen.lock().unwrap().is_empty());
    spec.condition.truncate(MAX_CONDITION_BYTES);
    assert_eq!(client.break_set(&spec).await.unwrap(), (1, false));
}

#[tokio::test]
async fn frame_reads_are_split_to_fit_and_joined_back_per_range() {
    let answer: Answerer = Box::new(|request| match request {
        DebugRequest::FrameRead { ranges, .. } => {
            let total: usize = ranges.iter().map(|r| usize::from(r.size)).sum();
            assert!(
                total <= MAX_PAYLOAD_BYTES,
                "{total} bytes asked in one read"
            );
            // Each byte is its offset's low byte, so the joined values can be checked.
            let bytes = ranges
                .iter()
                .flat_map(|r| (r.offset..r.offset + u32::from(r.size)).map(|o| o as u8))
                .collect();
            Ok(DebugResponse::FrameRead { bytes })
        }
        _ => Err(Refusal::bad("unexpected")),
    });
    let (mut client, seen) = fake(answer).await;
    let ranges = [
        FrameRange { offset: 0, size: 4 },
        FrameRange {
            offset: 100,
            size: 600,
        },
        FrameRange { offset: 8, size: 2 },
    ];
    let values = client.frame_read(0, 0, &ranges).await.unwrap();
    assert_eq!(values[0], [0, 1, 2, 3]);
    assert_eq!(values[1].len(), 600);
    assert_eq!(values[1][599], (699u32 % 256) as u8);
    assert_eq!(values[2], [8, 9]);
    assert!(seen.lock().unwrap().len() >= 3);
}

#[tokio::test]
async fn the_halt_state_gathers_every_task_and_reads_again_when_it_changed_meanwhile() {
    let calls = Arc::new(Mutex::new(0u32));
    let counter = Arc::clone(&calls);
    let answer: Answerer = Box::new(move |request| {
        let DebugRequest::HaltState { from } = request else {
            return Err(Refusal::bad("unexpected"));
        };
        let mut calls = counter.lock().unwrap();
        *calls += 1;
        // The state changes once, between the first and the second page.
        let generation = if *calls == 1 { 5 } else { 6 };
        let task = |index: u8| TaskHalt {
            task: index,
            state: TaskDebugState::Running,
            reason: HaltReason::Breakpoint,
            breakpoint: None,
            pou: 0,
            instruction: 0,
            depth: 0,
            cycle: 0,
            halted_ms: 0,
        };
        let end = (*from + 2).min(3);
        Ok(DebugResponse::HaltState(HaltState {
            session: SessionState::None,
            options: DebugOptions::default(),
            generation,
            total: 3,
            tasks: (*from..end).map(task).collect(),
        }))
    });
    let (mut client, _) = fake(answer).await;
    let state = client.halt_state().await.unwrap();
    assert_eq!(state.generation, 6);
    assert_eq!(
        state.tasks.iter().map(|t| t.task).collect::<Vec<_>>(),
        [0, 1, 2]
    );
}

#[test]
fn a_flow_bitmap_says_which_statements_ran() {
    let flow = FlowBitmap {
        cycle: 3,
        statements: 10,
        bitmap: vec![0b0000_0101, 0b0000_0010],
    };
    assert!(flow.ran(0) && !flow.ran(1) && flow.ran(2) && flow.ran(9));
    assert!(!flow.ran(8) && !flow.ran(200));
}

#[tokio::test]
async fn a_flow_bitmap_is_read_from_where_each_answer_ended_until_every_statement() {
    let answer: Answerer = Box::new(|request| match request {
        DebugRequest::FlowRead { from, .. } => {
            // 2,000 statements: 250 bytes, more than one answer carries.
            let first = (*from / 8) as usize;
            let end = (first + online_protocol::MAX_FLOW_BITMAP_BYTES).min(250);
            Ok(DebugResponse::FlowRead {
                cycle: 9,
                statements: 2000,
                bitmap: (first..end).map(|byte| byte as u8).collect(),
            })
        }
        _ => Err(Refusal::bad("unexpected")),
    });
    let (mut client, seen) = fake(answer).await;
    let flow = client.flow_read(0, FlowCycle::LastComplete).await.unwrap();
    assert_eq!(
        (flow.cycle, flow.statements, flow.bitmap.len()),
        (9, 2000, 250)
    );
    assert_eq!(flow.bitmap[249], 249);
    let froms: Vec<u32> = seen
        .lock()
        .unwrap()
        .iter()
        .map(|request| match request {
            DebugRequest::FlowRead { from, .. } => *from,
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(froms, [0, 224 * 8]);
}

#[tokio::test]
async fn frame_writes_are_split_into_frames_that_fit() {
    let answer: Answerer = Box::new(|request| match request {
        DebugRequest::FrameWrite { values, .. } => {
            let bytes: usize = values.iter().map(|(_, v)| 6 + v.len()).sum();
            assert!(
                20 + bytes <= MAX_PAYLOAD_BYTES,
                "{bytes} bytes in one write"
            );
            Ok(DebugResponse::FrameWrite)
        }
        _ => Err(Refusal::bad("unexpected")),
    });
    let (mut client, seen) = fake(answer).await;
    client
        .frame_write(0, 1, &[(0, vec![1; 500]), (600, vec![2; 4])])
        .await
        .unwrap();
    let written: Vec<(u32, usize)> = seen
        .lock()
        .unwrap()
        .iter()
        .flat_map(|request| match request {
            DebugRequest::FrameWrite { values, .. } => values
                .iter()
                .map(|(range, v)| (range.offset, v.len()))
                .collect::<Vec<_>>(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(written, [(0, 224), (224, 224), (448, 52), (600, 4)]);
}

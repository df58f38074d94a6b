//! The session's debugging events against a small fake runtime on loopback: attaching, halts
//! reported once per change with their call stacks, breakpoints replaced with their refusals
//! named, and a detach at the session's end.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use std::net::SocketAddr;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use online_protocol::{DebugRequest, DebugResponse, HaltReason, HaltState, Refusal, SessionState};
use tokio::sync::mpsc;

use super::super::{Command, Event, SessionOptions, spawn};
use super::*;

/// What the fake runtime knows: the halt state's generation and whether task 0 is halted.
#[derive(Default)]
struct Fake {
    generation: u32,
    halted: bool,
    seen: Vec<DebugRequest>,
}

fn task(halted: bool) -> TaskHalt {
    TaskHalt {
        task: 0,
        state: if halted {
            TaskDebugState::Halted
        } else {
            TaskDebugState::Running
        },
        reason: HaltReason::Breakpoint,
        breakpoint: halted.then_some(1),
        pou: if halted { 2 } else { 0 },
        instruction: if halted { 7 } else { 0 },
        depth: u16::from(halted),
        cycle: 0,
        halted_ms: 0,
    }
}

fn answer(fake: &mut Fake, request: &DebugRequest) -> Result<DebugResponse, Refusal> {
    fake.seen.push(request.clone());
    Ok(match request {
        DebugRequest::Attach { .. } => DebugResponse::Attach {
            took_over: false,
            halted: 0,
            breakpoints: 0,
        },
        DebugRequest::Detach { .. } => DebugResponse::Detach,
        DebugRequest::BreakClear { .. } => DebugResponse::BreakClear,
        DebugRequest::BreakSet { breakpoint, .. } => {
            if breakpoint.pou == 9 {
                return Err(Refusal::bad(
                    "no statement starts at instruction 3 of POU 9",
                ));
            }
            DebugResponse::BreakSet {
                id: 1,
                replaced: false,
            }
        }
        DebugRequest::HaltState { .. } => DebugResponse::HaltState(HaltState {
            session: SessionState::Attached,
            options: DebugOptions::default(),
            generation: fake.generation,
            total: 1,
            tasks: vec![task(fake.halted)],
        }),
        DebugRequest::Stack { .. } => DebugResponse::Stack {
            total: 1,
            frames: vec![StackFrame {
                pou: 2,
                instruction: 7,
                instance: 1 << 56,
                frame: 0,
                frame_bytes: 0,
            }],
        },
        DebugRequest::Continue { .. } => {
            fake.halted = false;
            fake.generation += 1;
            DebugResponse::Continue
        }
        DebugRequest::FlowConfigure { .. } => DebugResponse::FlowConfigure,
        // Entry `i` has bit `i` set; the cycle so far is numbered 100, the last complete 99.
        DebugRequest::FlowRead { entry, which, .. } => DebugResponse::FlowRead {
            cycle: match which {
                FlowCycle::Current => 100,
                FlowCycle::LastComplete => 99,
            },
            statements: 8,
            bitmap: vec![1 << entry],
        },
        other => return Err(Refusal::bad(format!("unexpected {other:?}"))),
    })
}

/// Serves connections on 127.0.0.1 from `fake`.
async fn serve(fake: Arc<Mutex<Fake>>) -> SocketAddr {
    crate::fake_target::serve(move |debug| answer(&mut fake.lock().unwrap(), debug)).await
}

/// The next event that is not a snapshot, waiting at most five seconds.
async fn next(events: &mut mpsc::Receiver<Event>) -> Event {
    tokio::time::timeout(Duration::from_secs(5), events.recv())
        .await
        .expect("an event within five seconds")
        .expect("the session runs")
}

#[tokio::test]
async fn an_attached_session_reports_each_halt_once_with_its_stack_and_detaches_at_the_end() {
    let fake = Arc::new(Mutex::new(Fake::default()));
    let address = serve(Arc::clone(&fake)).await;
    let (commands, mut events) = spawn(SessionOptions {
        address,
        password: None,
        poll_interval: Duration::from_millis(50),
        reconnect_interval: Duration::from_secs(1),
    });
    assert!(matches!(next(&mut events).await, Event::Connected(_)));
    commands
        .send(Command::Debug(DebugCommand::Attach))
        .await
        .unwrap();
    assert!(matches!(next(&mut events).await, Event::DebugAttached(_)));
    // The first look reports that nothing is halted.
    match next(&mut events).await {
        Event::Halted(tasks) => assert!(tasks.is_empty()),
        other => panic!("{other:?}"),
    }
    {
        let mut fake = fake.lock().unwrap();
        fake.halted = true;
        fake.generation = 1;
    }
    match next(&mut events).await {
        Event::Halted(tasks) => {
            assert_eq!(tasks.len(), 1);
            assert_eq!(tasks[0].halt.state, TaskDebugState::Halted);
            assert_eq!(tasks[0].frames[0].instruction, 7);
        }
        other => panic!("{other:?}"),
    }
    // The same generation again is not reported: the next event is the continue's own.
    tokio::time::sleep(HALT_POLL_INTERVAL * 3).await;
    commands
        .send(Command::Debug(DebugCommand::Continue(0)))
        .await
        .unwrap();
    match next(&mut events).await {
        Event::Halted(tasks) => assert!(tasks.is_empty()),
        other => panic!("{other:?}"),
    }
    let stacks = fake
        .lock()
        .unwrap()
        .seen
        .iter()
        .filter(|request| matches!(request, DebugRequest::Stack { .. }))
        .count();
    assert_eq!(stacks, 1, "the stack is read once per change");
    commands.send(Command::Close).await.unwrap();
    while events.recv().await.is_some() {}
    let seen = &fake.lock().unwrap().seen;
    assert!(matches!(seen.last(), Some(DebugRequest::Detach { .. })));
}

#[tokio::test]
async fn breakpoints_are_replaced_and_each_refusal_is_named_in_its_place() {
    let fake = Arc::new(Mutex::new(Fake::default()));
    let address = serve(Arc::clone(&fake)).await;
    let (commands, mut events) = spawn(SessionOptions {
        address,
        password: None,
        poll_interval: Duration::from_millis(50),
        reconnect_interval: Duration::from_secs(1),
    });
    assert!(matches!(next(&mut events).await, Event::Connected(_)));
    let spec = |pou| BreakpointSpec {
        pou,
        instruction: 3,
        instance: 0,
        task: online_protocol::ALL_TASKS,
        hit: online_protocol::HitRule::ALWAYS,
        condition: Vec::new(),
    };
    commands
        .send(Command::Debug(DebugCommand::SetBreakpoints(vec![
            spec(2),
            spec(9),
        ])))
        .await
        .unwrap();
    match next(&mut events).await {
        Event::BreakpointsSet(ids) => {
            assert!(matches!(ids[0], Ok(1)), "{ids:?}");
            let refused = ids[1].as_ref().unwrap_err().to_string();
            assert!(refused.contains("BREAK_SET"), "{refused}");
            assert!(refused.contains("POU 9"), "{refused}");
        }
        other => panic!("{other:?}"),
    }
    let seen = &fake.lock().unwrap().seen;
    assert!(matches!(seen[0], DebugRequest::BreakClear { .. }));
    // Not attached: no halt is polled.
    assert!(
        !seen
            .iter()
            .any(|request| matches!(request, DebugRequest::HaltState { .. }))
    );
}

#[tokio::test]
async fn flow_is_read_for_every_recording_task_and_from_the_cycle_so_far_of_a_halted_one() {
    let fake = Arc::new(Mutex::new(Fake {
        generation: 1,
        halted: true,
        seen: Vec::new(),
    }));
    let address = serve(Arc::clone(&fake)).await;
    let (commands, mut events) = spawn(SessionOptions {
        address,
        password: None,
        poll_interval: Duration::from_millis(50),
        reconnect_interval: Duration::from_secs(1),
    });
    assert!(matches!(next(&mut events).await, Event::Connected(_)));
    commands
        .send(Command::Debug(DebugCommand::Attach))
        .await
        .unwrap();
    assert!(matches!(next(&mut events).await, Event::DebugAttached(_)));
    match next(&mut events).await {
        Event::Halted(tasks) => assert_eq!(tasks[0].halt.task, 0),
        other => panic!("{other:?}"),
    }
    let entry = |pou| FlowEntry { pou, instance: 0 };
    // Task 1 is configured first; the entries are read in task order all the same.
    for (task, pou) in [(1, 5), (0, 4)] {
        let entries = vec![entry(pou)];
        commands
            .send(Command::Debug(DebugCommand::Flow { task, entries }))
            .await
            .unwrap();
    }
    let bitmaps = loop {
        match next(&mut events).await {
            Event::Flow { bitmaps } if bitmaps.len() == 2 => break bitmaps,
            _ => {}
        }
    };
    let read: Vec<(u8, u32, u64, Vec<u8>)> = bitmaps
        .into_iter()
        .map(|(task, entry, bitmap)| (task, entry.pou, bitmap.cycle, bitmap.bitmap))
        .collect();
    // Task 0 is halted: its cycle so far; task 1 runs: its last complete cycle.
    assert_eq!(read, vec![(0, 4, 100, vec![1]), (1, 5, 99, vec![2])]);

    // An empty list ends task 0's recording only.
    commands
        .send(Command::Debug(DebugCommand::Flow {
            task: 0,
            entries: Vec::new(),
        }))
        .await
        .unwrap();
    loop {
        match next(&mut events).await {
            Event::Flow { bitmaps } if bitmaps.len() == 1 => {
                assert_eq!((bitmaps[0].0, bitmaps[0].1.pou), (1, 5));
                break;
            }
            _ => {}
        }
    }
}

use std::sync::Arc;
use std::time::Instant;

use online_protocol::{
    Answer, DebugOptions, DebugRequest, DebugResponse, Request, Response, SessionState, Status,
    TaskDebugState,
};
use program_image::LineEntry;

use crate::areas::LocatedAreas;
use crate::online::OnlineServices;
use crate::scheduler::{Scheduler, SchedulerOptions};
use crate::test_images::{TestTask, image};

/// Services on a running scheduler with one counting task every millisecond whose first
/// instruction starts a statement; no password.
fn services(debug: bool) -> Arc<OnlineServices> {
    let areas = Arc::new(std::sync::Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).expect("spawns");
    let mut image = image(&[TestTask::cyclic(1_000_000, 1)], &[]);
    image.pous[0].lines = vec![LineEntry {
        index: 0,
        file: 0,
        line: 1,
    }];
    scheduler.load(image).expect("loads");
    scheduler.start().expect("starts");
    Arc::new(OnlineServices::new(Arc::new(scheduler), None).with_debugging(debug))
}

fn ask(services: &OnlineServices, connection: u64, request: DebugRequest) -> Answer {
    let request = Request::Debug(request);
    let body = services
        .respond_from(Some(connection), &request.encode())
        .expect("an answer");
    Response::decode(&request, &body).expect("decodes")
}

fn attach(linger_s: u16) -> DebugRequest {
    DebugRequest::Attach {
        token: 0,
        linger_s,
        options: DebugOptions::default(),
    }
}

fn halt_state(services: &OnlineServices) -> online_protocol::HaltState {
    match ask(services, 9, DebugRequest::HaltState { from: 0 }) {
        Ok(Response::Debug(DebugResponse::HaltState(state))) => state,
        other => panic!("{other:?}"),
    }
}

#[track_caller]
fn wait_for_state(services: &OnlineServices, state: TaskDebugState) {
    let start = Instant::now();
    while halt_state(services).tasks[0].state != state {
        assert!(start.elapsed().as_secs() < 10, "{:?}", halt_state(services));
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
}

#[test]
fn one_connection_attaches_halts_and_reads_the_stack_and_logging_out_resumes() {
    let services = services(true);
    let attached = ask(&services, 1, attach(0));
    assert!(matches!(
        attached,
        Ok(Response::Debug(DebugResponse::Attach {
            took_over: false,
            ..
        }))
    ));
    let refused = ask(&services, 2, attach(0)).expect_err("attached elsewhere");
    assert_eq!(refused.status, Status::NotNow);
    let refused =
        ask(&services, 2, DebugRequest::Halt { token: 0, task: 0 }).expect_err("not hers");
    assert_eq!(refused.status, Status::NotNow);
    ask(&services, 1, DebugRequest::Halt { token: 0, task: 0 }).expect("halts");
    wait_for_state(&services, TaskDebugState::Halted);
    let state = halt_state(&services);
    assert_eq!(state.session, SessionState::Attached);
    assert_eq!(state.tasks[0].reason, online_protocol::HaltReason::Halt);
    assert_eq!(state.tasks[0].depth, 1);
    match ask(&services, 2, DebugRequest::Stack { task: 0, from: 0 }) {
        Ok(Response::Debug(DebugResponse::Stack { total, frames })) => {
            assert_eq!((total, frames.len()), (1, 1));
            assert_eq!((frames[0].pou, frames[0].instruction), (0, 0));
        }
        other => panic!("{other:?}"),
    }
    // A frame read past the program's empty frame is outside it.
    let outside = ask(
        &services,
        2,
        DebugRequest::FrameRead {
            task: 0,
            frame: 0,
            ranges: vec![online_protocol::FrameRange { offset: 0, size: 4 }],
        },
    )
    .expect_err("outside");
    assert_eq!(outside.status, Status::BadPlace);
    // Stepping over the only statement halts at the next cycle's.
    let generation = halt_state(&services).generation;
    ask(
        &services,
        1,
        DebugRequest::Step {
            token: 0,
            task: 0,
            kind: online_protocol::StepKind::Over,
        },
    )
    .expect("steps");
    wait_for_state(&services, TaskDebugState::Halted);
    let state = halt_state(&services);
    assert!(state.generation > generation);
    assert_eq!(state.tasks[0].reason, online_protocol::HaltReason::Step);
    let logout = Request::Logout;
    services
        .respond_from(Some(1), &logout.encode())
        .expect("logs out");
    wait_for_state(&services, TaskDebugState::Running);
    assert_eq!(halt_state(&services).session, SessionState::None);
}

#[test]
fn a_closed_connection_leaves_a_lingering_session_that_another_takes_over() {
    let services = services(true);
    ask(&services, 1, attach(60)).expect("attached");
    ask(&services, 1, DebugRequest::Halt { token: 0, task: 0 }).expect("halts");
    wait_for_state(&services, TaskDebugState::Halted);
    (services.closed_handler())(1);
    assert_eq!(halt_state(&services).session, SessionState::Lingering);
    // Still halted without a connection.
    assert_eq!(halt_state(&services).tasks[0].state, TaskDebugState::Halted);
    match ask(&services, 2, attach(0)) {
        Ok(Response::Debug(DebugResponse::Attach {
            took_over, halted, ..
        })) => assert_eq!((took_over, halted), (true, 1)),
        other => panic!("{other:?}"),
    }
    ask(
        &services,
        2,
        DebugRequest::Continue {
            token: 0,
            task: 0xFF,
        },
    )
    .expect("goes on");
    wait_for_state(&services, TaskDebugState::Running);
    // With a linger of 0, closing ends the session at once.
    (services.closed_handler())(2);
    assert_eq!(halt_state(&services).session, SessionState::None);
}

#[test]
fn a_runtime_with_debugging_off_refuses_to_attach_and_says_so() {
    let services = services(false);
    let refused = ask(&services, 1, attach(0)).expect_err("off");
    assert_eq!(refused.status, Status::NotNow);
    assert!(
        refused.message.contains("--debug off"),
        "{}",
        refused.message
    );
    let identify = Request::Identify {
        protocol: online_protocol::PROTOCOL_VERSION,
    };
    let body = services
        .respond_from(Some(1), &identify.encode())
        .expect("answers");
    match Response::decode(&identify, &body) {
        Ok(Ok(Response::Identify(identity))) => assert!(identity.debug.switched_off),
        other => panic!("{other:?}"),
    }
}

#[test]
fn flow_recording_marks_the_statements_of_the_last_complete_cycle() {
    let services = services(true);
    ask(&services, 1, attach(0)).expect("attached");
    let read = DebugRequest::FlowRead {
        entry: 0,
        which: online_protocol::FlowCycle::LastComplete,
        from: 0,
    };
    assert_eq!(
        ask(&services, 1, read.clone()).expect_err("none").status,
        Status::NotNow
    );
    ask(
        &services,
        1,
        DebugRequest::FlowConfigure {
            token: 0,
            task: 0,
            entries: vec![online_protocol::FlowEntry {
                pou: 0,
                instance: 0,
            }],
        },
    )
    .expect("configured");
    let start = Instant::now();
    loop {
        match ask(&services, 1, read.clone()) {
            Ok(Response::Debug(DebugResponse::FlowRead {
                cycle,
                statements,
                bitmap,
            })) if cycle > 0 => {
                assert_eq!((statements, bitmap), (1, vec![1]));
                break;
            }
            Ok(_) => assert!(start.elapsed().as_secs() < 10, "no cycle recorded"),
            Err(refusal) => panic!("{refusal:?}"),
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    let odd = DebugRequest::FlowRead {
        entry: 0,
        which: online_protocol::FlowCycle::Current,
        from: 3,
    };
    assert_eq!(
        ask(&services, 1, odd).expect_err("odd").status,
        Status::BadRequest
    );
}

#[test]
fn a_lingering_session_ends_when_its_time_is_up_and_the_halted_task_goes_on() {
    let services = services(true);
    ask(&services, 1, attach(1)).expect("attached");
    ask(&services, 1, DebugRequest::Halt { token: 0, task: 0 }).expect("halts");
    wait_for_state(&services, TaskDebugState::Halted);
    (services.closed_handler())(1);
    assert_eq!(halt_state(&services).session, SessionState::Lingering);
    // Nobody asks anything until well after the second of linger.
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let status = services
        .respond_from(
            Some(2),
            &Request::Identify {
                protocol: online_protocol::PROTOCOL_VERSION,
            }
            .encode(),
        )
        .expect("answers");
    // The debug byte is the last: no session, nothing halted.
    assert_eq!(status.last(), Some(&0));
}

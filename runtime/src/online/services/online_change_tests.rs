use std::sync::{Arc, Mutex};

use online_protocol::{
    BreakpointSpec, ChangeCheck, DebugOptions, DebugRequest, DebugResponse, HitRule, Request,
    Response, TaskDebugState,
};
use program_image::{LineEntry, ProgramImage};
use sha2::{Digest, Sha256};

use super::super::OnlineServices;
use crate::areas::LocatedAreas;
use crate::engine::ChangeRefusal;
use crate::scheduler::{Scheduler, SchedulerOptions};
use crate::test_images::{TestTask, image};

const MS: u64 = 1_000_000;

fn services(password: Option<&str>, running: &ProgramImage) -> OnlineServices {
    let areas = Arc::new(Mutex::new(LocatedAreas::default()));
    let scheduler = Scheduler::spawn(areas, SchedulerOptions::default()).unwrap();
    scheduler.load(running.clone()).unwrap();
    scheduler.start().unwrap();
    OnlineServices::new(Arc::new(scheduler), password.map(str::to_owned))
}

fn answer(services: &OnlineServices, request: &Request) -> online_protocol::Answer {
    Response::decode(request, &services.respond(&request.encode()).unwrap()).unwrap()
}

/// Transfers `image` and returns the transfer's number.
fn transfer(services: &OnlineServices, token: u128, image: &ProgramImage) -> u16 {
    let bytes = image.encode();
    let begin = Request::DownloadBegin {
        token,
        size: bytes.len() as u32,
        hash: Sha256::digest(&bytes).into(),
    };
    let Ok(Response::DownloadBegin {
        transfer,
        chunk_size,
    }) = answer(services, &begin)
    else {
        panic!("the transfer did not begin");
    };
    for (index, chunk) in bytes.chunks(usize::from(chunk_size)).enumerate() {
        let request = Request::DownloadChunk {
            token,
            transfer,
            offset: (index * usize::from(chunk_size)) as u32,
            bytes: chunk.to_vec(),
        };
        assert!(answer(services, &request).is_ok());
    }
    transfer
}

fn check(services: &OnlineServices, token: u128, transfer: u16) -> ChangeCheck {
    match answer(services, &Request::OnlineChangeCheck { token, transfer }) {
        Ok(Response::OnlineChangeCheck(check)) => check,
        other => panic!("no check: {other:?}"),
    }
}

#[test]
fn a_checked_change_lists_its_details_and_applies_and_a_task_change_is_refused_with_its_reason() {
    let running = image(&[TestTask::cyclic(10 * MS, 1)], &[]);
    let services = services(None, &running);

    let mut faster = running.clone();
    faster.tasks[0].interval_ns = 5 * MS;
    let id = transfer(&services, 0, &faster);
    let refused = check(&services, 0, id);
    assert!(!refused.possible);
    assert_eq!(refused.reason, 3);
    assert_eq!(
        refused.why,
        "task 'Task0': interval changed from 10 ms to 5 ms"
    );
    let apply = Request::OnlineChangeApply {
        token: 0,
        transfer: id,
    };
    assert_eq!(answer(&services, &apply).unwrap_err().status.number(), 7);

    let mut changed = running.clone();
    changed.pous[0].code.push(program_image::Instr::Return);
    let id = transfer(&services, 0, &changed);
    // Applying needs a check of this very transfer.
    let apply = Request::OnlineChangeApply {
        token: 0,
        transfer: id,
    };
    assert_eq!(answer(&services, &apply).unwrap_err().status.number(), 7);
    let possible = check(&services, 0, id);
    assert!(possible.possible, "{possible:?}");
    assert_eq!((possible.pous_changed, possible.details), (1, 1));
    let details = answer(
        &services,
        &Request::OnlineChangeDetails {
            token: 0,
            transfer: id,
            from: 0,
        },
    );
    let Ok(Response::OnlineChangeDetails { total, details }) = details else {
        panic!("no details: {details:?}");
    };
    assert_eq!(total, 1);
    assert_eq!((details[0].kind, details[0].name.as_str()), (0, "Program0"));
    let applied = answer(&services, &apply);
    assert!(
        matches!(applied, Ok(Response::OnlineChangeApply(_))),
        "{applied:?}"
    );
    assert_eq!(
        services.scheduler.status().image,
        Some(changed.identity()),
        "the new program runs"
    );
    // The transfer has ended with the switch.
    assert_eq!(answer(&services, &apply).unwrap_err().status.number(), 7);
}

#[test]
fn online_change_needs_the_token_of_the_password() {
    let running = image(&[TestTask::cyclic(10 * MS, 1)], &[]);
    let services = services(Some("secret"), &running);
    for request in [
        Request::OnlineChangeCheck {
            token: 0,
            transfer: 1,
        },
        Request::OnlineChangeDetails {
            token: 0,
            transfer: 1,
            from: 0,
        },
        Request::OnlineChangeApply {
            token: 0,
            transfer: 1,
        },
    ] {
        assert_eq!(answer(&services, &request).unwrap_err().status.number(), 3);
    }
}

/// A debug request from connection 1, the one the debug session is attached to.
fn debug(services: &OnlineServices, request: DebugRequest) -> online_protocol::Answer {
    let request = Request::Debug(request);
    Response::decode(
        &request,
        &services.respond_from(Some(1), &request.encode()).unwrap(),
    )
    .unwrap()
}

/// Waits until task 0 is in `state`, for at most ten seconds.
#[track_caller]
fn wait_for_task_state(services: &OnlineServices, state: TaskDebugState) {
    let start = std::time::Instant::now();
    loop {
        let answer = debug(services, DebugRequest::HaltState { from: 0 });
        let Ok(Response::Debug(DebugResponse::HaltState(halt))) = answer else {
            panic!("no halt state: {answer:?}");
        };
        if halt.tasks[0].state == state {
            return;
        }
        assert!(start.elapsed().as_secs() < 10, "{halt:?}");
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
}

#[test]
fn an_online_change_is_refused_while_a_task_is_halted_at_a_breakpoint_and_applies_once_it_goes_on()
{
    let mut running = image(&[TestTask::cyclic(MS, 1)], &[]);
    running.pous[0].lines = vec![LineEntry {
        index: 0,
        file: 0,
        line: 1,
    }];
    let services = services(None, &running).with_debugging(true);
    let attach = DebugRequest::Attach {
        token: 0,
        linger_s: 0,
        options: DebugOptions::default(),
    };
    assert!(debug(&services, attach).is_ok());
    let set = DebugRequest::BreakSet {
        token: 0,
        breakpoint: BreakpointSpec {
            pou: 0,
            instruction: 0,
            instance: 0,
            task: 0xFF,
            hit: HitRule::ALWAYS,
            condition: Vec::new(),
        },
    };
    assert!(debug(&services, set).is_ok());
    wait_for_task_state(&services, TaskDebugState::Halted);

    let mut changed = running.clone();
    changed.pous[0].code.push(program_image::Instr::Return);
    let id = transfer(&services, 0, &changed);
    let refused = check(&services, 0, id);
    assert!(!refused.possible, "{refused:?}");
    assert_eq!(refused.reason, ChangeRefusal::Halted.number());
    assert_eq!(refused.reason, 6, "the number protocol §7 gives");
    assert_eq!(
        refused.why,
        "task 'Task0' is halted or stepping: continue it first"
    );
    let apply = Request::OnlineChangeApply {
        token: 0,
        transfer: id,
    };
    assert_eq!(answer(&services, &apply).unwrap_err().status.number(), 7);
    assert_eq!(services.scheduler.status().image, Some(running.identity()));

    // Without the breakpoint and with the task going on, the same transfer checks and applies.
    let clear = DebugRequest::BreakClear {
        token: 0,
        id: 0xFFFF,
    };
    assert!(debug(&services, clear).is_ok());
    let go_on = DebugRequest::Continue {
        token: 0,
        task: 0xFF,
    };
    assert!(debug(&services, go_on).is_ok());
    wait_for_task_state(&services, TaskDebugState::Running);
    let possible = check(&services, 0, id);
    assert!(possible.possible, "{possible:?}");
    let applied = answer(&services, &apply);
    assert!(
        matches!(applied, Ok(Response::OnlineChangeApply(_))),
        "{applied:?}"
    );
    assert_eq!(services.scheduler.status().image, Some(changed.identity()));
}

use std::sync::{Arc, Mutex};

use online_protocol::{ChangeCheck, Request, Response};
use program_image::ProgramImage;
use sha2::{Digest, Sha256};

use super::super::OnlineServices;
use crate::areas::LocatedAreas;
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

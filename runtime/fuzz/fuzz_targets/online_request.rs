//! Fuzzes the online services: any bytes after function code 0x64, parsed and served on a
//! stopped scheduler with a small program, must be answered without a panic by a response
//! that fits a frame and names the request's service. `START` is left out; a commit with
//! start almost never passes the hash check.

#![no_main]

use std::sync::{Arc, Mutex, OnceLock};

use libfuzzer_sys::fuzz_target;
use online_protocol::{FUNCTION_CODE, MAX_PAYLOAD_BYTES, Request};
use program_image::ProgramImage;
use runtime::areas::LocatedAreas;
use runtime::online::OnlineServices;
use runtime::scheduler::{Scheduler, SchedulerOptions};

/// The services, shared by every input: a stopped scheduler with the image in
/// `RIVET_FUZZ_IMAGE` if set (a `rivet build` output), else without a program.
fn services() -> &'static Arc<OnlineServices> {
    static SERVICES: OnlineLock = OnceLock::new();
    SERVICES.get_or_init(|| {
        let areas = Arc::new(Mutex::new(LocatedAreas::default()));
        let scheduler = Scheduler::spawn(areas, SchedulerOptions::default())
            .unwrap_or_else(|error| panic!("cannot start the scheduler: {error}"));
        if let Some(path) = std::env::var_os("RIVET_FUZZ_IMAGE") {
            let bytes = std::fs::read(path).unwrap_or_else(|error| panic!("{error}"));
            let image = ProgramImage::decode(&bytes).unwrap_or_else(|error| panic!("{error}"));
            scheduler
                .load(image)
                .unwrap_or_else(|error| panic!("{error}"));
        }
        Arc::new(OnlineServices::new(Arc::new(scheduler), None))
    })
}

type OnlineLock = OnceLock<Arc<OnlineServices>>;

/// `START`: left out so that the scheduler stays stopped and every input meets the same state.
const START: u8 = 0x20;

fuzz_target!(|data: &[u8]| {
    let request = &data[..data.len().min(252)];
    if request.first() == Some(&START) {
        return;
    }
    let _ = Request::decode(request);
    let handler = services().handler();
    match handler(FUNCTION_CODE, request) {
        Ok(body) => {
            assert!(body.len() >= 2 && body.len() <= MAX_PAYLOAD_BYTES + 2);
            assert_eq!(Some(&body[0]), request.first());
        }
        Err(_) => assert!(request.is_empty()),
    }
});

//! Fuzzes loading a program image: any bytes, given a correct identity hash so that they reach
//! the section decoders and the verifier, must be refused with an error or decode to an image
//! that the engine either refuses or loads and runs for one cycle of every task, all without a
//! panic, in the interpreter and in the native engine (whose outcomes are not compared here:
//! the differential harness does that). A watchdog of 10 ms ends any cycle that loops. The bytes are also tried as a
//! breakpoint condition of every POU of a decoded image.

#![no_main]

use libfuzzer_sys::fuzz_target;
use program_image::{BreakCondition, ProgramImage};
use runtime::engine::{Engine, EngineChoice};
use sha2::{Digest, Sha256};

fuzz_target!(|data: &[u8]| {
    // The input is an image without its trailer; the raw bytes are tried as they are too.
    let _ = ProgramImage::decode(data);
    let mut bytes = data.to_vec();
    bytes.extend_from_slice(&Sha256::digest(data));
    let Ok(mut image) = ProgramImage::decode(&bytes) else {
        return;
    };
    assert_eq!(ProgramImage::decode(&image.encode()).as_ref(), Ok(&image));
    // The same bytes as a breakpoint condition for every POU: decoding and verifying it never
    // panic, whatever the image.
    if let Ok(condition) = BreakCondition::decode(data) {
        for pou in 0..image.pous.len() {
            let _ = image.verify_condition(pou as u32, &condition);
        }
    }
    for task in &mut image.tasks {
        task.watchdog_ns = 10_000_000;
        task.watchdog_sensitivity = 1;
    }
    for choice in [EngineChoice::Interpreter, EngineChoice::Native] {
        let Ok((mut engine, _)) = Engine::with_choice(image.clone(), choice) else {
            return;
        };
        for task in 0..engine.image().tasks.len() {
            let _ = engine.run_cycle(task, 1_000_000, 0);
        }
    }
});

//! Fuzzes the decoders of the online protocol: any bytes are decoded as a request and as the
//! response to a request, without a panic, and whatever decodes encodes back to what decodes
//! to the same value.
//!
//! The first byte says how many of the following bytes are the request (the rest is the
//! response), so that READ answers meet the places of their own request.

#![no_main]

use libfuzzer_sys::fuzz_target;
use online_protocol::{Request, Response};

fuzz_target!(|data: &[u8]| {
    let Some((&split, rest)) = data.split_first() else {
        return;
    };
    let (request_bytes, response_bytes) = rest.split_at(usize::from(split).min(rest.len()));
    // Every byte string as a request.
    if let Ok(request) = Request::decode(rest) {
        assert_eq!(Request::decode(&request.encode()).as_ref(), Ok(&request));
    }
    let Ok(request) = Request::decode(request_bytes) else {
        // Still a response to some request, so the answer decoders see every input.
        let _ = Response::decode(&Request::Tasks, response_bytes);
        return;
    };
    assert_eq!(Request::decode(&request.encode()).as_ref(), Ok(&request));
    match Response::decode(&request, response_bytes) {
        Ok(Ok(response)) => {
            let again = Response::decode(&request, &response.encode());
            assert_eq!(again, Ok(Ok(response)));
        }
        Ok(Err(refusal)) => {
            let again = Response::decode(&request, &refusal.encode(request.service().number()));
            // A message longer than the runtime sends is cut when encoded again.
            if refusal.message.len() <= online_protocol::MAX_TEXT_BYTES {
                assert_eq!(again, Ok(Err(refusal)));
            }
        }
        Err(_) => {}
    }
});

//! Fuzzes the Modbus request handling: any bytes, read as an MBAP header and a request PDU
//! against areas of a size chosen by the first byte, must be answered without a panic by a
//! response that fits a frame, names the request's function code, and leaves the areas
//! untouched whenever it is an exception.

#![no_main]

use libfuzzer_sys::fuzz_target;
use runtime::areas::LocatedAreas;
use runtime::modbus::{HEADER_BYTES, MAX_PDU_BYTES, MbapHeader, ModbusMap, handle_pdu};

fuzz_target!(|data: &[u8]| {
    let Some((&sizes, rest)) = data.split_first() else {
        return;
    };
    if let Some(header) = rest.first_chunk::<HEADER_BYTES>() {
        if let Ok(header) = MbapHeader::parse(*header) {
            assert!((1..=MAX_PDU_BYTES).contains(&header.pdu_bytes));
        }
    }
    // Small areas make "address beyond the area" reachable, full ones every mapped address.
    let mut areas = if sizes & 1 == 0 {
        LocatedAreas::new(
            usize::from(sizes >> 4),
            usize::from(sizes >> 2),
            usize::from(sizes),
        )
    } else {
        LocatedAreas::new(1024, 1024, 8192)
    };
    for (index, byte) in areas.memory.iter_mut().enumerate() {
        *byte = index as u8;
    }
    let before = areas.clone();
    let request = &rest[..rest.len().min(MAX_PDU_BYTES)];
    let response = handle_pdu(&mut areas, &ModbusMap::default(), request);
    assert!((2..=MAX_PDU_BYTES).contains(&response.len()));
    let function = request.first().copied().unwrap_or(0);
    if response[0] & 0x80 != 0 {
        assert_eq!(response[0], function | 0x80);
        assert_eq!(response.len(), 2);
        assert!((1..=3).contains(&response[1]));
        assert!(areas == before, "an exception changed the areas");
    } else {
        assert_eq!(response[0], function);
    }
});

//! The exchange merges what the program and clients wrote, whichever exchange was skipped.

use super::*;

/// The exchange of all three areas at the start of a cycle.
fn exchange(areas: &mut LocatedAreas, input: &mut [u8], output: &mut [u8], memory: &mut [u8]) {
    areas.exchange(Area::Input, input);
    areas.exchange(Area::Output, output);
    areas.exchange(Area::Memory, memory);
}

#[test]
fn without_client_writes_the_program_gives_q_and_m_and_takes_i() {
    let mut areas = LocatedAreas::new(2, 2, 2);
    areas.input = vec![7, 8];
    let (mut input, mut output, mut memory) = ([0; 2], [1, 2], [3, 4]);
    exchange(&mut areas, &mut input, &mut output, &mut memory);
    assert_eq!(input, [7, 8]);
    assert_eq!((output, memory), ([1, 2], [3, 4]));
    assert_eq!(
        (&areas.output[..], &areas.memory[..]),
        (&[1, 2][..], &[3, 4][..])
    );
}

#[test]
fn a_client_write_outlives_a_publish_and_is_taken_in_at_the_next_exchange() {
    let mut areas = LocatedAreas::new(0, 2, 4);
    let (mut output, mut memory) = ([0u8; 2], [0u8; 4]);
    exchange(&mut areas, &mut [], &mut output, &mut memory);
    // During the cycle a client sets %QX1.3 and %MW1; the program writes both bytes of %QB1.
    areas.set_bit(Area::Output, 1, 3, true).unwrap();
    areas.set_word_at_byte(Area::Memory, 2, 0xBEEF).unwrap();
    output = [0x10, 0x01];
    memory = [5, 6, 7, 8];
    areas.publish(&output, &memory);
    assert_eq!(areas.output, [0x10, 0x09]);
    assert_eq!(areas.memory, [5, 6, 0xEF, 0xBE]);
    exchange(&mut areas, &mut [], &mut output, &mut memory);
    assert_eq!(output, [0x10, 0x09]);
    assert_eq!(memory, [5, 6, 0xEF, 0xBE]);
    // Taken in: the program's next writes win.
    output = [0, 0];
    areas.publish(&output, &memory);
    assert_eq!(areas.output, [0, 0]);
}

#[test]
fn a_skipped_exchange_loses_neither_the_program_writes_nor_the_client_ones() {
    let mut areas = LocatedAreas::new(0, 2, 0);
    let mut output = [0u8; 2];
    exchange(&mut areas, &mut [], &mut output, &mut []);
    // The program wrote %QB0 and %QX1.0, but its publish was skipped (the lock was busy); a
    // client cleared %QX1.1 and set %QX1.2 meanwhile.
    output = [0x55, 0x03];
    areas.set_bit(Area::Output, 1, 1, false).unwrap();
    areas.set_bit(Area::Output, 1, 2, true).unwrap();
    exchange(&mut areas, &mut [], &mut output, &mut []);
    assert_eq!(output, [0x55, 0x05]);
    assert_eq!(areas.output, [0x55, 0x05]);
}

#[test]
fn inputs_are_not_marked_and_forgotten_writes_are_overwritten() {
    let mut areas = LocatedAreas::new(1, 1, 0);
    areas.set_bit(Area::Input, 0, 0, true).unwrap();
    areas.set_bit(Area::Output, 0, 0, true).unwrap();
    areas.forget_writes();
    areas.publish(&[0], &[]);
    assert_eq!((areas.input[0], areas.output[0]), (1, 0));
}

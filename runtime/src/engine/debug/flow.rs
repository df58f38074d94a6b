//! Flow recording (`docs/protocol.md` §6.2, "Flow control"): which statements of the listed
//! POUs one task ran in its last complete cycle and in the current one.

/// One recorded POU: its statements' bits for the cycle in progress and the last complete one.
#[derive(Clone, Debug)]
pub struct FlowTrack {
    /// The POU's index in the image's code section.
    pub pou: u32,
    /// The instance as a pointer value; 0 for every instance.
    pub instance: u64,
    /// How many entries the POU's line table has (bits of a bitmap).
    pub statements: u32,
    /// The bits of the cycle in progress.
    pub current: Vec<u8>,
    /// The bits of the last complete cycle.
    pub last: Vec<u8>,
    /// The task's count of finished cycles the last bitmap belongs to; 0 before the first.
    pub last_cycle: u64,
}

/// What one task records.
#[derive(Clone, Debug)]
pub struct FlowRecording {
    /// The recorded task.
    pub task: usize,
    /// The recorded POUs, in the order they were configured.
    pub tracks: Vec<FlowTrack>,
}

impl FlowTrack {
    /// A track of `statements` statements of POU `pou`, nothing recorded yet.
    pub(crate) fn new(pou: u32, instance: u64, statements: u32) -> Self {
        let bytes = statements.div_ceil(8) as usize;
        Self {
            pou,
            instance,
            statements,
            current: vec![0; bytes],
            last: vec![0; bytes],
            last_cycle: 0,
        }
    }

    /// Notes that the statement of line-table entry `entry` started.
    pub(crate) fn mark(&mut self, entry: u32) {
        if let Some(byte) = self.current.get_mut((entry / 8) as usize) {
            *byte |= 1 << (entry % 8);
        }
    }

    /// The cycle numbered `cycle` (finished cycles) is complete: its bits become the last.
    pub(crate) fn end_cycle(&mut self, cycle: u64) {
        std::mem::swap(&mut self.current, &mut self.last);
        self.current.fill(0);
        self.last_cycle = cycle;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cycle_end_keeps_its_bits_as_the_last_and_starts_again() {
        let mut track = FlowTrack::new(0, 0, 10);
        track.mark(0);
        track.mark(9);
        track.mark(40);
        assert_eq!(track.current, vec![0b1, 0b10]);
        track.end_cycle(7);
        assert_eq!((track.last.clone(), track.last_cycle), (vec![1, 2], 7));
        assert_eq!(track.current, vec![0, 0]);
    }
}

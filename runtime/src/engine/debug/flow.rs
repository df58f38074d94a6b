//! Flow recording (`docs/protocol.md` §6.2, "Flow control"): which statements of the listed
//! POUs each recorded task ran in its last complete cycle and in the current one. Every task
//! has its own list, so a POU called from two tasks is recorded in both, each by its cycles.

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

/// The recordings of every task that records, in task order; lives with the debug session.
#[derive(Clone, Debug, Default)]
pub struct FlowRecordings {
    /// One recording per recorded task, sorted by task, none with an empty list.
    recordings: Vec<FlowRecording>,
}

impl FlowRecordings {
    /// Whether no task records.
    pub fn is_empty(&self) -> bool {
        self.recordings.is_empty()
    }

    /// Entry `entry` of the lists of every task taken one after the other in task order
    /// (`FLOW_READ`'s numbering), with the task that records it.
    pub fn entry(&self, entry: usize) -> Option<(usize, &FlowTrack)> {
        self.recordings
            .iter()
            .flat_map(|recording| recording.tracks.iter().map(|track| (recording.task, track)))
            .nth(entry)
    }

    /// How many entries the lists of every task have together.
    pub fn entry_count(&self) -> usize {
        self.recordings.iter().map(|r| r.tracks.len()).sum()
    }

    /// Whether some task's list records POU `pou`.
    pub fn records(&self, pou: u32) -> bool {
        self.recordings
            .iter()
            .any(|recording| recording.tracks.iter().any(|track| track.pou == pou))
    }

    /// Whether task `task` records.
    pub fn records_task(&self, task: usize) -> bool {
        self.recordings
            .iter()
            .any(|recording| recording.task == task)
    }

    /// Replaces task `task`'s list with `tracks`; an empty list ends that task's recording
    /// and leaves the other tasks' as they are.
    pub(crate) fn configure(&mut self, task: usize, tracks: Vec<FlowTrack>) {
        let at = self.recordings.partition_point(|r| r.task < task);
        let known = self.recordings.get(at).is_some_and(|r| r.task == task);
        match (known, tracks.is_empty()) {
            (true, true) => {
                self.recordings.remove(at);
            }
            (true, false) => {
                if let Some(recording) = self.recordings.get_mut(at) {
                    recording.tracks = tracks;
                }
            }
            (false, false) => self.recordings.insert(at, FlowRecording { task, tracks }),
            (false, true) => {}
        }
    }

    /// Task `task`'s recording, if it records.
    pub(crate) fn of_task_mut(&mut self, task: usize) -> Option<&mut FlowRecording> {
        self.recordings.iter_mut().find(|r| r.task == task)
    }

    /// Task `task` completed its cycle: `finished` cycles are done now; the other tasks'
    /// cycles go on, so their bits stay.
    pub(crate) fn end_cycle(&mut self, task: usize, finished: u64) {
        if let Some(recording) = self.of_task_mut(task) {
            for track in &mut recording.tracks {
                track.end_cycle(finished);
            }
        }
    }
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

    #[test]
    fn each_task_has_its_own_list_and_entries_are_numbered_in_task_order() {
        let mut flow = FlowRecordings::default();
        flow.configure(2, vec![FlowTrack::new(5, 0, 8)]);
        flow.configure(0, vec![FlowTrack::new(5, 0, 8), FlowTrack::new(6, 0, 3)]);
        assert_eq!(flow.entry_count(), 3);
        let entry = |flow: &FlowRecordings, index| flow.entry(index).map(|(t, k)| (t, k.pou));
        assert_eq!(entry(&flow, 0), Some((0, 5)));
        assert_eq!(entry(&flow, 1), Some((0, 6)));
        assert_eq!(entry(&flow, 2), Some((2, 5)));
        assert_eq!(entry(&flow, 3), None);
        assert!(flow.records(6) && !flow.records(7));

        // A cycle of task 2 ends its bits only; task 0's cycle in progress keeps its own.
        for recording in [0, 2] {
            if let Some(recording) = flow.of_task_mut(recording) {
                recording.tracks[0].mark(1);
            }
        }
        flow.end_cycle(2, 9);
        let task = |flow: &FlowRecordings, index| flow.entry(index).map(|(_, k)| k.clone());
        let two = task(&flow, 2).expect("task 2's entry");
        assert_eq!(
            (two.last, two.current, two.last_cycle),
            (vec![2], vec![0], 9)
        );
        let zero = task(&flow, 0).expect("task 0's entry");
        assert_eq!(
            (zero.last, zero.current, zero.last_cycle),
            (vec![0], vec![2], 0)
        );

        // An empty list ends one task's recording; the other's goes on.
        flow.configure(0, Vec::new());
        assert_eq!(entry(&flow, 0), Some((2, 5)));
        assert!(!flow.records(6));
        flow.configure(2, Vec::new());
        assert!(flow.is_empty());
    }
}

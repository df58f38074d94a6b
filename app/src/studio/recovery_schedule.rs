//! When the copy of unsaved changes is written, retried and removed: the decisions of
//! [`super::recovery`] without the files, so they can be tested.

use std::time::{Duration, Instant};

/// How long the project must rest after a change before a copy is written; also how long a
/// failed copy waits before it is tried again.
pub(crate) const RECOVERY_DELAY: Duration = Duration::from_secs(2);

/// What to do about the recovery copy this frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RecoveryStep {
    /// Nothing.
    Nothing,
    /// Look again after this long (the project is resting after a change).
    WaitFor(Duration),
    /// Write a copy of the current revision (and report back with [`RecoverySchedule::finished`]).
    Write,
    /// Remove the copy: the project equals its files again.
    Clear,
}

/// The recovery copy's bookkeeping for the open project. It lives while the project is open
/// and is never saved.
#[derive(Debug, Default)]
pub(crate) struct RecoverySchedule {
    /// The revision and time of the last change seen (or of the last failed copy).
    last_change: Option<(u64, Instant)>,
    /// The revision last copied successfully.
    written: Option<u64>,
    /// The revision whose copy is being written.
    writing: Option<u64>,
    /// Whether a copy exists that a save or an undo to the saved state makes stale.
    exists: bool,
}

impl RecoverySchedule {
    /// Decides what to do for `revision` of the project at `now`; `dirty` tells whether the
    /// project differs from its files.
    pub fn next(&mut self, revision: u64, dirty: bool, now: Instant) -> RecoveryStep {
        if self.writing.is_some() {
            // One copy at a time: the next decision waits for the running one's outcome.
            return RecoveryStep::Nothing;
        }
        if !dirty {
            self.written = Some(revision);
            if self.exists {
                self.exists = false;
                return RecoveryStep::Clear;
            }
            return RecoveryStep::Nothing;
        }
        if self.written == Some(revision) {
            return RecoveryStep::Nothing;
        }
        match self.last_change {
            Some((seen, at)) if seen == revision => {
                if now.duration_since(at) >= RECOVERY_DELAY {
                    self.writing = Some(revision);
                    // A copy that fails half-way may leave files behind, so it counts as one.
                    self.exists = true;
                    RecoveryStep::Write
                } else {
                    RecoveryStep::WaitFor(RECOVERY_DELAY)
                }
            }
            _ => {
                self.last_change = Some((revision, now));
                RecoveryStep::WaitFor(RECOVERY_DELAY)
            }
        }
    }

    /// Takes in the outcome of the copy [`RecoveryStep::Write`] asked for. A copy that failed is
    /// not counted as written: it is tried again once [`RECOVERY_DELAY`] passed after `now`.
    pub fn finished<E>(&mut self, outcome: Result<(), E>, now: Instant) -> Result<(), E> {
        let Some(revision) = self.writing.take() else {
            return outcome;
        };
        match &outcome {
            Ok(()) => self.written = Some(revision),
            Err(_) => self.last_change = Some((revision, now)),
        }
        outcome
    }

    /// Whether a copy is being written.
    #[cfg(test)]
    pub fn is_writing(&self) -> bool {
        self.writing.is_some()
    }

    /// Forgets the copy after a save removed it.
    pub fn saved(&mut self) {
        self.exists = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs the schedule for a change at `start` until it asks for a write.
    #[track_caller]
    fn rest_until_write(schedule: &mut RecoverySchedule, revision: u64, start: Instant) {
        assert_eq!(
            schedule.next(revision, true, start),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(revision, true, start + RECOVERY_DELAY),
            RecoveryStep::Write
        );
    }

    #[test]
    fn a_change_is_copied_only_after_the_project_rested() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        assert_eq!(
            schedule.next(1, true, start),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(1, true, start + Duration::from_millis(500)),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(1, true, start + RECOVERY_DELAY),
            RecoveryStep::Write
        );
    }

    #[test]
    fn another_change_while_resting_starts_the_wait_again() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        schedule.next(1, true, start);
        let later = start + Duration::from_millis(1500);
        assert_eq!(
            schedule.next(2, true, later),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(2, true, start + RECOVERY_DELAY),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(2, true, later + RECOVERY_DELAY),
            RecoveryStep::Write
        );
    }

    #[test]
    fn a_written_revision_is_not_copied_again() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        rest_until_write(&mut schedule, 1, start);
        assert!(schedule.finished::<()>(Ok(()), start).is_ok());
        assert_eq!(
            schedule.next(1, true, start + 10 * RECOVERY_DELAY),
            RecoveryStep::Nothing
        );
    }

    #[test]
    fn nothing_else_happens_while_a_copy_is_written() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        rest_until_write(&mut schedule, 1, start);
        assert!(schedule.is_writing());
        assert_eq!(
            schedule.next(2, true, start + 10 * RECOVERY_DELAY),
            RecoveryStep::Nothing
        );
        assert_eq!(
            schedule.next(3, false, start + 10 * RECOVERY_DELAY),
            RecoveryStep::Nothing
        );
    }

    #[test]
    fn a_failed_copy_is_not_marked_written_and_is_retried_after_the_delay() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        rest_until_write(&mut schedule, 1, start);
        let failed_at = start + RECOVERY_DELAY + Duration::from_millis(100);
        assert_eq!(
            schedule.finished(Err("disk full"), failed_at),
            Err("disk full")
        );
        assert!(!schedule.is_writing());
        assert_eq!(
            schedule.next(1, true, failed_at + Duration::from_millis(10)),
            RecoveryStep::WaitFor(RECOVERY_DELAY)
        );
        assert_eq!(
            schedule.next(1, true, failed_at + RECOVERY_DELAY),
            RecoveryStep::Write
        );
    }

    #[test]
    fn a_copy_is_stale_once_the_project_equals_its_files_again() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        rest_until_write(&mut schedule, 1, start);
        assert!(schedule.finished::<()>(Ok(()), start).is_ok());
        // An undo back to the saved state removes the copy, once.
        assert_eq!(schedule.next(2, false, start), RecoveryStep::Clear);
        assert_eq!(schedule.next(2, false, start), RecoveryStep::Nothing);
    }

    #[test]
    fn a_save_leaves_no_copy_to_remove() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        rest_until_write(&mut schedule, 1, start);
        assert!(schedule.finished::<()>(Ok(()), start).is_ok());
        schedule.saved();
        assert_eq!(schedule.next(1, false, start), RecoveryStep::Nothing);
    }

    #[test]
    fn a_clean_project_never_gets_a_copy() {
        let mut schedule = RecoverySchedule::default();
        let start = Instant::now();
        assert_eq!(schedule.next(0, false, start), RecoveryStep::Nothing);
        assert_eq!(
            schedule.next(0, false, start + 10 * RECOVERY_DELAY),
            RecoveryStep::Nothing
        );
    }
}

//! The statuses of the commands the kernel has accepted, kept until the issuing FB has read
//! the final one.

use crate::kernel::{CommandId, CommandStatus};

/// Command statuses by id. An entry is added when a command is accepted (the only time the
/// registry allocates) and removed when the FB that issued it forgets it after reading its
/// final status, so the registry holds about one entry per FB instance.
#[derive(Clone, Debug, Default)]
pub(crate) struct Registry {
    entries: Vec<(CommandId, CommandStatus)>,
    next_id: u64,
}

impl Registry {
    /// Records a new command with its first status and returns its id.
    pub(crate) fn issue(&mut self, status: CommandStatus) -> CommandId {
        self.next_id += 1;
        let id = CommandId(self.next_id);
        self.entries.push((id, status));
        id
    }

    /// Changes the status of a command; a forgotten command is left forgotten.
    pub(crate) fn set(&mut self, id: CommandId, status: CommandStatus) {
        if let Some(entry) = self.entries.iter_mut().find(|entry| entry.0 == id) {
            entry.1 = status;
        }
    }

    /// The status of a command, `None` once it is forgotten or if it never existed.
    pub(crate) fn get(&self, id: CommandId) -> Option<CommandStatus> {
        self.entries
            .iter()
            .find(|entry| entry.0 == id)
            .map(|entry| entry.1)
    }

    /// Drops a command's entry.
    pub(crate) fn forget(&mut self, id: CommandId) {
        if let Some(index) = self.entries.iter().position(|entry| entry.0 == id) {
            self.entries.swap_remove(index);
        }
    }

    /// How many commands are recorded.
    pub(crate) fn len(&self) -> usize {
        self.entries.len()
    }
}

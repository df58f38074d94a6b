//! The decisions of logging in to a target that runs another version of the project
//! (`docs/debugging.md` §6): which of CODESYS's three choices are offered, why an online change
//! is impossible, and what the change will do, grouped for the user to read before applying.

use online::{ChangeCheck, ChangeDetailEntry};

/// What the target said about taking the project's program over online, while the user
/// chooses how to log in.
#[derive(Clone, Debug, PartialEq)]
pub struct ChangeOffer {
    /// The checked transfer, open on the target until applied, committed or aborted.
    pub transfer: u16,
    /// Why the dialog opened, in words (the target runs another program).
    pub reason: String,
    /// The verdict and its counts.
    pub check: ChangeCheck,
    /// What the change will do, in the target's order.
    pub details: Vec<ChangeDetailEntry>,
}

/// How the user logs in to a target that runs another version of the project.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoginChoice {
    /// The new code takes over between two cycles; the variables keep their values.
    OnlineChange,
    /// The project's program replaces the target's; its variables start from their initial
    /// values.
    Download,
    /// Log in to the program the target runs, changing nothing.
    WithoutChange,
}

impl LoginChoice {
    /// The three choices in the order the dialog shows them.
    pub const ALL: [Self; 3] = [Self::OnlineChange, Self::Download, Self::WithoutChange];

    /// Whether the choice may be taken after this check: an online change only when the target
    /// says it is possible, the others always.
    pub fn is_enabled(self, check: &ChangeCheck) -> bool {
        match self {
            Self::OnlineChange => check.possible,
            Self::Download | Self::WithoutChange => true,
        }
    }

    /// The choice the dialog starts with: the online change when possible (it keeps the
    /// machine running), else the download.
    pub fn preferred(check: &ChangeCheck) -> Self {
        if check.possible {
            Self::OnlineChange
        } else {
            Self::Download
        }
    }
}

/// Why an online change is impossible (`docs/protocol.md` §7's reasons).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChangeRefusal {
    /// The target runs no program.
    NoProgram,
    /// The target already runs this program.
    SameProgram,
    /// A task was added, removed or renamed, or its timing, trigger or calls changed.
    TaskConfiguration,
    /// The located areas changed size or the Modbus map changed.
    LocatedAreas,
    /// An axis or a cam table changed.
    Motion,
    /// A task is halted by the debugger.
    TaskHalted,
    /// A reason this studio does not know, from a newer runtime.
    Other(u8),
}

impl ChangeRefusal {
    /// Why the check refused, or `None` when the change is possible.
    pub fn of(check: &ChangeCheck) -> Option<Self> {
        if check.possible {
            return None;
        }
        Some(match check.reason {
            1 => Self::NoProgram,
            2 => Self::SameProgram,
            3 => Self::TaskConfiguration,
            4 => Self::LocatedAreas,
            5 => Self::Motion,
            6 => Self::TaskHalted,
            other => Self::Other(other),
        })
    }
}

/// What one detail of the check says will happen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum ChangeKind {
    /// A POU whose code changed.
    PouChanged,
    /// A POU added.
    PouAdded,
    /// A POU removed.
    PouRemoved,
    /// A variable added; it starts from its initial value.
    VariableAdded,
    /// A variable removed.
    VariableRemoved,
    /// A variable whose type changed; it starts from its initial value.
    VariableReinitialised,
    /// A pointer set to 0 because what it pointed to is gone.
    PointerCleared,
    /// A force released.
    ForceReleased,
    /// The trace removed.
    TraceRemoved,
    /// A motion block instance dropped while its axis may move.
    MotionBlockDropped,
    /// A detail this studio does not know, from a newer runtime.
    Other,
}

impl ChangeKind {
    /// The kind of a detail by its number on the wire.
    pub fn of(kind: u8) -> Self {
        match kind {
            0 => Self::PouChanged,
            1 => Self::PouAdded,
            2 => Self::PouRemoved,
            3 => Self::VariableAdded,
            4 => Self::VariableRemoved,
            5 => Self::VariableReinitialised,
            6 => Self::PointerCleared,
            7 => Self::ForceReleased,
            8 => Self::TraceRemoved,
            9 => Self::MotionBlockDropped,
            _ => Self::Other,
        }
    }

    /// Whether the user loses something with this change (a value, a pointer, a force, a
    /// trace, a motion command), so the dialog marks it.
    pub fn loses_state(self) -> bool {
        !matches!(
            self,
            Self::PouChanged | Self::PouAdded | Self::VariableAdded
        )
    }
}

/// The details of one kind, for one heading of the dialog's list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ChangeGroup {
    /// What happens to the names below.
    pub kind: ChangeKind,
    /// The POUs' names or the variables' paths, in the target's order.
    pub names: Vec<String>,
}

/// The details grouped by kind, in the protocol's order (code first, then variables, pointers,
/// forces, the trace and motion); kinds without a detail are left out.
pub fn grouped(details: &[ChangeDetailEntry]) -> Vec<ChangeGroup> {
    let mut groups: Vec<ChangeGroup> = Vec::new();
    for detail in details {
        let kind = ChangeKind::of(detail.kind);
        match groups.iter_mut().find(|group| group.kind == kind) {
            Some(group) => group.names.push(detail.name.clone()),
            None => groups.push(ChangeGroup {
                kind,
                names: vec![detail.name.clone()],
            }),
        }
    }
    groups.sort_by_key(|group| group.kind);
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    fn detail(kind: u8, name: &str) -> ChangeDetailEntry {
        ChangeDetailEntry {
            kind,
            name: name.to_owned(),
        }
    }

    #[test]
    fn an_online_change_is_offered_and_preferred_only_when_the_target_says_it_is_possible() {
        let possible = ChangeCheck {
            possible: true,
            ..ChangeCheck::default()
        };
        let impossible = ChangeCheck {
            possible: false,
            reason: 3,
            why: "task 'Fast': interval changed from 2 ms to 1 ms".to_owned(),
            ..ChangeCheck::default()
        };
        let enabled = |check: &ChangeCheck| {
            LoginChoice::ALL
                .into_iter()
                .filter(|choice| choice.is_enabled(check))
                .collect::<Vec<_>>()
        };
        assert_eq!(enabled(&possible), LoginChoice::ALL.to_vec());
        assert_eq!(
            enabled(&impossible),
            vec![LoginChoice::Download, LoginChoice::WithoutChange]
        );
        assert_eq!(LoginChoice::preferred(&possible), LoginChoice::OnlineChange);
        assert_eq!(LoginChoice::preferred(&impossible), LoginChoice::Download);
    }

    #[test]
    fn the_refusal_follows_the_protocols_reasons_and_keeps_an_unknown_one() {
        let refusal = |reason| {
            ChangeRefusal::of(&ChangeCheck {
                reason,
                ..ChangeCheck::default()
            })
        };
        assert_eq!(refusal(3), Some(ChangeRefusal::TaskConfiguration));
        assert_eq!(refusal(4), Some(ChangeRefusal::LocatedAreas));
        assert_eq!(refusal(5), Some(ChangeRefusal::Motion));
        assert_eq!(refusal(6), Some(ChangeRefusal::TaskHalted));
        assert_eq!(refusal(42), Some(ChangeRefusal::Other(42)));
        let possible = ChangeCheck {
            possible: true,
            ..ChangeCheck::default()
        };
        assert_eq!(ChangeRefusal::of(&possible), None);
    }

    #[test]
    fn details_are_grouped_by_kind_in_the_protocols_order_keeping_the_targets_order_inside() {
        let details = [
            detail(3, "Main.b"),
            detail(0, "Main"),
            detail(3, "Main.a"),
            detail(7, "GVL.x"),
            detail(0, "FB_Conveyor"),
            detail(12, "something new"),
        ];
        let groups = grouped(&details);
        let kinds: Vec<ChangeKind> = groups.iter().map(|group| group.kind).collect();
        assert_eq!(
            kinds,
            [
                ChangeKind::PouChanged,
                ChangeKind::VariableAdded,
                ChangeKind::ForceReleased,
                ChangeKind::Other
            ]
        );
        assert_eq!(groups[0].names, ["Main", "FB_Conveyor"]);
        assert_eq!(groups[1].names, ["Main.b", "Main.a"]);
        assert!(grouped(&[]).is_empty());
    }

    #[test]
    fn only_changes_that_lose_state_are_marked() {
        assert!(!ChangeKind::VariableAdded.loses_state());
        assert!(!ChangeKind::PouChanged.loses_state());
        assert!(ChangeKind::VariableReinitialised.loses_state());
        assert!(ChangeKind::PointerCleared.loses_state());
        assert!(ChangeKind::ForceReleased.loses_state());
    }
}

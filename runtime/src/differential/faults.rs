//! The faults of two engines compared under the exceptions of `docs/native-engine.md` §6.3.

use super::{Difference, Subject};
use crate::engine::{FaultKind, FaultRecord};

/// How strictly the rest of the run can be compared after a cycle's faults.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum FaultVerdict {
    /// The faults (if any) agree in every field: the memory can still be compared.
    Exact,
    /// A watchdog, an abandoned halt or a stack overflow agreed in what §6.3 compares; the
    /// memory and the axes now depend on speed or build and are no longer compared.
    Lenient,
}

/// Compares the faults of two engines from the `seen`-th on (those of the cycle just run).
pub(super) fn compare(
    cycle: u64,
    seen: usize,
    first: &[FaultRecord],
    second: &[FaultRecord],
) -> Result<FaultVerdict, Difference> {
    let mut verdict = FaultVerdict::Exact;
    let new_first = first.get(seen..).unwrap_or_default();
    let new_second = second.get(seen..).unwrap_or_default();
    for index in 0..new_first.len().max(new_second.len()) {
        let (a, b) = (new_first.get(index), new_second.get(index));
        let differ = |a: Option<&FaultRecord>, b: Option<&FaultRecord>| Difference {
            cycle,
            subject: Subject::Fault {
                index: seen + index,
            },
            first: describe(a),
            second: describe(b),
        };
        let (Some(a), Some(b)) = (a, b) else {
            return Err(differ(a, b));
        };
        match rule(&a.kind) {
            Rule::Exact if a != b => return Err(differ(Some(a), Some(b))),
            Rule::KindAndTask if a.kind != b.kind || a.task != b.task => {
                return Err(differ(Some(a), Some(b)));
            }
            Rule::KindTaskAndPou if a.kind != b.kind || a.task != b.task || a.pou != b.pou => {
                return Err(differ(Some(a), Some(b)));
            }
            Rule::Exact => {}
            Rule::KindAndTask | Rule::KindTaskAndPou => verdict = FaultVerdict::Lenient,
        }
    }
    Ok(verdict)
}

/// Which fields of a fault are compared, by the first engine's fault kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Rule {
    /// Task, kind, POU, file, line, instruction and cycle.
    Exact,
    /// How far a cycle got before the watchdog (or a stop) ended it depends on speed: the
    /// kind and the task.
    KindAndTask,
    /// Where the native stack budget ends recursion depends on the build: the kind, the task
    /// and the POU.
    KindTaskAndPou,
}

fn rule(kind: &FaultKind) -> Rule {
    match kind {
        FaultKind::Watchdog { .. } | FaultKind::Abandoned => Rule::KindAndTask,
        FaultKind::StackOverflow => Rule::KindTaskAndPou,
        _ => Rule::Exact,
    }
}

/// A fault as a difference shows it: where and what, with the instruction and cycle, which
/// the usual text leaves out.
fn describe(fault: Option<&FaultRecord>) -> String {
    match fault {
        None => "no fault".to_owned(),
        Some(fault) => format!(
            "\"{fault}\" at instruction {} in cycle {}",
            fault.instruction, fault.cycle
        ),
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    fn fault(kind: FaultKind) -> FaultRecord {
        FaultRecord {
            task: "Fast".to_owned(),
            kind,
            pou: "Main".to_owned(),
            file: Some("main.st".to_owned()),
            line: Some(12),
            instruction: 7,
            cycle: 3,
        }
    }

    #[track_caller]
    fn verdict(first: &[FaultRecord], second: &[FaultRecord]) -> Result<FaultVerdict, Difference> {
        compare(4, 0, first, second)
    }

    #[test]
    fn no_faults_or_equal_faults_agree_exactly() {
        assert_eq!(verdict(&[], &[]), Ok(FaultVerdict::Exact));
        let division = fault(FaultKind::DivisionByZero);
        assert_eq!(
            verdict(
                std::slice::from_ref(&division),
                std::slice::from_ref(&division)
            ),
            Ok(FaultVerdict::Exact)
        );
    }

    #[test]
    fn an_ordinary_fault_differing_in_any_field_is_a_difference() {
        let division = fault(FaultKind::DivisionByZero);
        let changes: [fn(&mut FaultRecord); 7] = [
            |f| f.task = "Slow".to_owned(),
            |f| f.kind = FaultKind::NullPointer,
            |f| f.pou = "Other".to_owned(),
            |f| f.file = None,
            |f| f.line = Some(13),
            |f| f.instruction = 8,
            |f| f.cycle = 4,
        ];
        for change in changes {
            let mut other = division.clone();
            change(&mut other);
            let difference = verdict(std::slice::from_ref(&division), &[other]).unwrap_err();
            assert_eq!(difference.cycle, 4);
            assert_eq!(difference.subject, Subject::Fault { index: 0 });
        }
    }

    #[test]
    fn a_fault_in_one_engine_only_is_a_difference_naming_no_fault() {
        let division = fault(FaultKind::DivisionByZero);
        let difference = verdict(&[], std::slice::from_ref(&division)).unwrap_err();
        assert_eq!(difference.first, "no fault");
        assert!(
            difference.second.contains("division by zero"),
            "{difference}"
        );
        assert!(difference.second.contains("main.st:12"), "{difference}");
        let difference = verdict(&[division], &[]).unwrap_err();
        assert_eq!(difference.second, "no fault");
    }

    #[test]
    fn a_watchdog_or_an_abandoned_cycle_compares_only_kind_and_task() {
        for kind in [
            FaultKind::Watchdog { limit_us: 10_000 },
            FaultKind::Abandoned,
        ] {
            let first = fault(kind.clone());
            let mut elsewhere = first.clone();
            elsewhere.pou = "Helper".to_owned();
            elsewhere.file = None;
            elsewhere.line = None;
            elsewhere.instruction = 99;
            elsewhere.cycle = 5;
            assert_eq!(
                verdict(
                    std::slice::from_ref(&first),
                    std::slice::from_ref(&elsewhere)
                ),
                Ok(FaultVerdict::Lenient),
                "{kind}"
            );
            let mut other_task = elsewhere.clone();
            other_task.task = "Slow".to_owned();
            assert!(
                verdict(std::slice::from_ref(&first), &[other_task]).is_err(),
                "{kind}"
            );
            let mut other_kind = elsewhere;
            other_kind.kind = FaultKind::StackOverflow;
            assert!(verdict(&[first], &[other_kind]).is_err(), "{kind}");
        }
        let watchdog = fault(FaultKind::Watchdog { limit_us: 10_000 });
        let mut longer = watchdog.clone();
        longer.kind = FaultKind::Watchdog { limit_us: 20_000 };
        assert!(verdict(&[watchdog], &[longer]).is_err());
    }

    #[test]
    fn a_stack_overflow_compares_kind_task_and_pou_but_not_the_place_in_it() {
        let first = fault(FaultKind::StackOverflow);
        let mut deeper = first.clone();
        deeper.line = Some(40);
        deeper.instruction = 31;
        deeper.cycle = 4;
        assert_eq!(
            verdict(std::slice::from_ref(&first), std::slice::from_ref(&deeper)),
            Ok(FaultVerdict::Lenient)
        );
        let mut other_pou = deeper.clone();
        other_pou.pou = "Recurse".to_owned();
        let difference = verdict(std::slice::from_ref(&first), &[other_pou]).unwrap_err();
        assert!(difference.second.contains("Recurse"), "{difference}");
        let mut other_task = deeper;
        other_task.task = "Slow".to_owned();
        assert!(verdict(&[first], &[other_task]).is_err());
    }

    #[test]
    fn only_the_faults_after_those_seen_are_compared_and_indexed_from_the_run_start() {
        let division = fault(FaultKind::DivisionByZero);
        let null = fault(FaultKind::NullPointer);
        let earlier = [division.clone(), null.clone()];
        assert_eq!(
            compare(5, 1, &earlier, &[division.clone(), null.clone()]),
            Ok(FaultVerdict::Exact)
        );
        let difference = compare(5, 1, &earlier, std::slice::from_ref(&division)).unwrap_err();
        assert_eq!(difference.subject, Subject::Fault { index: 1 });
        assert_eq!(difference.second, "no fault");
    }
}

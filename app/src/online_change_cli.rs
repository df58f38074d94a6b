//! `rivet download --online-change` (`docs/debugging.md` §6 and §7): transfers the build,
//! asks the target whether it can take it over without stopping, prints what will change,
//! and applies it between two cycles, or says why it cannot and what a download would do.

#![allow(clippy::print_stdout)] // Printing is what a CLI is for.

use std::path::Path;

use online::{ChangeCheck, ChangeDetailEntry, Client};

/// The `reason` of a check that found the target already running the image.
const SAME_IMAGE: u8 = 2;

/// What a full download does instead, for the refusal's hint.
const DOWNLOAD_HINT: &str = "download without --online-change to replace the program, whose \
                             variables then start from their initial values (RETAIN and \
                             PERSISTENT kept)";

/// Compiles `project`, transfers it and changes the running program to it online; with
/// `dry_run`, checks and lists only. An impossible change is an error naming the reason, and
/// changes nothing.
pub async fn online_change(
    client: &mut Client,
    project: &Path,
    dry_run: bool,
) -> anyhow::Result<()> {
    let image = crate::build_cli::compile_path(project)?;
    let bytes = image.encode();
    let transfer = client.transfer(&bytes, |_, _| {}).await?;
    let check = client.online_change_check(transfer).await?;
    if !check.possible {
        // Nothing on the target may change: the transfer is dropped.
        client.abort(transfer).await?;
        if check.reason == SAME_IMAGE {
            println!("the target already runs this program; nothing to change");
            return Ok(());
        }
        anyhow::bail!(
            "an online change is impossible: {}; {DOWNLOAD_HINT}",
            check.why
        );
    }
    println!("online change possible: {}", summary(&check));
    for detail in client.online_change_details(transfer).await? {
        println!("  {}", detail_line(&detail));
    }
    if dry_run {
        client.abort(transfer).await?;
        println!("dry run: nothing changed");
        return Ok(());
    }
    let applied = client.online_change_apply(transfer).await?;
    println!(
        "applied between two cycles after cycle {} (switch {} µs); {} variable(s) kept their values{}",
        applied.cycles,
        applied.switch_us,
        applied.carried,
        if applied.retained {
            ", RETAIN/PERSISTENT values among them"
        } else {
            ""
        }
    );
    Ok(())
}

/// The check's counts in one line.
fn summary(check: &ChangeCheck) -> String {
    let mut text = format!(
        "{} POU(s) changed, {} variable(s) added, {} removed, {} reinitialised",
        check.pous_changed, check.added, check.removed, check.reinitialised
    );
    for (count, what) in [
        (u32::from(check.pous_added), "POU(s) added"),
        (u32::from(check.pous_removed), "POU(s) removed"),
        (check.pointers_moved, "pointer(s) moved"),
        (check.pointers_cleared, "pointer(s) cleared"),
        (u32::from(check.forces_released), "force(s) released"),
    ] {
        if count > 0 {
            text.push_str(&format!(", {count} {what}"));
        }
    }
    text
}

/// One detail as the user reads it.
fn detail_line(detail: &ChangeDetailEntry) -> String {
    let what = match detail.kind {
        0 => "POU changed",
        1 => "POU added",
        2 => "POU removed",
        3 => "variable added (starts from its initial value)",
        4 => "variable removed",
        5 => "variable reinitialised (its type changed)",
        6 => "pointer cleared (its target is gone)",
        7 => "force released",
        8 => "trace removed",
        9 => "motion block dropped (its axis goes on)",
        _ => "change",
    };
    format!("{what}: {}", detail.name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_summary_names_the_counts_and_only_the_other_counts_that_are_not_zero() {
        let check = ChangeCheck {
            possible: true,
            pous_changed: 2,
            added: 1,
            pointers_cleared: 3,
            ..ChangeCheck::default()
        };
        assert_eq!(
            summary(&check),
            "2 POU(s) changed, 1 variable(s) added, 0 removed, 0 reinitialised, 3 pointer(s) cleared"
        );
        let detail = ChangeDetailEntry {
            kind: 3,
            name: "Main.x".to_owned(),
        };
        assert_eq!(
            detail_line(&detail),
            "variable added (starts from its initial value): Main.x"
        );
    }
}

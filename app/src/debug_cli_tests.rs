//! The debugging commands' arguments as `docs/debugging.md` §7 writes them, and the pure
//! parts of the commands.

#![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

use clap::Parser as _;
use online::HitRule;

use super::*;
use crate::cli::{Cli, Command};

#[track_caller]
fn parse(args: &[&str]) -> Command {
    let mut all = vec!["rivet"];
    all.extend_from_slice(args);
    match Cli::try_parse_from(all) {
        Ok(cli) => cli.command.unwrap(),
        Err(error) => panic!("{args:?}: {error}"),
    }
}

#[track_caller]
fn refused(args: &[&str]) -> String {
    let mut all = vec!["rivet"];
    all.extend_from_slice(args);
    match Cli::try_parse_from(all) {
        Ok(cli) => panic!("{args:?} was accepted: {:?}", cli.command),
        Err(error) => error.to_string(),
    }
}

#[test]
fn a_breakpoint_takes_its_place_filters_condition_and_hit_rule() {
    let Command::Break(args) = parse(&[
        "break",
        "FB_Counter.st:12",
        "--instance",
        "Main.fbA",
        "--task",
        "MainTask",
        "--if",
        "iCount > 100",
        "--hits-multiple",
        "3",
        "--wait",
        "5",
        "--project",
        "machine",
    ]) else {
        panic!("not break");
    };
    assert_eq!(args.place.as_deref(), Some("FB_Counter.st:12"));
    assert_eq!(args.instance.as_deref(), Some("Main.fbA"));
    assert_eq!(args.condition.as_deref(), Some("iCount > 100"));
    assert_eq!(
        hit_rule(&args),
        HitRule {
            mode: HitMode::Multiple,
            target: 3
        }
    );
    assert_eq!(args.wait, Some(5));
    assert_eq!(args.debug.project, PathBuf::from("machine"));
    assert_eq!(args.debug.linger, 60);
    assert_eq!(args.debug.target.target, "127.0.0.1:5020");
}

#[test]
fn hit_rules_exclude_each_other_and_count_from_one() {
    let Command::Break(args) = parse(&["break", "a.st:1", "--hits", "2"]) else {
        panic!("not break");
    };
    assert_eq!(hit_rule(&args).mode, HitMode::Equal);
    let Command::Break(args) = parse(&["break", "a.st:1", "--hits-from", "4"]) else {
        panic!("not break");
    };
    assert_eq!(hit_rule(&args).mode, HitMode::AtLeast);
    let Command::Break(args) = parse(&["break", "a.st:1"]) else {
        panic!("not break");
    };
    assert_eq!(hit_rule(&args), HitRule::ALWAYS);
    refused(&["break", "a.st:1", "--hits", "2", "--hits-from", "3"]);
    refused(&["break", "a.st:1", "--hits", "0"]);
}

#[test]
fn listing_and_clearing_take_no_place_and_a_place_is_needed_otherwise() {
    let Command::Break(args) = parse(&["break", "--list"]) else {
        panic!("not break");
    };
    assert!(args.list && args.place.is_none());
    let Command::Break(args) = parse(&["break", "--clear", "1", "3"]) else {
        panic!("not break");
    };
    assert_eq!(args.clear, [1, 3]);
    let Command::Break(args) = parse(&["break", "--clear-all"]) else {
        panic!("not break");
    };
    assert!(args.clear_all);
    refused(&["break"]);
    refused(&["break", "a.st:1", "--list"]);
    refused(&["break", "--linger", "301", "--list"]);
}

#[test]
fn step_continue_halt_stack_and_flow_take_what_the_spec_gives_them() {
    let Command::Step(args) = parse(&["step", "over", "--task", "Fast"]) else {
        panic!("not step");
    };
    assert_eq!(
        (args.kind.as_str(), args.task.as_deref(), args.wait),
        ("over", Some("Fast"), 10)
    );
    refused(&["step", "sideways"]);
    let Command::Continue(args) = parse(&["continue", "--to", "FB_Counter.st:20", "--wait", "3"])
    else {
        panic!("not continue");
    };
    assert_eq!(args.to.as_deref(), Some("FB_Counter.st:20"));
    let Command::Continue(args) = parse(&["continue", "--end"]) else {
        panic!("not continue");
    };
    assert!(args.end);
    refused(&["continue", "--all", "--task", "Fast"]);
    refused(&["continue", "--end", "--all"]);
    let Command::Halt(args) = parse(&["halt", "--all"]) else {
        panic!("not halt");
    };
    assert!(args.all);
    let Command::Stack(args) = parse(&["stack", "--values", "--frame", "1"]) else {
        panic!("not stack");
    };
    assert!(args.values && args.frame == Some(1));
    let Command::Flow(args) = parse(&["flow", "FB_Counter", "--instance", "Main.fbA"]) else {
        panic!("not flow");
    };
    assert_eq!(args.pou, "FB_Counter");
}

const SOURCE: &str = "FUNCTION_BLOCK FB_Counter
VAR_INPUT step : INT; END_VAR
VAR count : INT; END_VAR
count := count + step;
END_FUNCTION_BLOCK

PROGRAM Main
VAR fbA : FB_Counter; fbB : FB_Counter; END_VAR
fbA(step := 1);
fbB(step := 2);
END_PROGRAM
";

fn image() -> ProgramImage {
    let source = compiler::SourceProject::new(SOURCE);
    compiler::compile_source(&source, "counter.st").unwrap()
}

#[test]
fn a_target_running_another_build_is_refused_naming_both_identities() {
    let image = image();
    let identity = |hash| Identity {
        protocol: 3,
        runtime_version: String::new(),
        state: online::TargetState::Running,
        image_hash: hash,
        project: String::new(),
        password_required: false,
        debug: online::DebugStatus::default(),
    };
    let project = Path::new("counter.st");
    assert!(same_build(&image, &identity(Some(image.identity())), project).is_ok());
    let other = same_build(&image, &identity(Some([7; 32])), project)
        .unwrap_err()
        .to_string();
    assert!(
        other.contains("0707070707070707")
            && other.contains(&crate::value_text::hex(&image.identity()[..8]))
            && other.contains("rivet download counter.st"),
        "{other}"
    );
    let none = same_build(&image, &identity(None), project)
        .unwrap_err()
        .to_string();
    assert!(none.contains("no program"), "{none}");
}

#[test]
fn an_instance_shows_its_members_at_their_places() {
    let image = image();
    let fb = image
        .pous
        .iter()
        .position(|p| p.name == "FB_Counter")
        .unwrap() as u32;
    let at = runtime::value::resolve(&image, "Main.fbB").unwrap().offset as u32;
    let members = instance_members(&image, fb, DATA_POINTER | u64::from(at)).unwrap();
    let names: Vec<&str> = members.iter().map(|(name, _, _)| name.as_str()).collect();
    assert!(
        names.contains(&"step") && names.contains(&"count"),
        "{names:?}"
    );
    let count = runtime::value::resolve(&image, "Main.fbB.count").unwrap();
    let (_, _, place) = members.iter().find(|(name, _, _)| name == "count").unwrap();
    assert_eq!((place.region, u64::from(place.offset)), (0, count.offset));
    // A pointer into a task's stack (region 2) is no instance in data.
    assert!(instance_members(&image, fb, (2 << 56) | u64::from(at)).is_none());
    assert_eq!(task_index(&image, "maintask").unwrap(), 0);
    assert!(
        task_index(&image, "Fast")
            .unwrap_err()
            .to_string()
            .contains("'MainTask'")
    );
}

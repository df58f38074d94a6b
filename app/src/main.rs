//! `rivet`: the studio, or with a subcommand the headless command line.

use std::process::ExitCode;

use clap::Parser as _;

fn main() -> ExitCode {
    let cli = app::cli::Cli::parse();
    match cli.command {
        Some(command) => app::cli::run(command),
        None => match app::studio::run(cli.project) {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                app::cli::report_error(&error);
                ExitCode::FAILURE
            }
        },
    }
}

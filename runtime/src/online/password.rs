//! Where a password comes from: a file or an environment variable, never the command line,
//! where every user of the machine sees it in the process list.

use std::ffi::OsString;
use std::io;
use std::path::{Path, PathBuf};

/// The environment variable a password may be given in, to `rivet-runtime` and to the `rivet`
/// online commands alike.
pub const PASSWORD_VARIABLE: &str = "RIVET_PASSWORD";

/// Why no password could be taken.
#[derive(Debug, thiserror::Error)]
pub enum PasswordError {
    /// The password was given on the command line, as older versions took it.
    #[error(
        "--password is no longer accepted: a password on the command line is visible to every \
         user in the process list; put it in a file named with --password-file, or in the \
         environment variable {PASSWORD_VARIABLE}"
    )]
    OnCommandLine,
    /// The password file could not be read.
    #[error("cannot read the password file {path}: {source}")]
    Unreadable {
        /// The file named with `--password-file`.
        path: PathBuf,
        /// What reading it gave.
        source: io::Error,
    },
    /// The password file's first line is empty.
    #[error("the password file {0} has an empty first line; its first line is the password")]
    EmptyFile(PathBuf),
    /// The environment variable is set but empty or not UTF-8.
    #[error("the environment variable {PASSWORD_VARIABLE} is set but empty or not UTF-8")]
    BadVariable,
    /// Both a file and the environment variable give a password.
    #[error("both --password-file and {PASSWORD_VARIABLE} give a password; keep one of them")]
    Both,
}

/// The password given by `file` (its first line, without the line end) or by `variable` (the
/// value of [`PASSWORD_VARIABLE`], if set), or `None` when neither gives one.
///
/// `command_line` is the value of the old `--password` option, which is refused with an error
/// that says where to put the password instead.
pub fn read_password(
    command_line: Option<&str>,
    file: Option<&Path>,
    variable: Option<OsString>,
) -> Result<Option<String>, PasswordError> {
    if command_line.is_some() {
        return Err(PasswordError::OnCommandLine);
    }
    let from_variable = match variable {
        None => None,
        Some(value) => match value.into_string() {
            Ok(value) if !value.is_empty() => Some(value),
            _ => return Err(PasswordError::BadVariable),
        },
    };
    let Some(path) = file else {
        return Ok(from_variable);
    };
    if from_variable.is_some() {
        return Err(PasswordError::Both);
    }
    let text = std::fs::read_to_string(path).map_err(|source| PasswordError::Unreadable {
        path: path.to_owned(),
        source,
    })?;
    let first_line = text.lines().next().unwrap_or_default();
    if first_line.is_empty() {
        return Err(PasswordError::EmptyFile(path.to_owned()));
    }
    Ok(Some(first_line.to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_password_comes_from_the_first_line_of_a_file_or_from_the_variable() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("password");
        std::fs::write(&file, "open sesame\r\nsecond line\n").unwrap();
        assert_eq!(
            read_password(None, Some(&file), None).unwrap().as_deref(),
            Some("open sesame")
        );
        let variable = Some(OsString::from("swordfish"));
        assert_eq!(
            read_password(None, None, variable).unwrap().as_deref(),
            Some("swordfish")
        );
        assert_eq!(read_password(None, None, None).unwrap(), None);
    }

    #[test]
    fn the_command_line_an_empty_or_missing_source_and_two_sources_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let empty = dir.path().join("empty");
        std::fs::write(&empty, "\nsecret\n").unwrap();
        let missing = dir.path().join("missing");
        let old = read_password(Some("secret"), None, None).unwrap_err();
        assert!(matches!(old, PasswordError::OnCommandLine));
        assert!(old.to_string().contains("--password-file"), "{old}");
        assert!(old.to_string().contains(PASSWORD_VARIABLE), "{old}");
        let error = read_password(None, Some(&empty), None).unwrap_err();
        assert!(error.to_string().contains("empty"), "{error}");
        let error = read_password(None, Some(&missing), None).unwrap_err();
        assert!(error.to_string().contains("missing"), "{error}");
        let error = read_password(None, None, Some(OsString::new())).unwrap_err();
        assert!(matches!(error, PasswordError::BadVariable));
        let both = read_password(None, Some(&empty), Some(OsString::from("x"))).unwrap_err();
        assert!(matches!(both, PasswordError::Both));
    }
}

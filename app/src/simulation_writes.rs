//! `rivet simulate --set CYCLE:PATH=VALUE`: values written into the simulated program before a
//! given cycle, as an operator (or another program) would set an input, so that a command line
//! test can drive a program whose inputs nothing else writes.

use anyhow::Context as _;
use program_image::{ProgramImage, TypeDef};
use runtime::engine::Engine;
use runtime::value::Place;

use crate::literal_value;

/// One value to write before a cycle, checked against the image before anything runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SimulationWrite {
    /// The cycle (from 1, counted in periods of the fastest task) before which it is written.
    pub cycle: u64,
    /// The variable's path, as typed.
    pub path: String,
    /// Where the variable is.
    place: Place,
    /// The value's bytes in the variable's type.
    bytes: Vec<u8>,
}

impl SimulationWrite {
    /// Reads `CYCLE:PATH=VALUE` (`5:plc_prg.Reset=TRUE`) and checks the path and the value
    /// against `image`; `cycles` is how many cycles will run, so a write that would never happen
    /// is refused rather than left out.
    pub fn parse(argument: &str, image: &ProgramImage, cycles: u64) -> anyhow::Result<Self> {
        let shape =
            || format!("--set {argument}: write CYCLE:PATH=VALUE, such as 5:Main.start=TRUE");
        let (cycle, assignment) = argument.split_once(':').with_context(shape)?;
        let (path, text) = assignment.split_once('=').with_context(shape)?;
        let (path, text) = (path.trim(), text.trim());
        let cycle: u64 = cycle.trim().parse().ok().with_context(shape)?;
        if cycle == 0 || cycle > cycles {
            anyhow::bail!(
                "--set {argument}: cycle {cycle} does not run; cycles run from 1 to {cycles}"
            );
        }
        let place = runtime::value::resolve(image, path)
            .map_err(|error| anyhow::anyhow!("--set {path}: {error}"))?;
        let bytes = value_bytes(image, place, text)
            .map_err(|error| anyhow::anyhow!("--set {path}: {error}"))?;
        Ok(Self {
            cycle,
            path: path.to_owned(),
            place,
            bytes,
        })
    }

    /// Writes the value into the engine's memory, between two cycles.
    pub fn apply(&self, engine: &mut Engine) {
        let memory = engine.region_mut(self.place.region);
        let Ok(start) = usize::try_from(self.place.offset) else {
            return;
        };
        match self.place.bit {
            // A located BOOL is one bit of its byte.
            Some(bit) => {
                if let Some(byte) = memory.get_mut(start) {
                    let mask = 1u8 << (bit & 7);
                    if self.bytes.first().is_some_and(|value| *value != 0) {
                        *byte |= mask;
                    } else {
                        *byte &= !mask;
                    }
                }
            }
            None => {
                let end = start.saturating_add(self.bytes.len());
                if let Some(target) = memory.get_mut(start..end) {
                    target.copy_from_slice(&self.bytes);
                }
            }
        }
    }
}

/// The bytes of `text` as a value of the variable at `place`: elementary values and strings as
/// IEC literals, enumeration values by name (`GREEN`, `Light#GREEN`) or number.
fn value_bytes(image: &ProgramImage, place: Place, text: &str) -> anyhow::Result<Vec<u8>> {
    let written = match image.types.get(place.ty as usize) {
        Some(TypeDef::Elementary(elementary)) => literal_value::parse(text, elementary.tag(), 0),
        Some(TypeDef::String { length }) => literal_value::parse(
            text,
            online::TYPE_STRING,
            u16::try_from(*length).unwrap_or(u16::MAX),
        ),
        Some(TypeDef::WString { length }) => literal_value::parse(
            text,
            online::TYPE_WSTRING,
            u16::try_from(*length).unwrap_or(u16::MAX),
        ),
        Some(TypeDef::Enum { name, values, base }) => {
            // A typed value must name this enumeration: `Other#GREEN` is not a `Light`, even
            // when both have a GREEN.
            let value_name = match text.rsplit_once('#') {
                Some((type_name, value)) if type_name.trim().eq_ignore_ascii_case(name) => value,
                Some((type_name, _)) => anyhow::bail!(
                    "'{text}' is a value of {}, but the variable is a {name}",
                    type_name.trim()
                ),
                None => text,
            };
            let number = values
                .iter()
                .find(|(value, _)| value.eq_ignore_ascii_case(value_name))
                .map(|(_, number)| number.to_string());
            match number {
                Some(number) => literal_value::parse(&number, base.tag(), 0),
                // A number is taken as the value's number, as an operator may write it.
                None if text.parse::<i64>().is_ok() => literal_value::parse(text, base.tag(), 0),
                None => {
                    let names: Vec<&str> = values.iter().map(|(value, _)| value.as_str()).collect();
                    anyhow::bail!(
                        "'{text}' is not a value of {name}; its values are {}",
                        names.join(", ")
                    );
                }
            }
        }
        _ => anyhow::bail!("only elementary values, strings and enumerations can be set"),
    };
    Ok(written?)
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)] // A panic is a failed test.

    use super::*;

    fn image() -> ProgramImage {
        let source = compiler::SourceProject::new(
            "TYPE Light : (RED, GREEN := 5); END_TYPE
PROGRAM Main
VAR start : BOOL; speed : INT; name : STRING(4); light : Light; at_q AT %QX0.3 : BOOL; END_VAR
END_PROGRAM
",
        );
        compiler::compile_source(&source, "main.st").unwrap()
    }

    fn written(argument: &str) -> runtime::value::Value {
        let image = image();
        let write = SimulationWrite::parse(argument, &image, 3).unwrap();
        let mut engine = Engine::new(image).unwrap();
        write.apply(&mut engine);
        runtime::value::read(&engine, &write.path).unwrap()
    }

    #[test]
    fn values_of_each_kind_are_written_where_the_path_resolves() {
        assert_eq!(written("1:Main.start=TRUE").to_string(), "TRUE");
        assert_eq!(written("2:Main.speed=-1500").to_string(), "-1500");
        assert_eq!(written("3:Main.name='abc'").to_string(), "'abc'");
        assert_eq!(written("1:Main.light=Light#GREEN").to_string(), "GREEN");
        assert_eq!(written("1:Main.light=light#green").to_string(), "GREEN");
        assert_eq!(written("1:Main.at_q=TRUE").to_string(), "TRUE");
    }

    #[test]
    fn malformed_arguments_wrong_values_and_cycles_that_never_run_are_refused() {
        let image = image();
        let refused = |argument: &str| {
            SimulationWrite::parse(argument, &image, 3)
                .unwrap_err()
                .to_string()
        };
        assert!(refused("Main.start=TRUE").contains("write CYCLE:PATH=VALUE"));
        assert!(refused("x:Main.start=TRUE").contains("write CYCLE:PATH=VALUE"));
        assert!(refused("1:Main.start").contains("write CYCLE:PATH=VALUE"));
        assert_eq!(
            refused("4:Main.start=TRUE"),
            "--set 4:Main.start=TRUE: cycle 4 does not run; cycles run from 1 to 3"
        );
        assert!(refused("0:Main.start=TRUE").contains("cycle 0 does not run"));
        assert!(refused("1:Main.nothing=1").starts_with("--set Main.nothing: "));
        assert_eq!(
            refused("1:Main.speed=40000"),
            "--set Main.speed: 40000 is outside the range of INT"
        );
        assert_eq!(
            refused("1:Main.light=Other#GREEN"),
            "--set Main.light: 'Other#GREEN' is a value of Other, but the variable is a Light"
        );
        assert_eq!(
            refused("1:Main.light=BLUE"),
            "--set Main.light: 'BLUE' is not a value of Light; its values are RED, GREEN"
        );
    }
}

//! Writing and forcing typed values, on the target and on Modbus devices, and the forces list.

use online::Place;
use online::session::Command;
use thiserror::Error;

use super::devices::Bound;
use super::{ForceSource, ForcedValue, Online, Refusal, devices};
use crate::studio::error_texts::value_error_text;
use crate::studio::i18n::Text;
use crate::value_text::{describe_place, show};

/// Why a typed value was refused before it was sent: the reason as the watch shows it, in the
/// interface language (its type's refusal, a channel the studio does not read, or a path the
/// target does not know).
#[derive(Debug, Error)]
#[error("{reason}")]
pub struct ValueRefused {
    /// The reason, already in the interface language.
    pub reason: String,
}

/// Typed values turned into bytes, by where they go.
#[derive(Default)]
struct Encoded {
    /// Values for the controller, by place.
    target: Vec<(Place, Vec<u8>)>,
    /// Values for the channels of the Modbus devices the studio polls, by bound path.
    devices: Vec<(String, Vec<u8>)>,
    /// Paths for the controller while logged out.
    logged_out: Vec<String>,
}

impl Online {
    /// Turns typed values into bytes of their variables' types: for the controller by the
    /// places it resolved, for the Modbus devices the studio polls by their channels (a
    /// runtime device's variable while logged in is the program's, written on the controller).
    /// Values for the controller are left out while logged out (`send` refuses them). Each
    /// failure names the path and the reason; nothing is sent when any value is refused.
    fn encode(&self, values: &[(String, String)]) -> Result<Encoded, Vec<Refusal>> {
        let mut encoded = Encoded::default();
        let mut refused = Vec::new();
        for (path, text) in values {
            if let Some(Bound::SeveralValues(_, count)) = self.bound(path) {
                refused.push((path.clone(), self.several_values(path, count)));
                continue;
            }
            if let Some(Bound::Polled(device, index)) = self.bound(path) {
                let channels = crate::modbus_devices::channels_of(device);
                let Some(channel) = channels.get(index) else {
                    continue;
                };
                match crate::literal_value::parse(text.trim(), channel.ty as u8, 0) {
                    Ok(bytes) => encoded.devices.push((path.clone(), bytes)),
                    Err(error) => {
                        refused.push((path.clone(), value_error_text(&error, self.language)));
                    }
                }
                continue;
            }
            if !self.is_online() {
                encoded.logged_out.push(path.clone());
                continue;
            }
            match self.resolved.get(path) {
                Some(Ok(resolved)) => {
                    match crate::literal_value::parse(
                        text.trim(),
                        resolved.type_tag,
                        resolved.length,
                    ) {
                        Ok(bytes) => encoded.target.push((resolved.place, bytes)),
                        Err(error) => {
                            refused.push((path.clone(), value_error_text(&error, self.language)));
                        }
                    }
                }
                Some(Err(reason)) => refused.push((path.clone(), reason.to_string())),
                None => refused.push((path.clone(), self.text(Text::NotKnownOnTarget).to_owned())),
            }
        }
        if refused.is_empty() {
            Ok(encoded)
        } else {
            Err(refused)
        }
    }

    /// Checks a typed value against its variable's type without sending it.
    pub fn check_value(&self, path: &str, text: &str) -> Result<(), ValueRefused> {
        match self.encode(&[(path.to_owned(), text.to_owned())]) {
            Ok(_) => Ok(()),
            Err(mut refused) => Err(ValueRefused {
                reason: refused.pop().map(|(_, reason)| reason).unwrap_or_default(),
            }),
        }
    }

    /// Writes values once (Ctrl+F7). Refused values are returned with the reason.
    pub fn write(&mut self, values: &[(String, String)]) -> Result<(), Vec<Refusal>> {
        self.send(values, false)
    }

    /// Forces values (F7). Refused values are returned with the reason.
    pub fn force(&mut self, values: &[(String, String)]) -> Result<(), Vec<Refusal>> {
        self.send(values, true)
    }

    /// Writes or forces `values`: those bound to Modbus devices on their devices, the others
    /// on the controller. A value its type refuses stops everything (nothing is sent); values
    /// for the controller while logged out are refused on their own, and the devices' values
    /// still go out.
    fn send(&mut self, values: &[(String, String)], force: bool) -> Result<(), Vec<Refusal>> {
        let encoded = self.encode(values)?;
        let mut refused: Vec<Refusal> = encoded
            .logged_out
            .into_iter()
            .map(|path| (path, self.text(Text::LogInToWrite).to_owned()))
            .collect();
        let logged_in = self.is_logged_in();
        for (path, bytes) in encoded.devices {
            let Some(Bound::Polled(device, index)) =
                devices::bound(&self.project_devices, &path, logged_in)
            else {
                continue;
            };
            if let Err(reason) = self
                .devices
                .send(device, index, bytes, force, self.language)
            {
                refused.push((path, reason.to_string()));
            }
        }
        if !encoded.target.is_empty() {
            self.command(if force {
                Command::Force(encoded.target)
            } else {
                Command::Write(encoded.target)
            });
            if force {
                self.command(Command::Forces);
            }
        }
        if refused.is_empty() {
            Ok(())
        } else {
            Err(refused)
        }
    }

    /// Releases every force, on the controller and on the devices (Alt+F7).
    pub fn unforce_all(&mut self) {
        self.devices.unforce(None);
        if self.link.is_some() {
            self.command(Command::Unforce(Vec::new()));
            self.command(Command::Forces);
        }
    }

    /// Releases one force.
    pub fn unforce(&mut self, source: &ForceSource) {
        match source {
            ForceSource::Target(place) => {
                self.command(Command::Unforce(vec![*place]));
                self.command(Command::Forces);
            }
            ForceSource::Device { device, channel } => {
                self.devices.unforce(Some((device, *channel)));
            }
        }
    }

    /// The place of a resolved path.
    pub fn place(&self, path: &str) -> Option<Place> {
        match self.resolved.get(path) {
            Some(Ok(resolved)) => Some(resolved.place),
            _ => None,
        }
    }

    /// Every forced variable, named by its path when a resolved path has its place.
    pub fn forced_values(&self) -> Vec<ForcedValue> {
        let on_devices = self.devices.forces().into_iter().map(|force| ForcedValue {
            name: force.path,
            source: ForceSource::Device {
                device: force.device,
                channel: force.channel,
            },
            value: force.value,
        });
        self.forces
            .iter()
            .map(|(place, bytes)| {
                let named = self
                    .resolved
                    .iter()
                    .find_map(|(path, resolved)| match resolved {
                        Ok(resolved) if resolved.place == *place => Some((path, resolved)),
                        _ => None,
                    });
                match named {
                    Some((path, resolved)) => ForcedValue {
                        name: path.clone(),
                        source: ForceSource::Target(*place),
                        value: show(resolved, bytes),
                    },
                    None => ForcedValue {
                        name: describe_place(place),
                        source: ForceSource::Target(*place),
                        value: format!("16#{}", crate::value_text::hex(bytes)),
                    },
                }
            })
            .chain(on_devices)
            .collect()
    }
}

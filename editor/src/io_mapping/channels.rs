//! The channels of the controller's I/O areas with the located variables bound to each, worked
//! out from the project before anything is drawn.

use compiler::ide::{AddressArea, AddressInfo, LocatedVariable};
use project_model::{IoArea, IoDirection, Project};

/// One channel of an I/O area: a word, or one bit of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Channel {
    /// The channel's address, such as `%IW0` or `%IX0.3`.
    pub(crate) address: String,
    /// `WORD` or `BOOL`.
    pub(crate) kind: &'static str,
    /// The variables bound to it: a one-bit variable on its bit, a wider one on every word it
    /// touches.
    pub(crate) bound: Vec<LocatedVariable>,
}

/// The channels of one area, words each followed by their bits.
pub(crate) fn area_channels(
    area: &IoArea,
    located: &[(LocatedVariable, AddressInfo)],
) -> Vec<Channel> {
    let letter = area.direction.area_letter();
    let wanted = area_of(area.direction);
    let first_byte = u64::from(area.start_byte);
    let end_byte = first_byte + u64::from(area.size_bytes);
    let in_area: Vec<(&LocatedVariable, std::ops::Range<u64>, bool)> = located
        .iter()
        .filter(|(_, info)| info.area == wanted)
        .filter_map(|(variable, info)| {
            let bits = info.bits.clone()?;
            Some((variable, bits, info.size_bits == Some(1)))
        })
        .collect();
    let bound_to = |bits: std::ops::Range<u64>, one_bit: bool| -> Vec<LocatedVariable> {
        in_area
            .iter()
            .filter(|(_, covered, is_bit)| {
                *is_bit == one_bit && covered.start < bits.end && bits.start < covered.end
            })
            .map(|(variable, _, _)| (*variable).clone())
            .collect()
    };
    let mut channels = Vec::new();
    for word in first_byte / 2..end_byte.div_ceil(2) {
        channels.push(Channel {
            address: format!("%{letter}W{word}"),
            kind: "WORD",
            bound: bound_to(word * 16..word * 16 + 16, false),
        });
        for byte in (word * 2..word * 2 + 2).filter(|byte| (first_byte..end_byte).contains(byte)) {
            for bit in 0..8 {
                let first = byte * 8 + bit;
                channels.push(Channel {
                    address: format!("%{letter}X{byte}.{bit}"),
                    kind: "BOOL",
                    bound: bound_to(first..first + 1, true),
                });
            }
        }
    }
    channels
}

/// Located variables whose address lies in no I/O area of its memory area: they read or write
/// memory nothing is wired to.
pub(crate) fn outside_areas(
    project: &Project,
    located: &[(LocatedVariable, AddressInfo)],
) -> Vec<LocatedVariable> {
    located
        .iter()
        .filter(|(_, info)| {
            let Some(bytes) = info.bytes() else {
                return false;
            };
            !project.io_areas.iter().any(|area| {
                let first = u64::from(area.start_byte);
                area_of(area.direction) == info.area
                    && bytes.start >= first
                    && bytes.end <= first + u64::from(area.size_bytes)
            })
        })
        .map(|(variable, _)| variable.clone())
        .collect()
}

fn area_of(direction: IoDirection) -> AddressArea {
    match direction {
        IoDirection::Input => AddressArea::Input,
        IoDirection::Output => AddressArea::Output,
        IoDirection::Memory => AddressArea::Memory,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_example_binds_its_buttons_to_bits_and_its_set_point_to_a_word() {
        let loaded = project_model::load_project(&assets::example_project_dir()).unwrap();
        let project = &loaded.project;
        let located = compiler::ide::located_variables(project);
        let inputs = project.io_areas.iter().find(|a| a.name == "DI_16").unwrap();
        let channels = area_channels(inputs, &located);
        // One word followed by its sixteen bits.
        assert_eq!(channels.len(), 17);
        let start = channels.iter().find(|c| c.address == "%IX0.0").unwrap();
        assert_eq!(start.bound.len(), 1);
        assert_eq!(
            (start.bound[0].owner.as_str(), start.bound[0].name.as_str()),
            ("GVL_IO", "xStartButton")
        );
        // The word over the buttons holds no word-sized variable.
        assert!(channels[0].bound.is_empty());
        assert!(
            channels
                .iter()
                .any(|c| c.address == "%IX1.7" && c.bound.is_empty())
        );
        let analog = project.io_areas.iter().find(|a| a.name == "AO_2").unwrap();
        let words = area_channels(analog, &located);
        let set_point = words.iter().find(|c| c.address == "%QW1").unwrap();
        assert_eq!(set_point.bound[0].name, "iBeltSpeedSetpoint");
        assert!(outside_areas(project, &located).is_empty());
    }
}

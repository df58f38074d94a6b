//! Checks of an I/O area: its name, its size and where it lies among the others.

use super::{DeviceProblem, name_problems, others};
use crate::IoArea;

/// The largest located area a program image may have (`program_image`'s `MAX_REGION_BYTES`,
/// repeated here because this crate depends on no other): 64 MiB.
pub const LOCATED_AREA_BYTES: u32 = 64 * 1024 * 1024;

/// Every problem of `area` as the I/O area at `index` of `areas` (`None` for a new one): its
/// name, a size of 0, bytes past the end of the located area, and bytes shared with another
/// area of the same direction, naming it.
pub fn io_area_problems(
    areas: &[IoArea],
    index: Option<usize>,
    area: &IoArea,
) -> Vec<DeviceProblem> {
    let mut problems = name_problems(
        "I/O area",
        &area.name,
        others(areas, index).map(|(_, other)| other.name.as_str()),
    );
    if area.size_bytes == 0 {
        problems.push(DeviceProblem::ZeroSize);
        return problems;
    }
    let end = u64::from(area.start_byte) + u64::from(area.size_bytes);
    if end > u64::from(LOCATED_AREA_BYTES) {
        problems.push(DeviceProblem::AreaPastEnd {
            start_byte: area.start_byte,
            size_bytes: area.size_bytes,
            limit: LOCATED_AREA_BYTES,
        });
    }
    for (_, other) in others(areas, index) {
        let other_end = u64::from(other.start_byte) + u64::from(other.size_bytes);
        let first = area.start_byte.max(other.start_byte);
        let last = end.min(other_end);
        if other.direction == area.direction && u64::from(first) < last {
            problems.push(DeviceProblem::AreasOverlap {
                direction: area.direction,
                first,
                // `last` is below `end`, which fits in a u32 plus one byte.
                last: u32::try_from(last - 1).unwrap_or(u32::MAX),
                other: other.name.clone(),
            });
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::IoDirection;

    fn area(name: &str, direction: IoDirection, start_byte: u32, size_bytes: u32) -> IoArea {
        IoArea {
            name: name.into(),
            direction,
            start_byte,
            size_bytes,
            comment: String::new(),
        }
    }

    fn example() -> Vec<IoArea> {
        vec![
            area("DI_16", IoDirection::Input, 0, 2),
            area("DO_16", IoDirection::Output, 0, 2),
            area("AO_2", IoDirection::Output, 2, 4),
        ]
    }

    #[test]
    fn an_area_overlapping_another_of_its_direction_names_it_and_the_bytes() {
        let areas = example();
        let moved = area("AO_2", IoDirection::Output, 1, 4);
        let problems = io_area_problems(&areas, Some(2), &moved);
        assert_eq!(
            problems,
            [DeviceProblem::AreasOverlap {
                direction: IoDirection::Output,
                first: 1,
                last: 1,
                other: "DO_16".into()
            }]
        );
        assert_eq!(
            problems[0].to_string(),
            "byte %QB1 overlaps the I/O area 'DO_16'"
        );
    }

    #[test]
    fn an_overlap_of_several_bytes_names_the_first_and_the_last() {
        let areas = example();
        let moved = area("AO_2", IoDirection::Output, 0, 4);
        let problems = io_area_problems(&areas, Some(2), &moved);
        assert_eq!(
            problems[0].to_string(),
            "bytes %QB0 to %QB1 overlap the I/O area 'DO_16'"
        );
    }

    #[test]
    fn areas_of_other_directions_and_the_area_itself_never_overlap() {
        let areas = example();
        assert!(io_area_problems(&areas, Some(0), &areas[0]).is_empty());
        let memory = area("Markers", IoDirection::Memory, 0, 1024);
        assert!(io_area_problems(&areas, None, &memory).is_empty());
    }

    #[test]
    fn a_size_of_0_and_bytes_past_the_located_area_are_refused() {
        let areas = example();
        let empty = area("AI", IoDirection::Input, 4, 0);
        assert_eq!(
            io_area_problems(&areas, None, &empty),
            [DeviceProblem::ZeroSize]
        );
        let far = area("AI", IoDirection::Input, LOCATED_AREA_BYTES - 1, 2);
        assert_eq!(
            io_area_problems(&areas, None, &far),
            [DeviceProblem::AreaPastEnd {
                start_byte: LOCATED_AREA_BYTES - 1,
                size_bytes: 2,
                limit: LOCATED_AREA_BYTES
            }]
        );
        let last = area("AI", IoDirection::Input, LOCATED_AREA_BYTES - 2, 2);
        assert!(io_area_problems(&areas, None, &last).is_empty());
    }

    #[test]
    fn a_new_area_may_not_take_a_used_name() {
        let areas = example();
        let copy = area("do_16", IoDirection::Memory, 0, 2);
        assert_eq!(
            io_area_problems(&areas, None, &copy),
            [DeviceProblem::DuplicateName {
                kind: "I/O area",
                name: "do_16".into()
            }]
        );
    }
}

//! Checks of a motion axis: its name, task, unit, period, limits and scaling.

use super::{DeviceProblem, name_problems, others};
use crate::{Axis, Project};

/// Every problem of `axis` as the axis at `index` of the project's axes (`None` for a new
/// one): its name, a task that does not exist, an empty unit, numbers that are not finite, a
/// modulo period of 0 or less, enabled software limits whose minimum is not below their
/// maximum, dynamic limits of 0 or less, a scaling term of 0.
pub fn axis_problems(project: &Project, index: Option<usize>, axis: &Axis) -> Vec<DeviceProblem> {
    let mut problems = name_problems(
        "axis",
        &axis.name,
        others(&project.axes, index).map(|(_, other)| other.name.as_str()),
    );
    if project.task(&axis.task).is_none() {
        problems.push(DeviceProblem::NoSuchTask(axis.task.clone()));
    }
    if axis.unit.trim().is_empty() {
        problems.push(DeviceProblem::EmptyUnit);
    }
    let numbers = [
        ("modulo period", axis.modulo_period.unwrap_or(1.0)),
        ("negative software limit", axis.software_limits.min),
        ("positive software limit", axis.software_limits.max),
        ("velocity", axis.limits.velocity),
        ("acceleration", axis.limits.acceleration),
        ("deceleration", axis.limits.deceleration),
        ("jerk", axis.limits.jerk),
        ("scaling numerator", axis.scaling.numerator),
        ("scaling denominator", axis.scaling.denominator),
    ];
    for (field, value) in numbers {
        if !value.is_finite() {
            problems.push(DeviceProblem::NotFinite { field });
        }
    }
    if let Some(period) = axis.modulo_period
        && period <= 0.0
    {
        problems.push(DeviceProblem::ModuloNotPositive(period));
    }
    let limits = axis.software_limits;
    if limits.enabled && limits.min >= limits.max {
        problems.push(DeviceProblem::LimitsInverted {
            min: limits.min,
            max: limits.max,
        });
    }
    for (field, value) in numbers[3..7].iter().copied() {
        if value <= 0.0 {
            problems.push(DeviceProblem::DynamicLimitNotPositive { field, value });
        }
    }
    for (field, value) in [
        ("numerator", axis.scaling.numerator),
        ("denominator", axis.scaling.denominator),
    ] {
        if value == 0.0 {
            problems.push(DeviceProblem::ZeroScaling { field });
        }
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Project {
        crate::load_project(&assets::example_project_dir())
            .unwrap()
            .project
    }

    #[test]
    fn the_example_axes_have_no_problem() {
        let project = example();
        for (index, axis) in project.axes.iter().enumerate() {
            assert_eq!(axis_problems(&project, Some(index), axis), []);
        }
    }

    #[test]
    fn a_missing_task_an_empty_unit_and_a_period_of_0_are_refused() {
        let project = example();
        let mut axis = project.axes[0].clone();
        axis.task = "FastTask".into();
        axis.unit = " ".into();
        axis.modulo_period = Some(0.0);
        assert_eq!(
            axis_problems(&project, Some(0), &axis),
            [
                DeviceProblem::NoSuchTask("FastTask".into()),
                DeviceProblem::EmptyUnit,
                DeviceProblem::ModuloNotPositive(0.0)
            ]
        );
    }

    #[test]
    fn enabled_software_limits_must_have_min_below_max() {
        let project = example();
        let mut axis = project.axes[0].clone();
        axis.software_limits.min = 10.0;
        axis.software_limits.max = 10.0;
        assert!(axis_problems(&project, Some(0), &axis).is_empty());
        axis.software_limits.enabled = true;
        let problems = axis_problems(&project, Some(0), &axis);
        assert_eq!(
            problems,
            [DeviceProblem::LimitsInverted {
                min: 10.0,
                max: 10.0
            }]
        );
        assert_eq!(
            problems[0].to_string(),
            "the negative software limit 10 must be below the positive limit 10"
        );
    }

    #[test]
    fn dynamic_limits_must_be_positive_and_scaling_terms_non_zero() {
        let project = example();
        let mut axis = project.axes[1].clone();
        axis.limits.deceleration = -1.0;
        axis.limits.jerk = f64::NAN;
        axis.scaling.denominator = 0.0;
        assert_eq!(
            axis_problems(&project, Some(1), &axis),
            [
                DeviceProblem::NotFinite { field: "jerk" },
                DeviceProblem::DynamicLimitNotPositive {
                    field: "deceleration",
                    value: -1.0
                },
                DeviceProblem::ZeroScaling {
                    field: "denominator"
                },
            ]
        );
    }

    #[test]
    fn a_new_axis_may_not_take_an_existing_axis_name() {
        let project = example();
        let axis = project.axes[1].clone();
        assert!(matches!(
            axis_problems(&project, None, &axis)[..],
            [DeviceProblem::DuplicateName { kind: "axis", .. }]
        ));
    }
}

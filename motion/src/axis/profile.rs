//! The profile generator: a time-parameterised motion from the axis's current velocity and
//! acceleration to a target position (coming to rest there) or to a target velocity.
//!
//! Method: a profile is planned once, when a command takes control of the axis, as a short list
//! of segments of constant jerk; the kernel then samples it at the time elapsed since the start.
//! With a jerk limit the profile is an S-curve: the acceleration first returns to zero (if the
//! axis was accelerating when the command took over), then each velocity change is a ramp of up
//! to three segments (jerk up, constant acceleration, jerk down). Without a jerk limit each
//! velocity change is one segment of constant acceleration (a trapezoid). For a target position
//! the peak velocity is the commanded velocity when the distance allows it, otherwise the highest
//! velocity that still lets the axis brake to the target, found by bisection on the closed-form
//! distance of the ramps; a constant-velocity segment covers the remaining distance. When the
//! axis cannot stop before the target, or moves away from it, it first brakes to rest and then
//! travels back. Sampling at or after the end returns the exact target, so a move ends exactly
//! where it was commanded to, without drift.
//!
//! For the blending buffer modes a move may instead pass its target with an end speed (and
//! zero acceleration); the last ramp then ends at that speed rather than at rest.
//!
//! A profile is replanned from the axis's current set values (never from the old plan) when an
//! override or a ContinuousUpdate input changes, so a replan cannot make the set values jump.

/// The dynamic limits a profile is planned with, all magnitudes in user units per s, s², s³.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProfileLimits {
    /// The highest speed of the move; must be positive.
    pub velocity: f64,
    /// The highest acceleration while the speed rises; must be positive.
    pub acceleration: f64,
    /// The highest deceleration while the speed falls; must be positive.
    pub deceleration: f64,
    /// The highest jerk; 0 plans a trapezoidal profile (acceleration steps).
    pub jerk: f64,
    /// The jerk that brings an acceleration above `acceleration` or `deceleration`, carried
    /// over from an aborted command, back within them: the axis's jerk limit, so that a gentle
    /// command taking over a hard ramp does not overshoot far past its target. Not above
    /// `jerk` it has no effect; 0 means the axis has no jerk limit and the excess is dropped at
    /// once.
    pub recovery_jerk: f64,
}

impl ProfileLimits {
    /// The acceleration limit for a speed change from `from` to `to` (same sign or zero).
    fn ramp_limit(&self, from: f64, to: f64) -> f64 {
        if to.abs() > from.abs() {
            self.acceleration
        } else {
            self.deceleration
        }
    }

    /// The durations of the jerk phases and of the constant-acceleration phase of a ramp.
    fn ramp_times(&self, from: f64, to: f64) -> (f64, f64) {
        let change = (to - from).abs();
        let a_max = self.ramp_limit(from, to);
        let jerk = self.jerk;
        if jerk <= 0.0 {
            (0.0, change / a_max)
        } else if change >= a_max * a_max / jerk {
            (a_max / jerk, change / a_max - a_max / jerk)
        } else {
            ((change / jerk).sqrt(), 0.0)
        }
    }

    /// The distance a velocity ramp from `from` to `to` (same sign or zero) covers: a ramp is
    /// symmetric about its middle, so it covers the mean velocity times its duration.
    pub fn ramp_distance(&self, from: f64, to: f64) -> f64 {
        let (jerk_s, constant_s) = self.ramp_times(from, to);
        (from + to) / 2.0 * (2.0 * jerk_s + constant_s)
    }

    /// The highest speed up to `wanted` that a ramp from `from` reaches within `distance`
    /// (speeds along the direction of travel, `from` below `wanted`).
    #[must_use]
    pub fn reachable_speed(&self, from: f64, wanted: f64, distance: f64) -> f64 {
        if self.ramp_distance(from, wanted) <= distance {
            return wanted;
        }
        bisect(from, wanted, |speed| {
            self.ramp_distance(from, speed) <= distance
        })
    }

    /// The highest speed up to `wanted` from which a ramp to rest fits within `distance`.
    #[must_use]
    pub fn stoppable_speed(&self, wanted: f64, distance: f64) -> f64 {
        if self.ramp_distance(wanted, 0.0) <= distance {
            return wanted;
        }
        bisect(0.0, wanted, |speed| {
            self.ramp_distance(speed, 0.0) <= distance
        })
    }
}

/// The value between `fits` (where `test` holds) and `too_far` (where it does not) at which
/// `test` stops holding, to the last bit; returns a value where `test` holds.
fn bisect(mut fits: f64, mut too_far: f64, test: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..200 {
        let middle = (fits + too_far) / 2.0;
        if middle == fits || middle == too_far {
            break;
        }
        if test(middle) {
            fits = middle;
        } else {
            too_far = middle;
        }
    }
    fits
}

/// The state of a profile at one time: displacement from the start and its derivatives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProfileSample {
    /// Displacement from the position at the start of the profile.
    pub displacement: f64,
    /// Velocity in user units per second.
    pub velocity: f64,
    /// Acceleration in user units per second².
    pub acceleration: f64,
    /// Jerk in user units per second³.
    pub jerk: f64,
}

/// One segment of constant jerk, with the state at its start.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Segment {
    duration_s: f64,
    displacement: f64,
    velocity: f64,
    acceleration: f64,
    jerk: f64,
}

/// The most segments a plan needs: settling the acceleration (1), braking before a reversal
/// (3), a ramp up (3), a cruise (1) and a ramp down (3).
const MAX_SEGMENTS: usize = 12;

/// A planned motion. It is a plain value without heap memory, so the kernel replans without
/// allocating.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Profile {
    segments: [Segment; MAX_SEGMENTS],
    count: usize,
    total_s: f64,
    end: ProfileSample,
}

impl Profile {
    /// A profile that stays at rest where it starts and is finished at once.
    #[must_use]
    pub fn at_rest() -> Self {
        Self {
            segments: [Segment::default(); MAX_SEGMENTS],
            count: 0,
            total_s: 0.0,
            end: ProfileSample::default(),
        }
    }

    /// A profile that starts with `velocity` and `acceleration` and comes to rest exactly
    /// `distance` away (signed).
    #[must_use]
    pub fn to_position(
        distance: f64,
        velocity: f64,
        acceleration: f64,
        limits: ProfileLimits,
    ) -> Self {
        Self::to_position_blending(distance, velocity, acceleration, limits, 0.0)
    }

    /// A profile that starts with `velocity` and `acceleration` and arrives exactly `distance`
    /// away (signed) with the speed `end_speed` (not negative, along the direction of travel) and
    /// zero acceleration, for the blending buffer modes. When the distance is too short to
    /// reach `end_speed`, the axis arrives with the highest speed it can reach; when the axis
    /// is too fast to slow down to `end_speed` in time, it comes to rest at the target instead.
    #[must_use]
    pub fn to_position_blending(
        distance: f64,
        velocity: f64,
        acceleration: f64,
        limits: ProfileLimits,
        end_speed: f64,
    ) -> Self {
        let mut plan = Builder::new(velocity, acceleration, limits);
        plan.settle_acceleration();
        let dir = if distance < 0.0 { -1.0 } else { 1.0 };
        let end_speed = if distance == 0.0 {
            0.0
        } else {
            end_speed.max(0.0)
        };
        let speed = dir * plan.velocity;
        let remaining = dir * (distance - plan.displacement);
        let arrival = if speed < 0.0 {
            plan.ramp(dir, speed, 0.0);
            let remaining = dir * (distance - plan.displacement);
            let end = limits.reachable_speed(0.0, end_speed, remaining);
            plan.forward(dir, 0.0, remaining, end);
            end
        } else if speed <= end_speed {
            let end = limits.reachable_speed(speed, end_speed, remaining);
            plan.forward(dir, speed, remaining, end);
            end
        } else if remaining >= limits.ramp_distance(speed, end_speed) {
            plan.forward(dir, speed, remaining, end_speed);
            end_speed
        } else if remaining >= limits.ramp_distance(speed, 0.0) {
            plan.forward(dir, speed, remaining, 0.0);
            0.0
        } else {
            plan.ramp(dir, speed, 0.0);
            let overshoot = dir * (plan.displacement - distance);
            plan.forward(-dir, 0.0, overshoot, 0.0);
            0.0
        };
        plan.finish(distance, dir * arrival)
    }

    /// A profile that starts with `velocity` and `acceleration` and reaches `target_velocity`
    /// (signed); after its end the velocity stays constant.
    #[must_use]
    pub fn to_velocity(
        target_velocity: f64,
        velocity: f64,
        acceleration: f64,
        limits: ProfileLimits,
    ) -> Self {
        let mut plan = Builder::new(velocity, acceleration, limits);
        plan.settle_acceleration();
        let start = plan.velocity;
        if start * target_velocity < 0.0 {
            plan.ramp(1.0, start, 0.0);
            plan.ramp(1.0, 0.0, target_velocity);
        } else {
            plan.ramp(1.0, start, target_velocity);
        }
        let displacement = plan.displacement;
        plan.finish(displacement, target_velocity)
    }

    /// The duration of the profile in seconds; after it the velocity stays at the end velocity.
    #[must_use]
    pub fn duration_s(&self) -> f64 {
        self.total_s
    }

    /// The displacement and velocity at the end of the profile.
    #[must_use]
    pub fn end(&self) -> ProfileSample {
        self.end
    }

    /// The state `time_s` seconds after the start; at or after the end, the exact end state
    /// continued at the end velocity.
    #[must_use]
    pub fn sample(&self, time_s: f64) -> ProfileSample {
        if time_s >= self.total_s {
            let after_s = time_s - self.total_s;
            return ProfileSample {
                displacement: self.end.displacement + self.end.velocity * after_s,
                velocity: self.end.velocity,
                acceleration: 0.0,
                jerk: 0.0,
            };
        }
        let mut start_s = 0.0;
        for segment in &self.segments[..self.count] {
            if time_s < start_s + segment.duration_s {
                return segment.at((time_s - start_s).max(0.0));
            }
            start_s += segment.duration_s;
        }
        // Rounding in the sum of durations can leave `time_s` just past the last segment.
        self.end
    }
}

impl Segment {
    fn at(&self, t: f64) -> ProfileSample {
        let (p, v, a, j) = (
            self.displacement,
            self.velocity,
            self.acceleration,
            self.jerk,
        );
        ProfileSample {
            displacement: p + v * t + a * t * t / 2.0 + j * t * t * t / 6.0,
            velocity: v + a * t + j * t * t / 2.0,
            acceleration: a + j * t,
            jerk: j,
        }
    }
}

/// Builds a profile segment by segment, integrating the state at the end of each segment.
struct Builder {
    profile: Profile,
    limits: ProfileLimits,
    displacement: f64,
    velocity: f64,
    acceleration: f64,
}

impl Builder {
    fn new(velocity: f64, acceleration: f64, limits: ProfileLimits) -> Self {
        Self {
            profile: Profile::at_rest(),
            limits,
            displacement: 0.0,
            velocity,
            // Without a jerk limit the acceleration may step, so the old one does not matter.
            acceleration: if limits.jerk > 0.0 { acceleration } else { 0.0 },
        }
    }

    fn push(&mut self, duration_s: f64, acceleration: f64, jerk: f64) {
        if duration_s <= 0.0 || self.profile.count >= MAX_SEGMENTS {
            return;
        }
        let segment = Segment {
            duration_s,
            displacement: self.displacement,
            velocity: self.velocity,
            acceleration,
            jerk,
        };
        let end = segment.at(duration_s);
        self.profile.segments[self.profile.count] = segment;
        self.profile.count += 1;
        self.profile.total_s += duration_s;
        self.displacement = end.displacement;
        self.velocity = end.velocity;
        self.acceleration = end.acceleration;
    }

    /// Brings a non-zero acceleration back to zero at the jerk limit, so that the ramps that
    /// follow all start and end at zero acceleration. The part of the acceleration above the
    /// command's own limit (a harder ramp of an aborted command) is first taken back at the
    /// recovery jerk.
    fn settle_acceleration(&mut self) {
        let jerk = self.limits.jerk;
        if jerk <= 0.0 || self.acceleration == 0.0 {
            return;
        }
        let a = self.acceleration;
        // Speeding up is bounded by the acceleration limit, slowing down by the deceleration.
        let bound = if a * self.velocity > 0.0 {
            self.limits.acceleration
        } else {
            self.limits.deceleration
        };
        let recovery_jerk = self.limits.recovery_jerk;
        if a.abs() > bound && recovery_jerk > jerk {
            let excess = a.abs() - bound;
            self.push(excess / recovery_jerk, a, -a.signum() * recovery_jerk);
            // The recovery ends exactly on the bound, free of integration rounding.
            self.acceleration = a.signum() * bound;
        } else if a.abs() > bound && recovery_jerk == 0.0 {
            // Without an axis jerk limit the excess may step away.
            self.acceleration = a.signum() * bound;
        }
        let a = self.acceleration;
        self.push(a.abs() / jerk, a, -a.signum() * jerk);
        self.acceleration = 0.0;
    }

    /// Appends a ramp from speed `from` to speed `to`, both measured along `dir`.
    fn ramp(&mut self, dir: f64, from: f64, to: f64) {
        if from == to {
            return;
        }
        let (jerk_s, constant_s) = self.limits.ramp_times(from, to);
        let sign = dir * (to - from).signum();
        let a_max = self.limits.ramp_limit(from, to);
        let jerk = self.limits.jerk;
        if jerk <= 0.0 {
            self.push(constant_s, sign * a_max, 0.0);
        } else {
            self.push(jerk_s, 0.0, sign * jerk);
            self.push(constant_s, self.acceleration, 0.0);
            self.push(jerk_s, self.acceleration, -sign * jerk);
            self.acceleration = 0.0;
        }
        // The ramp ends at the exact speed, free of the rounding of the integration.
        self.velocity = dir * to;
    }

    /// Appends the motion along `dir` from speed `speed` (not negative) over `distance` to
    /// speed `end` (not negative). The distance must allow it: at least the distance of the
    /// ramp from `speed` to `end`.
    fn forward(&mut self, dir: f64, speed: f64, distance: f64, end: f64) {
        let limits = self.limits;
        let cruise = limits.velocity.max(end);
        let covered =
            |peak: f64| limits.ramp_distance(speed, peak) + limits.ramp_distance(peak, end);
        let peak = if covered(cruise) <= distance {
            cruise
        } else {
            // At the lowest possible peak the ramps fit; at the cruise velocity they do not.
            bisect(speed.max(end), cruise, |peak| covered(peak) <= distance)
        };
        let cruise_distance = distance - covered(peak);
        self.ramp(dir, speed, peak);
        if peak > 0.0 && cruise_distance > 0.0 {
            self.push(cruise_distance / peak, 0.0, 0.0);
        }
        self.ramp(dir, peak, end);
    }

    fn finish(mut self, displacement: f64, velocity: f64) -> Profile {
        self.profile.end = ProfileSample {
            displacement,
            velocity,
            acceleration: 0.0,
            jerk: 0.0,
        };
        self.profile
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]
    use super::*;

    const TRAPEZOID: ProfileLimits = ProfileLimits {
        velocity: 100.0,
        acceleration: 1000.0,
        deceleration: 500.0,
        jerk: 0.0,
        recovery_jerk: 0.0,
    };

    #[test]
    fn a_long_trapezoid_cruises_at_the_commanded_velocity() {
        let profile = Profile::to_position(1000.0, 0.0, 0.0, TRAPEZOID);
        // 0.1 s up (5 units), 0.2 s down (10 units), 985 units at 100 u/s.
        assert!((profile.duration_s() - (0.1 + 9.85 + 0.2)).abs() < 1e-9);
        assert!((profile.sample(5.0).velocity - 100.0).abs() < 1e-9);
        assert_eq!(profile.sample(20.0).displacement, 1000.0);
    }

    #[test]
    fn a_short_trapezoid_is_a_triangle_that_ends_at_the_target() {
        let profile = Profile::to_position(1.5, 0.0, 0.0, TRAPEZOID);
        let peak = (0..1000)
            .map(|i| profile.sample(f64::from(i) * 1e-4).velocity)
            .fold(0.0, f64::max);
        // v²/2a + v²/2d = 1.5 gives v = sqrt(1000) ≈ 31.6.
        assert!((peak - 1000f64.sqrt()).abs() < 0.2, "peak {peak}");
        let end = profile.sample(profile.duration_s() - 1e-12);
        assert!((end.displacement - 1.5).abs() < 1e-9);
    }

    #[test]
    fn a_velocity_ramp_reverses_through_zero() {
        let profile = Profile::to_velocity(-50.0, 50.0, 0.0, TRAPEZOID);
        // 50 → 0 at 500 u/s², then 0 → −50 at 1000 u/s².
        assert!((profile.duration_s() - 0.15).abs() < 1e-12);
        assert_eq!(profile.sample(1.0).velocity, -50.0);
    }

    #[test]
    fn an_axis_past_its_target_brakes_and_comes_back() {
        let profile = Profile::to_position(1.0, 100.0, 0.0, TRAPEZOID);
        // Braking from 100 u/s at 500 u/s² takes 10 units, so it returns 9 units.
        let furthest = (0..10_000)
            .map(|i| profile.sample(f64::from(i) * 1e-4).displacement)
            .fold(0.0, f64::max);
        assert!((furthest - 10.0).abs() < 1e-3, "furthest {furthest}");
        assert_eq!(profile.sample(profile.duration_s()).displacement, 1.0);
    }
}

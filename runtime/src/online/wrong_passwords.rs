//! The wrong passwords each client address sent, so that a client cannot guess faster by
//! opening more connections (`docs/protocol.md` §5, "Guessing").

use std::collections::HashMap;
use std::net::{IpAddr, Ipv6Addr};
use std::time::{Duration, Instant};

/// How long an address waits after its first wrong password (and the answer to it is late);
/// each further wrong password in a row doubles the wait, up to [`LONGEST_WAIT`].
pub const WRONG_PASSWORD_DELAY: Duration = Duration::from_millis(500);

/// The longest an address waits after a wrong password: 16 times [`WRONG_PASSWORD_DELAY`].
pub const LONGEST_WAIT: Duration = Duration::from_secs(8);

/// How long an address must send no wrong password for one of its earlier ones to be
/// forgotten, so that the wait shrinks back for a user who mistyped a while ago.
pub const FORGET_ONE_AFTER: Duration = Duration::from_secs(30);

/// The most addresses remembered at once, so that a peer sending from many addresses cannot
/// make the runtime's memory grow; past it, the address whose last wrong password is oldest
/// is forgotten.
pub const MAX_ADDRESSES: usize = 1024;

/// The wrong passwords of each client address, shared by all its connections.
///
/// Every time is given by the caller, so that the rules are tested without a clock.
#[derive(Debug, Default)]
pub(crate) struct WrongPasswords {
    addresses: HashMap<IpAddr, Strikes>,
}

/// The wrong passwords of one address.
#[derive(Clone, Copy, Debug)]
struct Strikes {
    /// Wrong passwords not forgotten yet.
    count: u32,
    /// When the last wrong password came.
    last: Instant,
    /// Until when no password of this address is checked.
    blocked_until: Instant,
}

impl Strikes {
    /// The strikes left at `now`, one forgotten for each [`FORGET_ONE_AFTER`] since the last.
    fn remaining(&self, now: Instant) -> u32 {
        let quiet = now.saturating_duration_since(self.last);
        let forgotten = quiet.as_secs() / FORGET_ONE_AFTER.as_secs();
        self.count
            .saturating_sub(u32::try_from(forgotten).unwrap_or(u32::MAX))
    }
}

impl WrongPasswords {
    /// How long `address` must still wait at `now` before a password of its is checked;
    /// `None` when one may be checked now.
    pub(crate) fn wait(&self, address: IpAddr, now: Instant) -> Option<Duration> {
        let strikes = self.addresses.get(&client(address))?;
        let left = strikes.blocked_until.saturating_duration_since(now);
        (!left.is_zero()).then_some(left)
    }

    /// Notes a wrong password from `address` at `now` and returns how long the address now
    /// waits: [`WRONG_PASSWORD_DELAY`], doubled for each earlier wrong password not yet
    /// forgotten, at most [`LONGEST_WAIT`].
    pub(crate) fn failed(&mut self, address: IpAddr, now: Instant) -> Duration {
        let address = client(address);
        if !self.addresses.contains_key(&address) && self.addresses.len() >= MAX_ADDRESSES {
            self.make_room(now);
        }
        let count = self
            .addresses
            .get(&address)
            .map_or(0, |strikes| strikes.remaining(now))
            .saturating_add(1);
        let wait = WRONG_PASSWORD_DELAY
            .saturating_mul(1 << (count - 1).min(31))
            .min(LONGEST_WAIT);
        self.addresses.insert(
            address,
            Strikes {
                count,
                last: now,
                blocked_until: now + wait,
            },
        );
        wait
    }

    /// Forgets the wrong passwords of `address`, which has just sent the right one.
    pub(crate) fn succeeded(&mut self, address: IpAddr) {
        self.addresses.remove(&client(address));
    }

    /// Forgets every address whose strikes are all forgotten at `now`, and, if that frees
    /// nothing, the address whose last wrong password is oldest.
    fn make_room(&mut self, now: Instant) {
        self.addresses
            .retain(|_, strikes| strikes.remaining(now) > 0 || strikes.blocked_until > now);
        if self.addresses.len() < MAX_ADDRESSES {
            return;
        }
        let oldest = self
            .addresses
            .iter()
            .min_by_key(|(_, strikes)| strikes.last)
            .map(|(address, _)| *address);
        if let Some(oldest) = oldest {
            self.addresses.remove(&oldest);
        }
    }

    /// How many addresses are remembered.
    #[cfg(test)]
    fn len(&self) -> usize {
        self.addresses.len()
    }
}

/// The client an address stands for: an IPv4 address as itself (also when it comes mapped
/// into IPv6), an IPv6 address by its /64 prefix, which one machine usually holds whole and
/// could otherwise send from a new address for every guess.
fn client(address: IpAddr) -> IpAddr {
    match address {
        IpAddr::V4(_) => address,
        IpAddr::V6(v6) => match v6.to_ipv4_mapped() {
            Some(v4) => IpAddr::V4(v4),
            None => IpAddr::V6(Ipv6Addr::from(v6.to_bits() & !u128::from(u64::MAX))),
        },
    }
}

#[cfg(test)]
mod tests {
    use std::net::Ipv4Addr;
    use std::str::FromStr;

    use super::*;

    fn address(last: u8) -> IpAddr {
        IpAddr::V4(Ipv4Addr::new(192, 168, 0, last))
    }

    #[test]
    fn each_wrong_password_of_an_address_doubles_its_wait_up_to_the_longest() {
        let mut wrong = WrongPasswords::default();
        let start = Instant::now();
        let mut now = start;
        let mut waits = Vec::new();
        for _ in 0..7 {
            let wait = wrong.failed(address(1), now);
            waits.push(wait.as_millis());
            // The next guess comes as soon as the address may send one.
            now += wait;
        }
        assert_eq!(waits, [500, 1000, 2000, 4000, 8000, 8000, 8000]);
    }

    #[test]
    fn an_address_waits_whichever_connection_it_sends_from_and_others_do_not() {
        let mut wrong = WrongPasswords::default();
        let now = Instant::now();
        assert_eq!(wrong.wait(address(1), now), None);
        let wait = wrong.failed(address(1), now);
        // Another connection of the same address is held for the rest of the wait.
        let later = now + Duration::from_millis(200);
        assert_eq!(wrong.wait(address(1), later), Some(wait - (later - now)));
        assert_eq!(wrong.wait(address(1), now + wait), None);
        // Another address is not held at all.
        assert_eq!(wrong.wait(address(2), later), None);
    }

    #[test]
    fn strikes_are_forgotten_with_time_and_by_the_right_password() {
        let mut wrong = WrongPasswords::default();
        let start = Instant::now();
        for seconds in [0, 1, 3] {
            wrong.failed(address(1), start + Duration::from_secs(seconds));
        }
        // Three strikes: the fourth would wait 4 s; 60 s later two are forgotten.
        let later = start + Duration::from_secs(3) + FORGET_ONE_AFTER * 2;
        assert_eq!(wrong.failed(address(1), later), Duration::from_secs(1));
        wrong.succeeded(address(1));
        assert_eq!(wrong.wait(address(1), later), None);
        assert_eq!(wrong.failed(address(1), later), WRONG_PASSWORD_DELAY);
    }

    #[test]
    fn an_ipv6_client_is_its_64_bit_prefix_and_a_mapped_ipv4_one_its_address() {
        let mut wrong = WrongPasswords::default();
        let now = Instant::now();
        let parse = |text: &str| IpAddr::from_str(text).unwrap();
        wrong.failed(parse("2001:db8:1:2::7"), now);
        wrong.failed(parse("::ffff:192.168.0.1"), now);
        assert!(wrong.wait(parse("2001:db8:1:2:ffff::1"), now).is_some());
        assert_eq!(wrong.wait(parse("2001:db8:1:3::7"), now), None);
        assert!(wrong.wait(address(1), now).is_some());
    }

    #[test]
    fn the_addresses_remembered_are_bounded() {
        let mut wrong = WrongPasswords::default();
        let start = Instant::now();
        // Each address in its own /64 prefix.
        let nth = |index: usize| IpAddr::V6(Ipv6Addr::from((index as u128) << 64));
        for index in 0..=MAX_ADDRESSES {
            wrong.failed(nth(index), start + Duration::from_millis(index as u64));
        }
        assert_eq!(wrong.len(), MAX_ADDRESSES);
        // The oldest went; the newest is held.
        let first = nth(0);
        let newest = nth(MAX_ADDRESSES);
        let now = start + Duration::from_millis(MAX_ADDRESSES as u64);
        assert_eq!(wrong.wait(first, now), None);
        assert!(wrong.wait(newest, now).is_some());
    }
}

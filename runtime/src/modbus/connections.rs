//! The connections a Modbus server is serving, so that a new client always gets in.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, PoisonError};

use tokio::sync::Notify;
use tokio::time::Instant;

/// The open connections of one server, each with the time of its last whole request.
///
/// When the server is full, a new connection takes the place of the connection that has gone
/// longest without a whole request: an idle client, or a slow one trickling a frame, can then
/// never keep a working client out (`docs/modbus-map.md`, "Connections").
#[derive(Debug, Default)]
pub(crate) struct Connections {
    open: Mutex<HashMap<u64, OpenConnection>>,
}

/// One open connection.
#[derive(Debug)]
struct OpenConnection {
    /// When the connection was accepted or last sent a whole request.
    last_request: Instant,
    /// Told when the connection must close to make room for a new one.
    evicted: Arc<Notify>,
}

impl Connections {
    /// Registers connection `id`, accepted at `now`, closing the connection idle longest if
    /// `max_clients` are already open; returns what tells the connection to close, or `None`
    /// when `max_clients` is 0 and nobody may connect.
    pub(crate) fn admit(&self, id: u64, now: Instant, max_clients: usize) -> Option<Arc<Notify>> {
        if max_clients == 0 {
            return None;
        }
        let mut open = self.open.lock().unwrap_or_else(PoisonError::into_inner);
        while open.len() >= max_clients {
            let Some(idlest) = open
                .iter()
                .min_by_key(|(id, connection)| (connection.last_request, **id))
                .map(|(id, _)| *id)
            else {
                break;
            };
            if let Some(connection) = open.remove(&idlest) {
                // A permit is stored if the connection is not waiting yet, so it still closes.
                connection.evicted.notify_one();
            }
        }
        let evicted = Arc::new(Notify::new());
        open.insert(
            id,
            OpenConnection {
                last_request: now,
                evicted: Arc::clone(&evicted),
            },
        );
        Some(evicted)
    }

    /// Notes that connection `id` sent a whole request at `now`.
    pub(crate) fn touch(&self, id: u64, now: Instant) {
        let mut open = self.open.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(connection) = open.get_mut(&id) {
            connection.last_request = now;
        }
    }

    /// Forgets connection `id`, which has closed (nothing happens if it was evicted).
    pub(crate) fn remove(&self, id: u64) {
        let mut open = self.open.lock().unwrap_or_else(PoisonError::into_inner);
        open.remove(&id);
    }

    /// How many connections are open.
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.open
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .len()
    }
}

#[cfg(test)]
mod tests {
    use std::time::Duration;

    use super::*;

    /// Whether `evicted` has been told to close (consumes the permit).
    fn was_evicted(evicted: &Notify) -> bool {
        use std::future::Future;
        use std::pin::pin;
        use std::task::{Context, Poll, Waker};
        let notified = pin!(evicted.notified());
        matches!(
            notified.poll(&mut Context::from_waker(Waker::noop())),
            Poll::Ready(())
        )
    }

    #[test]
    fn a_full_server_closes_the_connection_without_a_request_for_longest() {
        let connections = Connections::default();
        let start = Instant::now();
        let at = |seconds: u64| start + Duration::from_secs(seconds);
        let first = connections.admit(1, at(0), 2).unwrap();
        let second = connections.admit(2, at(1), 2).unwrap();
        // The first connection works; the second has said nothing since it connected.
        connections.touch(1, at(5));
        let third = connections.admit(3, at(6), 2).unwrap();
        assert!(was_evicted(&second));
        assert!(!was_evicted(&first));
        assert_eq!(connections.len(), 2);
        // Now the first is the idlest (5 s against 6 s).
        let _fourth = connections.admit(4, at(7), 2).unwrap();
        assert!(was_evicted(&first));
        assert!(!was_evicted(&third));
    }

    #[test]
    fn closed_connections_free_their_place_and_zero_places_admit_nobody() {
        let connections = Connections::default();
        let now = Instant::now();
        let first = connections.admit(1, now, 1).unwrap();
        connections.remove(1);
        let _second = connections.admit(2, now, 1).unwrap();
        assert!(!was_evicted(&first));
        connections.remove(7);
        assert_eq!(connections.len(), 1);
        assert!(connections.admit(3, now, 0).is_none());
    }
}

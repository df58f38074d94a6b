//! The map a server serves, replaceable while it serves (after a download).

use std::sync::{Arc, PoisonError, RwLock};

use crate::modbus::map::ModbusMap;

/// The map the Modbus server translates addresses with; lives as long as the server and the
/// online services that replace it after a download; never saved.
#[derive(Debug)]
pub struct MapSlot {
    current: RwLock<Arc<ModbusMap>>,
}

impl MapSlot {
    /// A slot holding `map`, ready to share.
    pub fn new(map: ModbusMap) -> Arc<Self> {
        Arc::new(Self {
            current: RwLock::new(Arc::new(map)),
        })
    }

    /// The map now; a request is served with the map it started with.
    pub fn get(&self) -> Arc<ModbusMap> {
        Arc::clone(&self.current.read().unwrap_or_else(PoisonError::into_inner))
    }

    /// Replaces the map for the requests that come next.
    pub fn set(&self, map: ModbusMap) {
        *self.current.write().unwrap_or_else(PoisonError::into_inner) = Arc::new(map);
    }
}

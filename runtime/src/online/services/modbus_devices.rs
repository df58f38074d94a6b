//! The `MODBUS_DEVICES` service (`docs/modbus-master.md` §9.1): the state and counters of the
//! devices the runtime's Modbus master polls, page by page.

use online_protocol::{Response, modbus_devices_page};

use super::OnlineServices;

impl OnlineServices {
    /// The page of devices from the `from`-th on, in the image's order; `total` 0 without a
    /// program or without runtime devices. The master keeps each device's report as the
    /// protocol words it (`DeviceStatus::snapshot`), so nothing is translated here.
    pub(super) fn modbus_devices(&self, from: u8) -> Response {
        modbus_devices_page(&self.scheduler.modbus_devices(), from)
    }
}

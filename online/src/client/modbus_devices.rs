//! The client's side of `MODBUS_DEVICES` (`docs/modbus-master.md` §9.1): the state and
//! counters of every Modbus device the runtime masters, gathered page by page.

use online_protocol::{ModbusDeviceReport, Request, Response};

use super::{Client, unexpected};
use crate::error::OnlineError;

impl Client {
    /// `MODBUS_DEVICES`, asked again `from` where each answer ended until it has `total`:
    /// every device the runtime masters, in the image's order (none without a program or
    /// without runtime devices). A runtime older than the service answers status 1, which
    /// is [`OnlineError::ModbusDevicesNotReported`].
    pub async fn modbus_devices(&mut self) -> Result<Vec<ModbusDeviceReport>, OnlineError> {
        let mut devices = Vec::new();
        loop {
            // `total` is one byte, so while devices are missing their count fits `from`.
            let request = Request::ModbusDevices {
                from: u8::try_from(devices.len()).unwrap_or(u8::MAX),
            };
            let (total, page) = match self.call(&request).await? {
                Response::ModbusDevices { total, devices } => (total, devices),
                other => return Err(unexpected(&other)),
            };
            // An empty page before `total` would ask the same again forever.
            let empty = page.is_empty();
            devices.extend(page);
            if empty || devices.len() >= usize::from(total) {
                return Ok(devices);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)] // A panic is a failed test.

    use std::sync::{Arc, Mutex};

    use online_protocol::{ModbusDeviceState, Refusal, Status, modbus_devices_page};

    use super::*;

    /// The `index`-th device's report, with texts long enough that a page holds only two
    /// (32 bytes of name, as long as the runtime sends).
    fn device(index: usize) -> ModbusDeviceReport {
        ModbusDeviceReport {
            name: format!("Device{index:02}{}", "-".repeat(24)),
            state: ModbusDeviceState::ALL[index % ModbusDeviceState::ALL.len()],
            last_error: 0,
            last_exception: 0,
            consecutive_errors: 0,
            requests: index as u32,
            errors: 0,
            rounds: 1,
            overruns: 0,
            last_response_us: 800,
            since_last_error_ms: None,
            detail: "connection refused by 127.0.0.1:5502".to_owned(),
        }
    }

    /// A client of a fake runtime that answers `MODBUS_DEVICES` with `answer`, and the
    /// `from` of every request it got.
    async fn fake(
        answer: impl Fn(u8) -> Result<Response, Refusal> + Send + 'static,
    ) -> (Client, Arc<Mutex<Vec<u8>>>) {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let record = Arc::clone(&seen);
        let address = crate::fake_target::serve_requests(move |request| match request {
            Request::ModbusDevices { from } => {
                record.lock().unwrap().push(*from);
                answer(*from)
            }
            other => panic!("the fake runtime got {other:?}"),
        })
        .await;
        let (client, _) = Client::connect(address, None).await.unwrap();
        (client, seen)
    }

    #[tokio::test]
    async fn the_devices_are_asked_again_from_where_each_answer_ended_until_the_total() {
        let devices: Vec<ModbusDeviceReport> = (0..7).map(device).collect();
        let served = devices.clone();
        let (mut client, seen) = fake(move |from| Ok(modbus_devices_page(&served, from))).await;
        assert_eq!(client.modbus_devices().await.unwrap(), devices);
        // Entries of 101 bytes: two fit one answer of 250 bytes.
        assert_eq!(*seen.lock().unwrap(), [0, 2, 4, 6]);
    }

    #[tokio::test]
    async fn a_runtime_without_runtime_devices_is_asked_once() {
        let (mut client, seen) = fake(|from| Ok(modbus_devices_page(&[], from))).await;
        assert!(client.modbus_devices().await.unwrap().is_empty());
        assert_eq!(*seen.lock().unwrap(), [0]);
    }

    #[tokio::test]
    async fn an_empty_page_before_the_total_ends_the_list_instead_of_asking_forever() {
        let (mut client, seen) = fake(|from| {
            Ok(Response::ModbusDevices {
                total: 5,
                devices: if from == 0 {
                    vec![device(0)]
                } else {
                    Vec::new()
                },
            })
        })
        .await;
        assert_eq!(client.modbus_devices().await.unwrap(), [device(0)]);
        assert_eq!(*seen.lock().unwrap(), [0, 1]);
    }

    #[tokio::test]
    async fn an_older_runtime_s_unknown_service_is_an_error_of_its_own() {
        let (mut client, _) = fake(|_| {
            Err(Refusal::new(
                Status::UnknownService,
                "service 0x52 is unknown to protocol version 3",
            ))
        })
        .await;
        let error = client.modbus_devices().await.unwrap_err();
        assert!(
            matches!(error, OnlineError::ModbusDevicesNotReported),
            "{error:?}"
        );
        assert_eq!(
            error.to_string(),
            "this runtime does not report its Modbus devices"
        );
    }

    #[tokio::test]
    async fn another_refusal_keeps_the_runtime_s_words() {
        let (mut client, _) = fake(|_| Err(Refusal::bad("the frame is too short"))).await;
        let error = client.modbus_devices().await.unwrap_err();
        assert!(
            matches!(&error, OnlineError::Rejected(message) if message == "the frame is too short"),
            "{error:?}"
        );
    }
}

//! A download in progress: the image's bytes as chunks arrive, checked on commit.

use std::time::{Duration, Instant};

use program_image::{ImageHash, MAX_IMAGE_BYTES, ProgramImage};
use sha2::{Digest, Sha256};

use online_protocol::{CHUNK_BYTES, Refusal, Status};
/// How long a transfer lives without a chunk.
pub const TRANSFER_TIMEOUT: Duration = Duration::from_secs(30);

/// How long a transfer lives after an online change check, so the user can read what will
/// change before applying it (`docs/protocol.md` §7).
pub const CHECKED_TRANSFER_TIMEOUT: Duration = Duration::from_secs(300);

/// One transfer: lives from `DOWNLOAD_BEGIN` until its commit, its abort, a new begin or
/// [`TRANSFER_TIMEOUT`] without a chunk; never saved.
#[derive(Debug)]
pub struct Transfer {
    /// The transfer's number, as the client names it.
    pub id: u16,
    /// The Modbus connection that began it, whose closing drops it; `None` outside a server.
    pub owner: Option<u64>,
    /// Whether an online change check found the image valid: it then lives
    /// [`CHECKED_TRANSFER_TIMEOUT`].
    pub checked: bool,
    hash: ImageHash,
    bytes: Vec<u8>,
    /// Whether each byte has arrived.
    arrived: Vec<bool>,
    received: u32,
    last_chunk: Instant,
}

impl Transfer {
    /// A transfer of `size` bytes that must hash to `hash`.
    pub fn begin(id: u16, size: u32, hash: ImageHash, now: Instant) -> Result<Self, Refusal> {
        if size == 0 || size as usize > MAX_IMAGE_BYTES {
            return Err(Refusal::bad(format!(
                "an image of {size} bytes: 1 to {MAX_IMAGE_BYTES} expected"
            )));
        }
        Ok(Self {
            id,
            owner: None,
            checked: false,
            hash,
            bytes: vec![0; size as usize],
            arrived: vec![false; size as usize],
            received: 0,
            last_chunk: now,
        })
    }

    /// Whether the transfer has gone [`TRANSFER_TIMEOUT`] without a chunk at `now`.
    pub fn expired(&self, now: Instant) -> bool {
        let timeout = if self.checked {
            CHECKED_TRANSFER_TIMEOUT
        } else {
            TRANSFER_TIMEOUT
        };
        now.saturating_duration_since(self.last_chunk) > timeout
    }

    /// Writes `chunk` at `offset` and returns how many distinct bytes have arrived.
    pub fn chunk(&mut self, offset: u32, chunk: &[u8], now: Instant) -> Result<u32, Refusal> {
        if chunk.len() > usize::from(CHUNK_BYTES) {
            return Err(Refusal::bad(format!(
                "a chunk of {} bytes: at most {CHUNK_BYTES} expected",
                chunk.len()
            )));
        }
        let start = offset as usize;
        let end = start + chunk.len();
        if end > self.bytes.len() {
            return Err(Refusal::bad(format!(
                "a chunk ending at byte {end} of an image of {} bytes",
                self.bytes.len()
            )));
        }
        self.bytes[start..end].copy_from_slice(chunk);
        for arrived in &mut self.arrived[start..end] {
            if !*arrived {
                *arrived = true;
                self.received += 1;
            }
        }
        self.last_chunk = now;
        Ok(self.received)
    }

    /// The image, if every byte arrived, the bytes hash to the announced hash and they decode.
    pub fn finish(self) -> Result<ProgramImage, Refusal> {
        self.image()
    }

    /// The image, checked as [`Transfer::finish`] checks it, keeping the transfer (an online
    /// change check leaves it open for the apply or a commit).
    pub fn image(&self) -> Result<ProgramImage, Refusal> {
        let refuse = |message: String| Refusal {
            status: Status::ImageRefused,
            message,
        };
        if self.received as usize != self.bytes.len() {
            return Err(refuse(format!(
                "the image is incomplete: {} of {} bytes arrived",
                self.received,
                self.bytes.len()
            )));
        }
        let hash: ImageHash = Sha256::digest(&self.bytes).into();
        if hash != self.hash {
            return Err(refuse(
                "the image's bytes do not hash to the announced SHA-256".to_owned(),
            ));
        }
        ProgramImage::decode(&self.bytes)
            .map_err(|error| refuse(format!("the bytes are not a valid program image: {error}")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hash(bytes: &[u8]) -> ImageHash {
        Sha256::digest(bytes).into()
    }

    #[test]
    fn a_transfer_counts_resent_bytes_once_and_refuses_what_is_incomplete_or_corrupted() {
        let now = Instant::now();
        let bytes = [7u8; 300];
        let mut transfer = Transfer::begin(1, 300, hash(&bytes), now).unwrap();
        assert_eq!(transfer.chunk(0, &bytes[..200], now).unwrap(), 200);
        assert_eq!(transfer.chunk(100, &bytes[100..200], now).unwrap(), 200);
        assert_eq!(
            transfer.chunk(250, &bytes[..60], now).unwrap_err().status,
            Status::BadRequest
        );
        let refusal = transfer.finish().unwrap_err();
        assert_eq!(refusal.status, Status::ImageRefused);
        assert!(
            refusal.message.contains("incomplete"),
            "{}",
            refusal.message
        );

        let mut transfer = Transfer::begin(2, 300, hash(&bytes), now).unwrap();
        transfer.chunk(0, &bytes[..200], now).unwrap();
        transfer.chunk(200, &[8; 100], now).unwrap();
        let refusal = transfer.finish().unwrap_err();
        assert!(refusal.message.contains("SHA-256"), "{}", refusal.message);

        let mut transfer = Transfer::begin(3, 300, hash(&bytes), now).unwrap();
        transfer.chunk(0, &bytes[..200], now).unwrap();
        transfer.chunk(200, &bytes[200..], now).unwrap();
        let refusal = transfer.finish().unwrap_err();
        assert!(
            refusal.message.contains("not a valid"),
            "{}",
            refusal.message
        );
        assert!(transfer_is_refused_when_empty());
    }

    fn transfer_is_refused_when_empty() -> bool {
        Transfer::begin(4, 0, [0; 32], Instant::now()).is_err()
    }

    #[test]
    fn a_transfer_expires_after_its_timeout_without_a_chunk() {
        let now = Instant::now();
        let transfer = Transfer::begin(1, 10, [0; 32], now).unwrap();
        assert!(!transfer.expired(now + TRANSFER_TIMEOUT));
        assert!(transfer.expired(now + TRANSFER_TIMEOUT + Duration::from_millis(1)));
    }
}

//! The transport a serial line gives tokio-modbus's RTU client (`docs/modbus-master.md` §6.9):
//! the serial stream, with what that client lacks. It notes when the last byte went either way,
//! so the line can keep the inter-frame silence before each request, and it drops the input
//! that arrived unasked (a late answer, noise after a timeout) when the line says so; and when
//! tokio-modbus's client is dropped it hands the stream back, so the line can give a new client
//! the same open port.

use std::pin::Pin;
use std::sync::{Arc, Mutex, PoisonError};
use std::task::{Context, Poll};
use std::time::Instant;

use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};

/// What the line and its transport share.
#[derive(Debug)]
pub struct LineActivity {
    /// When the last byte was sent or received.
    last_byte: Mutex<Instant>,
    /// Whether the input that is waiting is to be dropped before the next read or write.
    discard: Mutex<bool>,
}

impl LineActivity {
    /// A line whose last byte is now.
    pub fn new() -> Arc<Self> {
        Arc::new(Self {
            last_byte: Mutex::new(Instant::now()),
            discard: Mutex::new(false),
        })
    }

    /// When the last byte went either way (or the line noted a timeout).
    pub fn last_byte(&self) -> Instant {
        *self
            .last_byte
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }

    /// Notes activity now: a byte, or a timeout, from which the silence is counted.
    pub fn touch(&self) {
        *self
            .last_byte
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Instant::now();
    }

    /// Asks the transport to drop the input waiting now, before its next read or write.
    pub fn discard_input(&self) {
        *self.discard.lock().unwrap_or_else(PoisonError::into_inner) = true;
    }

    fn take_discard(&self) -> bool {
        std::mem::take(&mut *self.discard.lock().unwrap_or_else(PoisonError::into_inner))
    }
}

/// Where a dropped [`LinePort`] leaves its stream.
pub type StreamSlot<T> = Arc<Mutex<Option<T>>>;

/// A serial stream (or any byte stream, in tests) as the line's transport.
#[derive(Debug)]
pub struct LinePort<T> {
    /// The stream; taken out only when the port is dropped.
    inner: Option<T>,
    /// What the line and the port share.
    activity: Arc<LineActivity>,
    /// Where the stream goes when the port is dropped.
    returned: StreamSlot<T>,
}

impl<T: AsyncRead + Unpin> LinePort<T> {
    /// Wraps `inner`, reporting to `activity`; dropped, it leaves `inner` in `returned`.
    pub fn new(inner: T, activity: Arc<LineActivity>, returned: StreamSlot<T>) -> Self {
        Self {
            inner: Some(inner),
            activity,
            returned,
        }
    }

    /// The stream (always there until the port is dropped).
    fn stream(&mut self) -> std::io::Result<Pin<&mut T>> {
        self.inner
            .as_mut()
            .map(Pin::new)
            .ok_or_else(|| std::io::Error::from(std::io::ErrorKind::NotConnected))
    }

    /// Reads and drops every byte that is ready now, when the line asked for it.
    fn discard_if_asked(&mut self, context: &mut Context<'_>) {
        if !self.activity.take_discard() {
            return;
        }
        let Some(inner) = self.inner.as_mut() else {
            return;
        };
        let mut scratch = [0u8; 256];
        loop {
            let mut buffer = ReadBuf::new(&mut scratch);
            match Pin::new(&mut *inner).poll_read(context, &mut buffer) {
                Poll::Ready(Ok(())) if !buffer.filled().is_empty() => {}
                // Nothing more now, the end of the stream, or an error: the next read sees it.
                _ => return,
            }
        }
    }
}

impl<T: AsyncRead + Unpin> AsyncRead for LinePort<T> {
    fn poll_read(
        mut self: Pin<&mut Self>,
        context: &mut Context<'_>,
        buffer: &mut ReadBuf<'_>,
    ) -> Poll<std::io::Result<()>> {
        self.discard_if_asked(context);
        let before = buffer.filled().len();
        let result = match self.stream() {
            Ok(stream) => stream.poll_read(context, buffer),
            Err(error) => Poll::Ready(Err(error)),
        };
        if matches!(result, Poll::Ready(Ok(()))) && buffer.filled().len() > before {
            self.activity.touch();
        }
        result
    }
}

impl<T: AsyncRead + AsyncWrite + Unpin> AsyncWrite for LinePort<T> {
    fn poll_write(
        mut self: Pin<&mut Self>,
        context: &mut Context<'_>,
        bytes: &[u8],
    ) -> Poll<std::io::Result<usize>> {
        self.discard_if_asked(context);
        let result = match self.stream() {
            Ok(stream) => stream.poll_write(context, bytes),
            Err(error) => Poll::Ready(Err(error)),
        };
        if matches!(result, Poll::Ready(Ok(written)) if written > 0) {
            self.activity.touch();
        }
        result
    }

    fn poll_flush(
        mut self: Pin<&mut Self>,
        context: &mut Context<'_>,
    ) -> Poll<std::io::Result<()>> {
        match self.stream() {
            Ok(stream) => stream.poll_flush(context),
            Err(error) => Poll::Ready(Err(error)),
        }
    }

    fn poll_shutdown(
        mut self: Pin<&mut Self>,
        context: &mut Context<'_>,
    ) -> Poll<std::io::Result<()>> {
        match self.stream() {
            Ok(stream) => stream.poll_shutdown(context),
            Err(error) => Poll::Ready(Err(error)),
        }
    }
}

impl<T> Drop for LinePort<T> {
    fn drop(&mut self) {
        if let Some(inner) = self.inner.take() {
            *self.returned.lock().unwrap_or_else(PoisonError::into_inner) = Some(inner);
        }
    }
}

#[cfg(test)]
mod tests {
    use tokio::io::{AsyncReadExt, AsyncWriteExt};

    use super::*;

    #[tokio::test]
    async fn unasked_input_is_dropped_on_request_and_bytes_are_noted() {
        let (ours, mut theirs) = tokio::io::duplex(64);
        let activity = LineActivity::new();
        let returned = StreamSlot::default();
        let mut port = LinePort::new(ours, Arc::clone(&activity), Arc::clone(&returned));
        let start = activity.last_byte();
        // A late answer arrives; the line drops it before its next request.
        theirs.write_all(&[1, 2, 3]).await.unwrap();
        tokio::task::yield_now().await;
        activity.discard_input();
        port.write_all(&[9]).await.unwrap();
        assert!(activity.last_byte() >= start);
        let mut sent = [0u8; 1];
        theirs.read_exact(&mut sent).await.unwrap();
        assert_eq!(sent, [9]);
        // The answer to the request is read whole; the late one is gone.
        theirs.write_all(&[7, 8]).await.unwrap();
        let mut answer = [0u8; 2];
        port.read_exact(&mut answer).await.unwrap();
        assert_eq!(answer, [7, 8]);
        // Without a request to drop, nothing is dropped.
        theirs.write_all(&[5]).await.unwrap();
        port.write_all(&[6]).await.unwrap();
        let mut kept = [0u8; 1];
        port.read_exact(&mut kept).await.unwrap();
        assert_eq!(kept, [5]);
        // Dropped, the port hands its stream back, still connected.
        drop(port);
        let mut stream = returned.lock().unwrap().take().unwrap();
        theirs.write_all(&[4]).await.unwrap();
        let mut again = [0u8; 1];
        stream.read_exact(&mut again).await.unwrap();
        assert_eq!(again, [4]);
    }
}

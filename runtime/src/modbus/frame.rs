//! The MBAP header that frames each PDU on a Modbus TCP connection.

use crate::modbus::pdu::MAX_PDU_BYTES;

/// Bytes of the MBAP header: transaction id, protocol id, length, unit id.
pub const HEADER_BYTES: usize = 7;

/// A request's MBAP header, checked: the protocol is Modbus and the PDU fits one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MbapHeader {
    /// Chosen by the client and echoed in the response.
    pub transaction_id: u16,
    /// The unit (slave) addressed; echoed, not checked.
    pub unit_id: u8,
    /// Bytes of PDU that follow the header, 1 to [`MAX_PDU_BYTES`].
    pub pdu_bytes: usize,
}

/// Why a header cannot start a frame; the connection cannot be trusted to stay in step after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// The protocol identifier is not 0 (Modbus).
    #[error("protocol identifier {0} in an MBAP header; expected 0 (Modbus)")]
    Protocol(u16),
    /// The length field does not allow a PDU of 1 to 253 bytes.
    #[error("length {0} in an MBAP header; expected 2 to 254 (unit id and PDU)")]
    Length(u16),
}

impl MbapHeader {
    /// Reads and checks a header.
    pub fn parse(bytes: [u8; HEADER_BYTES]) -> Result<Self, FrameError> {
        let protocol_id = u16::from_be_bytes([bytes[2], bytes[3]]);
        if protocol_id != 0 {
            return Err(FrameError::Protocol(protocol_id));
        }
        let length = u16::from_be_bytes([bytes[4], bytes[5]]);
        let pdu_bytes = usize::from(length).saturating_sub(1);
        if !(1..=MAX_PDU_BYTES).contains(&pdu_bytes) {
            return Err(FrameError::Length(length));
        }
        Ok(Self {
            transaction_id: u16::from_be_bytes([bytes[0], bytes[1]]),
            unit_id: bytes[6],
            pdu_bytes,
        })
    }

    /// The whole frame answering this request with the response PDU `pdu` (at most
    /// [`MAX_PDU_BYTES`] long).
    pub fn response_frame(&self, pdu: &[u8]) -> Vec<u8> {
        let length = u16::try_from(pdu.len() + 1).unwrap_or(u16::MAX);
        let mut frame = Vec::with_capacity(HEADER_BYTES + pdu.len());
        frame.extend_from_slice(&self.transaction_id.to_be_bytes());
        frame.extend_from_slice(&[0, 0]);
        frame.extend_from_slice(&length.to_be_bytes());
        frame.push(self.unit_id);
        frame.extend_from_slice(pdu);
        frame
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_gives_the_pdu_length_without_the_unit_id() {
        let header = MbapHeader::parse([0x12, 0x34, 0, 0, 0, 6, 9]).unwrap();
        assert_eq!(
            header,
            MbapHeader {
                transaction_id: 0x1234,
                unit_id: 9,
                pdu_bytes: 5
            }
        );
        assert_eq!(
            header.response_frame(&[3, 2, 0, 7]),
            [0x12, 0x34, 0, 0, 0, 5, 9, 3, 2, 0, 7]
        );
    }

    #[test]
    fn headers_that_cannot_frame_a_pdu_are_refused() {
        let with_length = |length: u16| {
            let [high, low] = length.to_be_bytes();
            MbapHeader::parse([0, 1, 0, 0, high, low, 1])
        };
        assert_eq!(with_length(0), Err(FrameError::Length(0)));
        assert_eq!(with_length(1), Err(FrameError::Length(1)));
        assert_eq!(with_length(255), Err(FrameError::Length(255)));
        assert_eq!(with_length(65535), Err(FrameError::Length(65535)));
        assert_eq!(with_length(254).map(|header| header.pdu_bytes), Ok(253));
        assert_eq!(
            MbapHeader::parse([0, 1, 0x12, 0x34, 0, 6, 1]),
            Err(FrameError::Protocol(0x1234))
        );
        assert_eq!(
            FrameError::Length(0).to_string(),
            "length 0 in an MBAP header; expected 2 to 254 (unit id and PDU)"
        );
    }
}

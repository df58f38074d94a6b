//! The exception codes the server answers with.

/// A Modbus exception code, sent back as `function + 0x80` followed by the code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ExceptionCode {
    /// 1: the function code is not served.
    IllegalFunction,
    /// 2: an address of the request is not mapped, or its bytes do not exist.
    IllegalDataAddress,
    /// 3: a quantity, byte count, coil value or request length is wrong.
    IllegalDataValue,
    /// 4: the server could not do what was asked (for example, the areas could not be locked).
    ServerDeviceFailure,
}

impl ExceptionCode {
    /// The code as it travels in the exception response.
    pub fn code(self) -> u8 {
        match self {
            ExceptionCode::IllegalFunction => 1,
            ExceptionCode::IllegalDataAddress => 2,
            ExceptionCode::IllegalDataValue => 3,
            ExceptionCode::ServerDeviceFailure => 4,
        }
    }

    /// The exception response PDU to a request with function code `function`.
    pub fn response(self, function: u8) -> Vec<u8> {
        vec![function | 0x80, self.code()]
    }
}

impl std::fmt::Display for ExceptionCode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let name = match self {
            ExceptionCode::IllegalFunction => "illegal function",
            ExceptionCode::IllegalDataAddress => "illegal data address",
            ExceptionCode::IllegalDataValue => "illegal data value",
            ExceptionCode::ServerDeviceFailure => "server device failure",
        };
        write!(f, "exception {} ({name})", self.code())
    }
}

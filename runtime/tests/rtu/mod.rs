//! Modbus RTU over socat's virtual serial cables (`peers::SocatPair`, 8N1 and 8N2: this
//! machine's pseudo-terminals refuse parity): the runtime's serial ports, and
//! `rivet-runtime --modbus-rtu` as a slave to mbpoll (`docs/modbus-master.md` §7, §10 test 4).

mod serial_ports;

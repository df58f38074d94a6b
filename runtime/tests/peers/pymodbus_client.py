"""pymodbus as an independent Modbus TCP client of the Rivet runtime.

Usage: pymodbus_client.py HOST PORT

runtime/tests/modbus_server.rs presets the areas, runs this script against its server and
compares what it prints and writes. Addresses are PDU addresses (0-based), as pymodbus's
client uses them. The calls avoid the unit keyword, which pymodbus renamed between 3.0
(Debian 12's python3-pymodbus) and later releases.
"""

import sys

from pymodbus.client import ModbusTcpClient


def checked(response, what):
    if response.isError():
        sys.exit(f"{what} failed: {response}")
    return response


def main():
    host, port = sys.argv[1], int(sys.argv[2])
    client = ModbusTcpClient(host, port=port, timeout=5)
    if not client.connect():
        sys.exit(f"cannot connect to {host}:{port}")

    words = checked(client.read_holding_registers(1024, count=2), "reading %MW0..1")
    print(f"%MW0..1 {words.registers}")

    # %MD6 is holding registers 2060 and 2061, high word first as in OpenPLC.
    high, low = checked(client.read_holding_registers(2060, count=2), "reading %MD6").registers
    print(f"%MD6 {(high << 16) | low:#x}")
    # %MD5 := 16#12345678 through holding registers 2058 and 2059.
    checked(client.write_registers(2058, [0x1234, 0x5678]), "writing %MD5")

    checked(client.write_coils(0, [True, False, True, True]), "writing %QX0.0..3")
    coils = checked(client.read_coils(8, count=3), "reading %QX1.0..2")
    print(f"%QX1.0..2 {coils.bits[:3]}")
    inputs = checked(client.read_discrete_inputs(0, count=4), "reading %IX0.0..3")
    print(f"%IX0.0..3 {inputs.bits[:4]}")
    registers = checked(client.read_input_registers(0, count=2), "reading %IW0..1")
    print(f"%IW0..1 {registers.registers}")

    checked(client.write_register(5, 777), "writing %QW5")
    checked(client.write_register(1026, 3333), "writing %MW2")

    unmapped = client.read_holding_registers(9000, count=1)
    if not unmapped.isError():
        sys.exit(f"reading holding register 9000 should fail, got {unmapped}")
    print(f"unmapped exception {unmapped.exception_code}")
    client.close()


if __name__ == "__main__":
    main()

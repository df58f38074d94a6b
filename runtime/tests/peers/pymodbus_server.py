"""pymodbus as an independent Modbus slave (server) for the runtime's Modbus master tests.

Usage:
    pymodbus_server.py tcp [PORT]
    pymodbus_server.py rtu PATH BAUD PARITY STOPBITS [UNITS]

`tcp` serves Modbus TCP on 127.0.0.1, on PORT or (without it, or with 0) a port the system
picks, and prints `port N` once it listens; it answers every unit id from the same tables.
The tests always let the system pick: one that stops the server and starts it again gets a
new port and keeps the master's address with the fault proxy in front
(`tests/src/fault_proxy.rs`), since a port freed and bound again could be taken meanwhile.
PORT is for a person trying a project at the desk (the README's "try it"), whose device names
a fixed port. `rtu` serves Modbus RTU on the serial port PATH (a socat
pseudo-terminal in the tests) with BAUD, PARITY (N, E or O) and STOPBITS (1 or 2), 8 data bits, as the units listed in UNITS (comma-separated, default 1), each with
tables of its own, and prints `ready` once the port is open; it opens the port again when it
goes away (socat killed and started again). A port that cannot be bound or opened at the
start, or a server that fails, ends the script with status 1 and the reason on standard error.

Every unit has coils (co), discrete inputs (di), holding registers (hr) and input registers
(ir) at addresses 0 to 999 (PDU addresses, 0-based: the datastores use zero_mode, without which
pymodbus shifts every address by one), all 0 at the start; any other address is answered with
exception 2.

Commands on standard input, one a line, each answered with one line on standard output:

    get TABLE ADDRESS          -> value N
    set TABLE ADDRESS VALUE    -> ok
    delay MS                   -> ok     (answer every later request MS milliseconds late)
    exceptions on|off          -> ok     (answer every later request with exception 2)

TABLE is co, di, hr or ir for unit 1, or UNIT.TABLE (`2.hr`) for another unit of an RTU server.
A command that cannot be understood is answered `error` with the reason. The server ends at the
end of its standard input, so a test that drops its handle ends it.

Written for pymodbus 3.0 (Debian 12's python3-pymodbus, seen by /usr/bin/python3).
"""

import asyncio
import os
import sys
import threading
import time

from pymodbus.datastore import (
    ModbusSequentialDataBlock,
    ModbusServerContext,
    ModbusSlaveContext,
)
from pymodbus.framer.rtu_framer import ModbusRtuFramer
from pymodbus.server.async_io import ModbusSerialServer, ModbusTcpServer

# Addresses 0 to 999 of every table exist.
TABLE_SIZE = 1000


class Behaviour:
    """What the test has asked of the whole server; read by every data block."""

    delay_s = 0.0
    exceptions = False


class TestBlock(ModbusSequentialDataBlock):
    """A data block that answers late or refuses as the test asks.

    The delay blocks the server's event loop, which is what a slow device does: it answers
    nothing else meanwhile.
    """

    def validate(self, address, count=1):
        if Behaviour.exceptions:
            return False
        return super().validate(address, count)

    def getValues(self, address, count=1):
        if Behaviour.delay_s:
            time.sleep(Behaviour.delay_s)
        return super().getValues(address, count)

    def setValues(self, address, values):
        if Behaviour.delay_s:
            time.sleep(Behaviour.delay_s)
        super().setValues(address, values)


def unit_context():
    def block():
        return TestBlock(0, [0] * TABLE_SIZE)

    return ModbusSlaveContext(di=block(), co=block(), hr=block(), ir=block(), zero_mode=True)


# pymodbus's function codes for reading each table, which select the block.
READ_FUNCTION = {"co": 1, "di": 2, "hr": 3, "ir": 4}


def answer(units, line):
    """The answer to one command line."""
    line = line.strip()
    words = line.split()
    if not words:
        return "error empty command"
    command, arguments = words[0], words[1:]
    if command == "delay" and len(arguments) == 1:
        Behaviour.delay_s = int(arguments[0]) / 1000
        return "ok"
    if command == "exceptions" and arguments in (["on"], ["off"]):
        Behaviour.exceptions = arguments[0] == "on"
        return "ok"
    if command in ("get", "set") and len(arguments) == (2 if command == "get" else 3):
        unit, _, table = arguments[0].rpartition(".")
        unit = int(unit) if unit else 1
        if unit not in units or table not in READ_FUNCTION:
            return f"error no table {arguments[0]}"
        address = int(arguments[1])
        if not 0 <= address < TABLE_SIZE:
            return f"error address {address} is not in 0-{TABLE_SIZE - 1}"
        # The blocks themselves, so that a delay or exceptions do not touch the test's own view.
        store = units[unit].store[units[unit].decode(READ_FUNCTION[table])]
        if command == "get":
            return f"value {ModbusSequentialDataBlock.getValues(store, address, 1)[0]}"
        value = int(arguments[2])
        ModbusSequentialDataBlock.setValues(store, address, [value])
        return "ok"
    return f"error unknown command {line!r}"


def serve_commands(units):
    """Answers standard input's commands until its end, then ends the process."""
    for line in sys.stdin:
        try:
            reply = answer(units, line)
        except ValueError as error:
            reply = f"error {error}"
        print(reply, flush=True)
    os._exit(0)


def fail(reason):
    """Ends the process with status 1 after saying `reason` on standard error, for the test."""
    print(f"pymodbus_server.py: {reason}", file=sys.stderr, flush=True)
    os._exit(1)


async def serve_tcp(port):
    unit = unit_context()
    # A person who stops the script and starts it again on the same fixed port finds the old
    # connections in TIME_WAIT: without SO_REUSEADDR that bind fails for a minute.
    server = ModbusTcpServer(
        ModbusServerContext(slaves=unit, single=True),
        address=("127.0.0.1", port),
        allow_reuse_address=True,
    )
    task = asyncio.create_task(server.serve_forever())
    while server.server is None:
        if task.done():
            # The bind failed: serve_forever raised before it set server.server.
            error = task.exception() if not task.cancelled() else "cancelled"
            fail(f"cannot serve Modbus TCP on 127.0.0.1:{port}: {error}")
        await asyncio.sleep(0.01)
    print(f"port {server.server.sockets[0].getsockname()[1]}", flush=True)
    threading.Thread(target=serve_commands, args=({1: unit},), daemon=True).start()
    try:
        await task
    except Exception as error:  # pylint: disable=broad-except
        fail(f"the Modbus TCP server failed: {error!r}")
    fail("the Modbus TCP server stopped")


async def serve_rtu(path, baud, parity, stop_bits, unit_ids):
    units = {unit_id: unit_context() for unit_id in unit_ids}
    server = ModbusSerialServer(
        ModbusServerContext(slaves=units, single=False),
        ModbusRtuFramer,
        port=path,
        baudrate=baud,
        bytesize=8,
        parity=parity,
        stopbits=stop_bits,
        timeout=0.05,
        auto_reconnect=True,
        reconnect_delay=0.1,
    )
    await server.start()
    # With auto_reconnect, pymodbus swallows a failed open and tries again later; at the start
    # the port must open, or the test would talk to nobody.
    if server.transport is None:
        fail(f"cannot open the serial port {path}")
    print("ready", flush=True)
    threading.Thread(target=serve_commands, args=(units,), daemon=True).start()
    try:
        await server.serve_forever()
    except Exception as error:  # pylint: disable=broad-except
        fail(f"the Modbus RTU server failed: {error!r}")


def main():
    mode = sys.argv[1:2]
    if mode == ["tcp"] and len(sys.argv) in (2, 3):
        asyncio.run(serve_tcp(int(sys.argv[2]) if len(sys.argv) == 3 else 0))
    elif mode == ["rtu"] and len(sys.argv) in (6, 7):
        path, baud, parity, stop_bits = sys.argv[2], int(sys.argv[3]), sys.argv[4], int(sys.argv[5])
        unit_ids = [int(unit) for unit in (sys.argv[6] if len(sys.argv) == 7 else "1").split(",")]
        asyncio.run(serve_rtu(path, baud, parity, stop_bits, unit_ids))
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()

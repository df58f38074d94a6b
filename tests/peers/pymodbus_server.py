"""A pymodbus TCP server on 127.0.0.1 at the port given as the only argument, with 200 coils,
discrete inputs, holding and input registers from address 0: an independent third-party
Modbus device for Rivet's tests."""

import sys

from pymodbus.datastore import (
    ModbusSequentialDataBlock,
    ModbusServerContext,
    ModbusSlaveContext,
)
from pymodbus.server import StartTcpServer


def block():
    return ModbusSequentialDataBlock(0, [0] * 200)


port = int(sys.argv[1])
store = ModbusSlaveContext(di=block(), co=block(), hr=block(), ir=block(), zero_mode=True)
context = ModbusServerContext(slaves=store, single=True)
StartTcpServer(context=context, address=("127.0.0.1", port))

"""A stand-in for bleak, for tests: BleakClient records what is written as JSON
lines in $FAKE_BLEAK_LOG and, once the status period is set (0x32), plays the
notifications in $FAKE_BLEAK_NOTIFY (hex frames separated by commas)."""
import asyncio
import json
import os


def _log(*entry):
    with open(os.environ["FAKE_BLEAK_LOG"], "a") as f:
        f.write(json.dumps(list(entry)) + "\n")


class BleakClient:
    def __init__(self, address):
        self.address = address
        self.callbacks = {}

    async def __aenter__(self):
        _log("connect", self.address)
        return self

    async def __aexit__(self, *exc):
        _log("disconnect")
        return False

    async def start_notify(self, characteristic, callback):
        _log("start_notify", characteristic)
        self.callbacks[characteristic] = callback

    async def stop_notify(self, characteristic):
        _log("stop_notify", characteristic)
        del self.callbacks[characteristic]

    async def write_gatt_char(self, characteristic, data, response=False):
        _log("write", characteristic, bytes(data).hex(), response)
        if data[:1] == b"\x32" and characteristic in self.callbacks:
            loop = asyncio.get_running_loop()
            for frame in os.environ.get("FAKE_BLEAK_NOTIFY", "").split(","):
                if frame:
                    loop.call_soon(self.callbacks[characteristic], characteristic, bytearray.fromhex(frame))

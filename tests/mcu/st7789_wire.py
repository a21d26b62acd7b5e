#!/usr/bin/env python3
"""The ST7789 image's wire, read back: qemu's log of the GPIO stores (-d unimp: the mps2-an385's
GPIO block is not emulated, so every store to DATAOUT is logged with the levels of every output
pin, platform/mcu/hal_mps2.cpp) decoded as the panel would take it, SPI mode 0 on pins 0 (clock)
and 1 (data), D/C on pin 2, chip select on pin 3 (boards/mcu-st7789.hpp). Writes the first frame
sent after RAMWR as the canvas's bytes (RGB565 little-endian, 240 rows of 480) and stops.

    st7789_wire.py LOG OUT.rgb565      (LOG may be a FIFO qemu writes to; tests/mcu/run)

Prints the command bytes up to that frame on stderr. Exit 0 with the frame, 1 without."""
import re
import sys

FRAME = 240 * 240 * 2
store = re.compile(r"offset 0x004, value 0x([0-9a-f]+)")


def main(log, out):
    previous, bits, count = 0, 0, 0
    commands, frame, in_frame = [], bytearray(), False
    with open(log, encoding="ascii", errors="replace") as f:
        for line in f:
            m = store.search(line)
            if not m:
                continue
            v = int(m.group(1), 16)
            rising = (v & 1) and not (previous & 1)
            previous = v
            if not rising or v & 8:  # a bit is taken on the clock's rise while CS is low
                continue
            bits, count = (bits << 1) | ((v >> 1) & 1), count + 1
            if count < 8:
                continue
            byte, bits, count = bits, 0, 0
            if not v & 4:  # D/C low: a command
                commands.append(byte)
                in_frame = byte == 0x2C
                frame.clear()
            elif in_frame:
                frame.append(byte)
                if len(frame) == FRAME:
                    break
    print("st7789 commands: " + " ".join("%02x" % c for c in commands), file=sys.stderr)
    if len(frame) != FRAME:
        print("st7789_wire: no whole frame on the wire (%d bytes after RAMWR)." % len(frame), file=sys.stderr)
        return 1
    swapped = bytearray(FRAME)
    swapped[0::2], swapped[1::2] = frame[1::2], frame[0::2]  # high byte first on the wire
    with open(out, "wb") as f:
        f.write(swapped)
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print("usage: st7789_wire.py LOG OUT.rgb565", file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))

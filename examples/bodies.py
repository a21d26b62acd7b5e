#!/usr/bin/env python3
"""The C interface from Python through ctypes (docs/library.md): a built-in scene run for some
frames, its bodies printed as JSON, one a line. tests/library compares them with the last line
of `noneuclid dump` for the same scene and frames.

    python3 bodies.py LIBNONEUCLID.SO SCENE FRAMES
"""
import ctypes
import json
import sys


class Body(ctypes.Structure):
    """noneuclid.h's nw_body."""
    _fields_ = [("name", ctypes.c_char * 64), ("kind", ctypes.c_char * 16), ("r", ctypes.c_double),
                ("theta", ctypes.c_double), ("facing", ctypes.c_double), ("speed", ctypes.c_double),
                ("travel", ctypes.c_double), ("vertices", ctypes.c_int)]


def load(path):
    """The library, with the argument and result types of the functions used here."""
    nw = ctypes.CDLL(path)
    world_p = ctypes.c_void_p
    nw.nw_version.restype = ctypes.c_char_p
    nw.nw_last_error.restype = ctypes.c_char_p
    nw.nw_world_from_name.argtypes = [ctypes.c_char_p, ctypes.c_char_p, ctypes.POINTER(world_p)]
    nw.nw_world_free.argtypes = [world_p]
    nw.nw_world_free.restype = None
    nw.nw_step.argtypes = [world_p, ctypes.c_long]
    nw.nw_body_count.argtypes = [world_p, ctypes.POINTER(ctypes.c_int)]
    nw.nw_body_at.argtypes = [world_p, ctypes.c_int, ctypes.POINTER(Body)]
    return nw


def check(nw, status):
    """Raises with the library's sentence when a call fails (status is not NW_OK, 0)."""
    if status != 0:
        raise RuntimeError(nw.nw_last_error().decode())


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: bodies.py LIBNONEUCLID.SO SCENE FRAMES")
    nw = load(sys.argv[1])
    world = ctypes.c_void_p()
    check(nw, nw.nw_world_from_name(sys.argv[2].encode(), None, ctypes.byref(world)))
    try:
        check(nw, nw.nw_step(world, int(sys.argv[3])))
        count = ctypes.c_int()
        check(nw, nw.nw_body_count(world, ctypes.byref(count)))
        for i in range(count.value):
            b = Body()
            check(nw, nw.nw_body_at(world, i, ctypes.byref(b)))
            print(json.dumps({"name": b.name.decode(), "kind": b.kind.decode(), "center": [b.r, b.theta],
                              "facing": b.facing}))
    finally:
        nw.nw_world_free(world)


if __name__ == "__main__":
    main()

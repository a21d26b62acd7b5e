#!/usr/bin/env python3
"""The library's examples run and checked against references of their own (tests/library,
docs/library.md). One check a call:

    check_examples.py picture|c|sphere|game|python|outside BUILD SOURCE WORK [FLAGS]

BUILD is the build tree (noneuclid, png_diff, the examples, libnoneuclid.so), SOURCE the source
tree, WORK a scratch directory of the check's own. Exit 0 if the check holds, 1 with what
differed otherwise.
"""
import json
import math
import os
import shutil
import subprocess
import sys


def run(*args, **kw):
    """The command's standard output; a failure ends the check with its output."""
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.exit(f"{' '.join(map(str, args))} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
    return r.stdout


def same_pictures(build, ours, theirs):
    """png_diff --exact: the two pictures have every pixel alike."""
    print(run(f"{build}/png_diff", ours, theirs, "--exact"), end="")


def check_picture(build, source, work):
    """example_picture's PPM is `noneuclid render`'s PNG of the same scene, frames and size."""
    run(f"{build}/example_picture", "kiosk", 45, "320x240", f"{work}/picture.ppm")
    run(f"{build}/noneuclid", "render", "--scene", "kiosk", "--frames", 45, "--size", "320x240",
        "--out", f"{work}/picture.png")
    same_pictures(build, f"{work}/picture.ppm", f"{work}/picture.png")


def check_c(build, source, work):
    """example_c, through noneuclid.h: a scene file's text drawn in rgb565 is render's picture of
    that file in rgb565; its body lines name the scene's bodies."""
    scene = f"{source}/tests/files/data/lesson.toml"
    out = run(f"{build}/example_c", scene, 30, "300x200", "rgb565", f"{work}/c.ppm")
    run(f"{build}/noneuclid", "render", "--scene", scene, "--frames", 30, "--size", "300x200", "--format", "rgb565",
        "--out", f"{work}/c.png")
    same_pictures(build, f"{work}/c.ppm", f"{work}/c.png")
    for name in ("ship (ship)", "square (body)"):
        if name not in out:
            sys.exit(f"example_c printed no body '{name}':\n{out}")


def sphere_distance(t, r, theta_deg, r0=1.0, speed=0.5):
    """The angle on the unit sphere between the centre printed and the great circle's closed
    form: from (r0, 0) at right angles to the x axis, p(t) = p0 cos(vt) + e_y sin(vt), with
    p0 = (sin r0, 0, cos r0) and O the pole (0, 0, 1)."""
    s = speed * t
    want = (math.sin(r0) * math.cos(s), math.sin(s), math.cos(r0) * math.cos(s))
    th = math.radians(theta_deg)
    got = (math.sin(r) * math.cos(th), math.sin(r) * math.sin(th), math.cos(r))
    dot = sum(a * b for a, b in zip(want, got))
    cross = (want[1] * got[2] - want[2] * got[1], want[2] * got[0] - want[0] * got[2],
             want[0] * got[1] - want[1] * got[0])
    return math.atan2(math.sqrt(sum(c * c for c in cross)), dot)


def check_sphere(build, source, work):
    """example_sphere's body on the great circle's closed form, 41 times over 40 s (20 units: three
    times round): within 1e-8 in double and 1e-3 in fixed point, the bounds tests/world/test_coast.cpp
    holds coasting bodies to (docs/accuracy.md); and it reaches the circle's farthest point from O,
    pi - 1 (the closed form's z = -cos 1), within 0.01 (a second's step there moves r by less)."""
    for engine, bound in (("double", 1e-8), ("fixed", 1e-3)):
        lines = run(f"{build}/example_sphere", engine, 40).split()
        rows = [tuple(map(float, lines[i:i + 3])) for i in range(0, len(lines), 3)]
        if len(rows) != 41:
            sys.exit(f"example_sphere {engine} printed {len(rows)} lines, not 41")
        worst = max(sphere_distance(*row) for row in rows)
        far = max(r for _, r, _ in rows)
        print(f"{engine}: the largest distance from the great circle is {worst:.3g} (bound {bound}); "
              f"the farthest from O {far:.3f}")
        if not worst <= bound or abs(far - (math.pi - 1)) > 0.01:
            sys.exit(f"example_sphere {engine}: {worst:.3g} from the great circle (bound {bound}), "
                     f"farthest {far:.3f} from O (the circle's farthest point is pi - 1)")


def dump_event(frame, event):
    """A dump's event as example_game prints it."""
    (kind, v), = event.items()
    number = lambda name: int(name.split()[1])
    bullet = number(v[0]) if kind == "hit" else 0
    asteroid = number(v[1]) if kind == "hit" else number(v) if kind == "crash" else 0
    value = v if kind in ("level", "over") else 0
    return f"frame {frame}: {kind} bullet {bullet} asteroid {asteroid} value {value}"


def check_game(build, source, work):
    """example_game's events, frame by frame, and its last score, lives and level are those of
    `noneuclid dump` with the same presses (tests/files/data/game_actions.txt), and there is a hit."""
    ours = run(f"{build}/example_game", 300).splitlines()
    dump = run(f"{build}/noneuclid", "dump", "--scene", "asteroids", "--frames", 300, "--actions",
               f"{source}/tests/files/data/game_actions.txt").splitlines()
    theirs = []
    for line in dump:
        frame = json.loads(line)
        theirs += [dump_event(frame["frame"], e) for e in frame.get("events", [])]
    last = json.loads(dump[-1])
    theirs.append(f"frame {last['frame']}: score {last['score']} lives {last['lives']} level {last['level']}")
    if ours != theirs:
        sys.exit("example_game's lines differ from the dump's:\n" + "\n".join(ours) + "\n-- the dump's:\n" +
                 "\n".join(theirs))
    hits = sum(" hit " in line for line in ours)
    print(f"{len(ours) - 1} events alike ({hits} hits); {ours[-1]}")
    if hits == 0:
        sys.exit("example_game hit nothing: the check would show little")


def close(a, b):
    """Numbers the dump prints with 9 significant digits: alike to within that."""
    return abs(a - b) <= 1e-8 * (1 + abs(a))


def check_python(build, source, work):
    """bodies.py reads, through ctypes, the bodies `noneuclid dump` lists for the same scene and
    frames: the same names and kinds in the same order, centres and facings alike to the 9 digits
    the dump prints."""
    frames = 30
    ours = [json.loads(line) for line in run(sys.executable, f"{source}/examples/bodies.py",
                                             f"{build}/libnoneuclid.so", "kiosk", frames).splitlines()]
    env = dict(os.environ)
    env.pop("LD_PRELOAD", None)  # (the sanitizers' runtimes, for Python: noneuclid has its own)
    last = json.loads(run(f"{build}/noneuclid", "dump", "--scene", "kiosk", "--frames", frames,
                          env=env).splitlines()[-1])
    theirs = last["bodies"]
    if [(b["name"], b["kind"]) for b in ours] != [(b["name"], b["kind"]) for b in theirs]:
        sys.exit(f"the bodies differ:\n{ours}\n-- the dump's:\n{theirs}")
    for a, b in zip(ours, theirs):
        if not (close(a["center"][0], b["center"][0]) and close(a["center"][1], b["center"][1]) and
                close(a["facing"], b["facing"])):
            sys.exit(f"body {a['name']}: {a} against the dump's {b['center']}, facing {b['facing']}")
    print(f"{len(ours)} bodies alike: {', '.join(b['name'] for b in ours)}")


def check_outside(build, source, work, flags=""):
    """The dev component installed into a scratch prefix, then examples/ configured and built as a
    project of its own against it (find_package): its C and game examples print what the tree's do."""
    prefix, tree = f"{work}/prefix", f"{work}/build"
    shutil.rmtree(work, ignore_errors=True)
    run("cmake", "--install", build, "--component", "dev", "--prefix", prefix)
    for root, _, files in os.walk(prefix):
        for f in files:
            if f.endswith(".cmake") and source in open(os.path.join(root, f)).read():
                sys.exit(f"{os.path.join(root, f)} names the source tree {source}")
    cxx, linker = (flags.split("|") + ["", ""])[:2]
    run("cmake", "-S", f"{source}/examples", "-B", tree, f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_BUILD_TYPE=Debug",
        f"-DCMAKE_CXX_FLAGS={cxx}", f"-DCMAKE_C_FLAGS={cxx}", f"-DCMAKE_EXE_LINKER_FLAGS={linker}")
    run("cmake", "--build", tree, "--target", "example_c", "example_game", "-j", "2")
    for args in (["example_c", "kiosk", 20, "64x48", "xrgb8888", "PICTURE"], ["example_game"]):
        outputs = []
        for where, side in ((tree, "outside"), (build, "inside")):
            picture = f"{work}/{side}-c.ppm"
            outputs.append(run(f"{where}/{args[0]}", *[picture if a == "PICTURE" else a for a in args[1:]]))
        if outputs[0] != outputs[1]:
            sys.exit(f"{args[0]} built outside prints\n{outputs[0]}\n-- and inside\n{outputs[1]}")
    same_pictures(build, f"{work}/outside-c.ppm", f"{work}/inside-c.ppm")
    print(f"built outside the tree against {prefix}: example_c and example_game print what the tree's do")


CHECKS = {"picture": check_picture, "c": check_c, "sphere": check_sphere, "game": check_game,
          "python": check_python, "outside": check_outside}

if __name__ == "__main__":
    if len(sys.argv) < 5 or sys.argv[1] not in CHECKS:
        sys.exit(f"usage: check_examples.py {'|'.join(CHECKS)} BUILD SOURCE WORK [FLAGS]")
    work = sys.argv[4]
    os.makedirs(work, exist_ok=True)
    CHECKS[sys.argv[1]](sys.argv[2], sys.argv[3], work, *sys.argv[5:])

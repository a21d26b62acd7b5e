#!/usr/bin/env bash
# Redraw the pictures in docs/images/ with the current program (the README shows them).
#   docs/images/regenerate.sh [NONEUCLID]  # builds the release preset if needed; needs python3
#
# kiosk.png      the kiosk scene after 120 frames (2 s), anti-aliased, with the HUD, 800x480
# curvature.png  the same scene and frame at K = -1, 0 and +1, side by side (three 400x400
#                renders joined by the few lines of Python below: no imaging library needed)
# textured.png   the textured scene (five textured bodies, one filled) at K = -1, 0 and +1;
#                textured-sweep.png the same at K = -1, -0.5, 0, 0.5 and 1
# game.png       the game at K = -1, played by game.actions (fire, key 1, turns, thrust)
# game-timelapse.png  attract mode playing the game for 30 s (a headless run, recorded), a
#                frame every 2 s over the last frame's grid
# kiosk-k1.png   the kiosk scene at K = +1 (the antipode is the rim), anti-aliased, 800x480
# fig17.png      the demo's figure 17: K swept from -1 to +1, the grid at each sampled K
# measure-triangle.png  the measure scene's triangle and its readings at K = -1, 0 and +1
# fig2.png, fig4.png  the demo's figures 2 (lines that start parallel) and 4 (a {7,3} tiling)
# projections-k1.png, projections-k-1.png  the kiosk scene in the five projections at K = +1
#                and -1 (equidistant, stereographic, gnomonic, orthographic, Lambert), 320x320 each
# earth.png      the earth scene about Greenwich at K = +1, with the HUD, 800x480 (docs/earth.md)
# earth-curvature.png  the same, stereographic, at K = +1, 0 and -1 (400x400 each)
# earth-zoom.png  zoom by curvature: the whole globe, 5000 km and 1500 km from Greenwich
# earth-projections.png  the earth scene at K = +1 in the five projections, 320x320 each
# earth-tissot.png  the same with Tissot's circles (--tissot) about 45 N 10 E
# game-earth.png  attract mode playing the game over the Earth (tests/files/data/earth_game.toml)
#                for 10 s, 800x480 (docs/game.md)
# uneven-lens.png  the lens scene in its chart and in the inhabitant's view, 400x400 each
#                (docs/uneven.md); uneven-hills.png the hills scene's chart at K = -0.6 and 0,
#                and its inhabitant's view at 0; uneven-gravity.png the game around a mass
#                (game.actions), chart view, 800x480; uneven-triangle.png a triangle's reading about a
#                mass (tests/files/data/bumps.toml), chart view, 800x480
# space.png, space-map.png  the space scene after 1 s in the inhabitant's view and in the map at
#                K = -1, 0 and +1, 400x400 each (docs/space.md); honeycombs.png the order-5 cubic
#                honeycomb at K = -1 (it fits) and -0.7, the 8-cell at K = +0.6, 400x400 each
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
nc=${1:-build/release/noneuclid}
if [ ! -x "$nc" ]; then
    cmake --preset release >/dev/null && cmake --build --preset release --target noneuclid -j 2 >/dev/null
fi
"$nc" render --scene kiosk --frames 120 --aa --hud --size 800x480 --out docs/images/kiosk.png
"$nc" render --scene kiosk --frames 120 --aa --size 800x480 --curvature 1 --out docs/images/kiosk-k1.png
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$nc" demo --no-hud --out-dir "$tmp/demo" >/dev/null
cp "$tmp/demo/fig17.png" "$tmp/demo/fig2.png" "$tmp/demo/fig4.png" docs/images/
"$nc" render --actions docs/images/game.actions --frames 570 --out docs/images/game.png
"$nc" run --display png --scene asteroids --attract 0.5 --frames 1800 --aa --scores none --record "$tmp/game.rec" \
    --screenshot "$tmp/game-last.png"
"$nc" render --actions "$tmp/game.rec" --timelapse 120 --out docs/images/game-timelapse.png
for k in -1 0 1; do
    "$nc" render --scene kiosk --frames 120 --aa --hud --size 400x400 --curvature "$k" --out "$tmp/k$k.png"
done
cat > "$tmp/join.py" <<'PY'
# Join 8-bit RGB PNGs of the same height left to right, with a 4-px gap.
import struct, sys, zlib

def read(path):
    data = open(path, 'rb').read()
    pos, idat = 8, b''
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b'IHDR':
            w, h, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            assert (depth, colour, interlace) == (8, 2, 0), path + ': not 8-bit RGB'
        elif kind == b'IDAT':
            idat += body
    raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b, c = prev[i], prev[i - 3] if i >= 3 else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, rows

images = [read(p) for p in sys.argv[1:-1]]
h, gap = images[0][1], bytes(3 * 4)
assert all(img[1] == h for img in images)
width = sum(img[0] for img in images) + 4 * (len(images) - 1)
raw = b''.join(b'\0' + gap.join(img[2][y] for img in images) for y in range(h))
def chunk(kind, body):
    return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))
with open(sys.argv[-1], 'wb') as out:
    out.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, h, 8, 2, 0, 0, 0))
              + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
print('regenerate.sh: wrote', sys.argv[-1], f'({width}x{h})')
PY
python3 "$tmp/join.py" "$tmp/k-1.png" "$tmp/k0.png" "$tmp/k1.png" docs/images/curvature.png
for k in -1 1; do
    panels=()
    for p in equidistant stereographic gnomonic orthographic lambert; do
        "$nc" render --scene kiosk --frames 120 --aa --size 320x320 --curvature "$k" --projection "$p" --out "$tmp/$p$k.png"
        panels+=("$tmp/$p$k.png")
    done
    python3 "$tmp/join.py" "${panels[@]}" "docs/images/projections-k$k.png"
done
# The textured scene at K = -1, 0, +1, and through the sweep: K = -1, -0.5, 0, 0.5, 1.
for k in -1 -0.5 0 0.5 1; do
    "$nc" render --scene textured --frames 60 --aa --size 400x400 --curvature "$k" --out "$tmp/t$k.png"
done
python3 "$tmp/join.py" "$tmp/t-1.png" "$tmp/t0.png" "$tmp/t1.png" docs/images/textured.png
python3 "$tmp/join.py" "$tmp/t-1.png" "$tmp/t-0.5.png" "$tmp/t0.png" "$tmp/t0.5.png" "$tmp/t1.png" docs/images/textured-sweep.png
# The measure scene's triangle at K = -1, 0, +1, its readings beside it.
for k in -1 0 1; do
    "$nc" render --scene measure --frames 0 --aa --font builtin --size 560x360 --curvature "$k" --out "$tmp/m$k.png"
done
python3 "$tmp/join.py" "$tmp/m-1.png" "$tmp/m0.png" "$tmp/m1.png" docs/images/measure-triangle.png
# The Earth (docs/earth.md): about Greenwich, at K = +1; K = +1, 0, -1 (stereographic); zoomed by
# curvature; the five projections.
"$nc" render --scene earth --centre 51.5,0 --curvature 1 --frames 0 --aa --hud --size 800x480 --out docs/images/earth.png
for k in 1 0 -1; do
    "$nc" render --scene earth --frames 0 --aa --size 400x400 --curvature "$k" --projection stereographic --out "$tmp/e$k.png"
done
python3 "$tmp/join.py" "$tmp/e1.png" "$tmp/e0.png" "$tmp/e-1.png" docs/images/earth-curvature.png
for v in 20015 5000 1500; do
    "$nc" render --scene earth --view "$v" --frames 0 --aa --size 400x400 --out "$tmp/v$v.png"
done
python3 "$tmp/join.py" "$tmp/v20015.png" "$tmp/v5000.png" "$tmp/v1500.png" docs/images/earth-zoom.png
panels=()
for p in equidistant stereographic gnomonic orthographic lambert; do
    "$nc" render --scene earth --frames 0 --aa --size 320x320 --projection "$p" --out "$tmp/ep$p.png"
    panels+=("$tmp/ep$p.png")
done
python3 "$tmp/join.py" "${panels[@]}" docs/images/earth-projections.png
# Tissot's indicatrices (--tissot) about 45 N 10 E in the five projections.
panels=()
for p in equidistant stereographic gnomonic orthographic lambert; do
    "$nc" render --scene earth --tissot --centre 45,10 --frames 0 --aa --size 320x320 --projection "$p" --out "$tmp/et$p.png"
    panels+=("$tmp/et$p.png")
done
python3 "$tmp/join.py" "${panels[@]}" docs/images/earth-tissot.png
"$nc" run --display png --scene tests/files/data/earth_game.toml --attract 0.5 --frames 600 --aa --scores none \
    --size 800x480 --screenshot docs/images/game-earth.png
# Uneven worlds (docs/uneven.md).
for p in stereographic equidistant; do
    "$nc" render --scene lens --frames 60 --aa --size 400x400 --projection "$p" --out "$tmp/lens-$p.png"
done
python3 "$tmp/join.py" "$tmp/lens-stereographic.png" "$tmp/lens-equidistant.png" docs/images/uneven-lens.png
"$nc" render --scene hills --frames 60 --aa --size 400x400 --projection stereographic --curvature -0.6 --out "$tmp/h1.png"
"$nc" render --scene hills --frames 60 --aa --size 400x400 --projection stereographic --out "$tmp/h2.png"
"$nc" render --scene hills --frames 60 --aa --size 400x400 --out "$tmp/h3.png"
python3 "$tmp/join.py" "$tmp/h1.png" "$tmp/h2.png" "$tmp/h3.png" docs/images/uneven-hills.png
sed 's/^scene .*/scene gravity/' docs/images/game.actions > "$tmp/gravity.actions"
"$nc" render --actions "$tmp/gravity.actions" --frames 570 --projection stereographic --out docs/images/uneven-gravity.png
"$nc" render --scene tests/files/data/bumps.toml --projection stereographic --hud --aa --frames 10 --out docs/images/uneven-triangle.png
# Three dimensions (docs/space.md): the space scene in both views at K = -1, 0, +1; honeycombs.
for p in equidistant stereographic; do
    for k in -1 0 1; do
        "$nc" render --scene space --frames 60 --aa --size 400x400 --projection "$p" --curvature "$k" --out "$tmp/s$p$k.png"
    done
done
python3 "$tmp/join.py" "$tmp/sequidistant-1.png" "$tmp/sequidistant0.png" "$tmp/sequidistant1.png" docs/images/space.png
python3 "$tmp/join.py" "$tmp/sstereographic-1.png" "$tmp/sstereographic0.png" "$tmp/sstereographic1.png" docs/images/space-map.png
"$nc" render --scene order-5-cubic --frames 0 --aa --size 400x400 --out "$tmp/c1.png"
"$nc" render --scene order-5-cubic --frames 0 --aa --size 400x400 --curvature -0.7 --out "$tmp/c2.png"
"$nc" render --scene 8-cell --frames 0 --aa --size 400x400 --curvature 0.6 --out "$tmp/c3.png"
python3 "$tmp/join.py" "$tmp/c1.png" "$tmp/c2.png" "$tmp/c3.png" docs/images/honeycombs.png

"""Draws the plugin's menu icons (32 x 32 PNG; Debian's Qt has no SVG image plugin unless
libqt5svg5 is installed, so the icons are bitmaps). Run with /usr/bin/python3 (Pillow comes with
python3-matplotlib) from this folder after changing a drawing:

    /usr/bin/python3 make_icons.py
"""
import math

from PIL import Image, ImageDraw

SCALE = 4  # drawn at 128 x 128, then reduced: smooth edges
BLUE, LIGHT, PALE, RED, ORANGE, PURPLE = ("#3b6fb6", "#6aaef0", "#a9c8ee", "#d0342c", "#e08a1e",
                                          "#7a3fb0")


def canvas():
    image = Image.new("RGBA", (32 * SCALE, 32 * SCALE), (0, 0, 0, 0))
    return image, ImageDraw.Draw(image)


def s(*values):
    return [v * SCALE for v in values]


def curve(draw, points, color, width):
    draw.line([tuple(s(*p)) for p in points], fill=color, width=round(width * SCALE), joint="curve")


def arrow(draw, start, end, color, width=2.5):
    curve(draw, [start, end], color, width)
    angle = math.atan2(end[1] - start[1], end[0] - start[0])
    for side in (-1, 1):
        a = angle + math.pi + side * 0.7
        curve(draw, [end, (end[0] + 5 * math.cos(a), end[1] + 5 * math.sin(a))], color, width)


def boosted_surface(draw):  # circles of a boosted family, growing along the boost
    for (cx, rx, ry, color) in ((8, 3, 7, BLUE), (16, 4, 10, "#4a8fd8"), (25, 5, 13, LIGHT)):
        draw.ellipse(s(cx - rx, 16 - ry, cx + rx, 16 + ry), outline=color, width=2 * SCALE)


def sample(f, n=40):
    return [f(i / n) for i in range(n + 1)]


def point_pair_deformation(draw):  # a warped mesh and a generator arrow
    for y0, color in ((24, BLUE), (29, LIGHT)):
        curve(draw, sample(lambda t: (3 + 26 * t, y0 - (8 if y0 == 24 else 7) *
                                      math.exp(-((t - 0.5) / 0.18) ** 2))), color, 2)
    arrow(draw, (16, 12), (16, 3), RED)


def dipole_field(draw):  # field loops of a dipole and its generator arrow
    for r, color in ((7, LIGHT), (4, BLUE)):
        draw.ellipse(s(16 - 2 * r, 16 - r, 16, 16 + r), outline=color, width=2 * SCALE)
        draw.ellipse(s(16, 16 - r, 16 + 2 * r, 16 + r), outline=color, width=2 * SCALE)
    arrow(draw, (8, 16), (25, 16), RED)


def hopf_fibration(draw):  # two linked fibers
    draw.ellipse(s(4, 6, 20, 22), outline=BLUE, width=3 * SCALE)
    draw.ellipse(s(12, 10, 28, 26), outline=ORANGE, width=3 * SCALE)
    draw.arc(s(4, 6, 20, 22), start=270, end=330, fill=BLUE, width=3 * SCALE)


def curvature_patch(draw):  # a bent patch and its normal
    top = sample(lambda t: (3 + 26 * t, 22 - 8 * math.sin(math.pi * t)))
    bottom = sample(lambda t: (7 + 18 * t, 28 - 6 * math.sin(math.pi * t)))
    outline = top + bottom[::-1]
    draw.polygon([tuple(s(*p)) for p in outline], fill=PALE, outline=BLUE)
    curve(draw, outline + [outline[0]], BLUE, 2)
    arrow(draw, (16, 15), (16, 4), RED)


def conformal_orbit(draw):  # a trefoil orbit
    curve(draw, sample(lambda t: (16 + 6 * (math.sin(2 * math.pi * t) + 2 * math.sin(4 * math.pi * t)) / 1.4,
                                  16 + 6 * (math.cos(2 * math.pi * t) - 2 * math.cos(4 * math.pi * t)) / 1.4),
                       120), PURPLE, 2)


ICONS = {"BoostedSurface": boosted_surface, "PointPairDeformation": point_pair_deformation,
         "DipoleField": dipole_field, "HopfFibration": hopf_fibration,
         "CurvaturePatch": curvature_patch, "ConformalOrbit": conformal_orbit}

if __name__ == "__main__":
    for name, draw_icon in ICONS.items():
        image, draw = canvas()
        draw_icon(draw)
        image.resize((32, 32), Image.LANCZOS).save(name + ".png")

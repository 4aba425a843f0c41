"""Assemble rendered figures into one montage with their figure numbers (the README's docs/gallery.png).

    python3 render_gallery.py --output-dir gallery
    python3 make_gallery_montage.py --gallery-dir gallery --output ../docs/gallery.png

Each row of ROWS is scaled to one height so that it fills the montage's width (a wide figure gets
a wide cell, not a shrunken one), after trimming its white border; every figure gets its number
("Fig 11") above its top left. The
PNGs are those render_gallery.py writes (one per figure script, named after the script).
"""
import argparse
import os
import sys

from vtkmodules.vtkImagingCore import (
    vtkExtractVOI,
    vtkImageChangeInformation,
    vtkImageResize,
    vtkImageSincInterpolator,
)
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkRenderingCore import vtkActor2D, vtkImageMapper, vtkTextActor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gallery_common as gc  # noqa: E402
import render_gallery  # noqa: E402

# Rows of paper figure numbers, each row's aspect ratios summing to about 3.5-5 (rows neither
# thin strips nor too tall): one picture or more per class of the project (surface source: 2, 3;
# Hopf construction and fibration: 4, 5; curvature patch: 7, 10; deformation filter: 11; dipole
# field: 14).
ROWS = ((2, 4), (7, 5), (11, 10), (14, 3))
WIDTH = 1600  # shown at about half that width in a README: the labels stay readable
GAP = 12  # pixels between cells (white)
LABEL_SIZE = 40
MARGIN = 16  # white pixels kept around a figure's content
LABEL_BAND = 52  # pixels above each row for the figure numbers


def figure_path(gallery_dir, number):
    """The PNG render_gallery.py writes for paper figure `number`."""
    prefix = "fig%d_" % number
    names = [name for name in render_gallery.FIGURES if name.startswith(prefix)]
    if len(names) != 1:
        raise ValueError("no figure script for Fig %d" % number)
    path = os.path.join(gallery_dir, names[0] + ".png")
    if not os.path.isfile(path):
        raise FileNotFoundError("%s is missing: run render_gallery.py first" % path)
    return path


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader


def trimmed(reader, margin=MARGIN):
    """The image of `reader` without its white border (but `margin` pixels of it): the montage
    shows the figures, not their empty space. Scans the RGB bytes row by row (no numpy here)."""
    image = reader.GetOutput()
    width, height = image.GetDimensions()[:2]
    components = image.GetNumberOfScalarComponents()
    pixels = bytes(memoryview(image.GetPointData().GetScalars()))
    row_bytes = width * components
    rows, left, right = [], width, 0
    for y in range(height):
        row = pixels[y * row_bytes:(y + 1) * row_bytes]
        # Whole pixels only: strip white pixels, not single white channels.
        lead = (len(row) - len(row.lstrip(b"\xff"))) // components
        trail = (len(row) - len(row.rstrip(b"\xff"))) // components
        if lead < width:
            rows.append(y)
            left, right = min(left, lead), max(right, width - 1 - trail)
    extract = vtkExtractVOI()
    extract.SetInputConnection(reader.GetOutputPort())
    if rows:
        extract.SetVOI(max(left - margin, 0), min(right + margin, width - 1),
                       max(rows[0] - margin, 0), min(rows[-1] + margin, height - 1), 0, 0)
    origin = vtkImageChangeInformation()  # extent from (0, 0): the mapper draws from there
    origin.SetInputConnection(extract.GetOutputPort())
    origin.SetOutputExtentStart(0, 0, 0)
    origin.Update()
    origin.pipeline = extract
    return origin


def resized(reader, size):
    """The image of `reader` resampled to `size` with an antialiasing windowed sinc (no moire on
    thin lines when shrinking)."""
    interpolator = vtkImageSincInterpolator()
    interpolator.AntialiasingOn()
    resize = vtkImageResize()
    resize.SetInputConnection(reader.GetOutputPort())
    resize.SetResizeMethodToOutputDimensions()
    resize.SetOutputDimensions(size[0], size[1], 1)
    resize.SetInterpolator(interpolator)
    resize.Update()
    return resize


def layout(aspects_by_row, width, gap, band):
    """Cells (x, y, w, h) of the images in pixels from the bottom left, and the montage's height:
    each row has one height, chosen so that its cells and gaps span `width`, and a `band` above it
    for the labels."""
    rows = []
    for aspects in aspects_by_row:
        height = (width - gap * (len(aspects) + 1)) / sum(aspects)
        rows.append((int(round(height)), aspects))
    total = gap + sum(band + height + gap for height, _ in rows)
    cells = []
    top = total - gap
    for height, aspects in rows:
        top -= band
        x = gap
        for aspect in aspects:
            w = int(round(aspect * height))
            cells.append((x, top - height, w, height))
            x += w + gap
        top -= height + gap
    return cells, total


def montage_renderer(images, cells, labels):
    """A renderer showing each image at its cell with its label above the cell's left end."""
    renderer = gc.new_renderer()
    for image, (x, y, w, h), text in zip(images, cells, labels):
        mapper = vtkImageMapper()
        mapper.SetInputConnection(image.GetOutputPort())
        mapper.SetColorWindow(255.0)  # show the 8-bit pixels as they are
        mapper.SetColorLevel(127.5)
        actor = vtkActor2D()
        actor.SetMapper(mapper)
        actor.SetPosition(x, y)
        actor.pipeline = image
        renderer.AddActor2D(actor)
        label = vtkTextActor()
        label.SetInput(text)
        label.SetPosition(x, y + h + 4)
        prop = label.GetTextProperty()
        prop.SetFontSize(LABEL_SIZE)
        prop.BoldOn()
        prop.SetColor(0.1, 0.1, 0.1)
        prop.SetVerticalJustificationToBottom()
        renderer.AddActor2D(label)
    return renderer


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gallery-dir", default="gallery",
                        help="where render_gallery.py wrote the figures (default: %(default)s)")
    parser.add_argument("--output", default="gallery.png", help="montage PNG to write")
    parser.add_argument("--width", type=int, default=WIDTH, help="montage width in pixels")
    args = parser.parse_args(argv)

    readers = [[trimmed(read_png(figure_path(args.gallery_dir, n))) for n in row] for row in ROWS]
    aspects = [[r.GetOutput().GetDimensions()[0] / r.GetOutput().GetDimensions()[1] for r in row]
               for row in readers]
    cells, height = layout(aspects, args.width, GAP, LABEL_BAND)
    images = [resized(reader, cell[2:]) for reader, cell in
              zip([r for row in readers for r in row], cells)]
    labels = ["Fig %d" % n for row in ROWS for n in row]
    renderer = montage_renderer(images, cells, labels)
    # The 2D actors sit at pixel positions: no camera to fit.
    path = gc.render_to_png(renderer, args.output, (args.width, int(round(height))))
    print(path)
    return path


if __name__ == "__main__":
    main()

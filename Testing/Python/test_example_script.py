"""Runs one script of Examples/ and checks the PNGs it writes.

    python3 test_example_script.py <Examples/script.py> <output directory>

A figure script gets --output <dir>/<name>.png --size 320 240; render_gallery.py gets
--output-dir <dir>. Every path the script prints must be a PNG of that size that is not blank:
it shows something besides the white background, in more than one colour. After render_gallery.py,
make_gallery_montage.py assembles those PNGs into a montage, which must not be blank either.
"""
import os
import shutil
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

SIZE = (320, 240)


def check_png(path, expected_size):
    """Return a list of problems with the PNG at `path` (empty if it looks like a picture)."""
    if not os.path.isfile(path):
        return ["%s was not written" % path]
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    problems = []
    if expected_size and image.GetDimensions()[:2] != expected_size:
        problems.append("%s is %s, not %s" % (path, image.GetDimensions()[:2], expected_size))
    scalars = image.GetPointData().GetScalars()
    if scalars is None or scalars.GetNumberOfComponents() < 3:
        return problems + ["%s has no RGB pixels" % path]
    # Not one colour: some channel varies a lot.
    spread = max(scalars.GetRange(c)[1] - scalars.GetRange(c)[0] for c in range(3))
    if spread < 100:
        problems.append("%s is nearly one colour (channel spread %g)" % (path, spread))
    # Something drawn: at least 1% of the pixels differ from the white background.
    pixels = scalars.GetNumberOfTuples()
    drawn = sum(1 for i in range(pixels) if min(scalars.GetTuple3(i)) < 240)
    if drawn < 0.01 * pixels:
        problems.append("%s is nearly blank (%d of %d pixels drawn)" % (path, drawn, pixels))
    return problems


def main():
    script, output_dir = sys.argv[1], sys.argv[2]
    name = os.path.splitext(os.path.basename(script))[0]
    size_args = ["--size", str(SIZE[0]), str(SIZE[1])]
    if name == "render_gallery":
        gallery_dir = os.path.join(output_dir, name)
        shutil.rmtree(gallery_dir, ignore_errors=True)  # PNGs of an earlier run must not count
        arguments = ["--output-dir", gallery_dir] + size_args
    else:
        expected = os.path.join(output_dir, name + ".png")
        if os.path.exists(expected):
            os.remove(expected)  # a PNG left by an earlier run must not count
        arguments = ["--output", expected] + size_args
    run = subprocess.run([sys.executable, script] + arguments, capture_output=True, text=True)
    sys.stdout.write(run.stdout)
    sys.stderr.write(run.stderr)
    if run.returncode != 0:
        print("FAIL: %s exited with %d" % (script, run.returncode))
        return 1

    paths = [line.strip() for line in run.stdout.splitlines() if line.strip().endswith(".png")]
    if not paths:
        print("FAIL: %s printed no PNG path" % script)
        return 1
    if name == "render_gallery":
        sys.path.insert(0, os.path.dirname(os.path.abspath(script)))
        import render_gallery
        if len(paths) != len(render_gallery.FIGURES):
            print("FAIL: %d PNGs for %d figures" % (len(paths), len(render_gallery.FIGURES)))
            return 1
        montage = os.path.join(output_dir, "montage.png")
        if os.path.exists(montage):
            os.remove(montage)
        run = subprocess.run([sys.executable, os.path.join(os.path.dirname(script),
                                                           "make_gallery_montage.py"),
                              "--gallery-dir", gallery_dir, "--output", montage, "--width", "900"],
                             capture_output=True, text=True)
        sys.stdout.write(run.stdout)
        sys.stderr.write(run.stderr)
        montage_problems = check_png(montage, None)
        if run.returncode != 0 or montage_problems:
            print("FAIL: make_gallery_montage.py exited with %d; %s"
                  % (run.returncode, "; ".join(montage_problems)))
            return 1
    elif paths != [os.path.abspath(expected)]:
        print("FAIL: printed %s, expected %s" % (paths, os.path.abspath(expected)))
        return 1
    problems = [p for path in paths for p in check_png(path, SIZE)]
    for problem in problems:
        print("FAIL: " + problem)
    if not problems:
        print("OK: " + ", ".join(paths))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

"""Render every figure script of this folder into one directory and print the paths of the PNGs.

    python3 render_gallery.py --output-dir gallery [--size 900 700]

To add a figure, write a script with a main(argv) that takes --output and --size (see
gallery_common.parse_args) and add its module name to FIGURES.
"""
import argparse
import os
import sys

FIGURES = [
    "fig1_boosted_circle",
    "fig2_boosted_surfaces",
    "fig3_horn",
    "fig4_hopf_construction",
    "fig5_hopf_fibration",
    "fig6_bent_line",
    "fig7_translated_tangents",
    "fig8_osculating_circles",
    "fig9_control_point_patches",
    "fig10_patch_assemblies",
    "fig11_deformation",
    "fig12_bilinear_patches",
    "fig13_dipole",
    "fig14_dipole_methods",
    "twisted_bar",
    "boost_versus_twist",
    "torus_knots_and_orbits",
]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default="gallery", help="where the PNGs go")
    parser.add_argument("--size", nargs=2, type=int, metavar=("W", "H"),
                        help="image size for every figure (default: each figure's own)")
    args = parser.parse_args(argv)

    # The figure scripts and gallery_common sit next to this file.
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    paths = []
    for name in FIGURES:
        figure = __import__(name)
        figure_args = ["--output", os.path.join(args.output_dir, name + ".png")]
        if args.size:
            figure_args += ["--size"] + [str(n) for n in args.size]
        paths.append(figure.main(figure_args))  # each main prints its path
    return paths


if __name__ == "__main__":
    main()

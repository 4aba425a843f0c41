#!/usr/bin/env bash
# ParaView.GUI.Menus: the ParaView GUI plays test_gui_menus.xml (QtTesting events: each proxy from
# its Sources/Filters > Boosted Surfaces menu action, then Apply) with the plugin found through
# PV_PLUGIN_PATH alone, and compares its render view (300 x 300 while testing) with the baseline.
# A missing or different image is written to <output dir>; copy it to the baseline to accept it.
# Usage: test_gui.sh <paraview> <plugin folder> <baseline png> <output dir> [<events xml>]
# (default events: test_gui_menus.xml; ParaView.GUI.Handles plays test_gui_handles.xml)
set -euo pipefail
paraview="$1"
plugin_dir="$2"
baseline="$3"
output_dir="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
events="${5:-$here/test_gui_menus.xml}"

missing=0
if [ ! -f "$baseline" ]; then
  # ParaView writes the image where the baseline should be: let that be the output folder.
  missing=1
  baseline="$output_dir/$(basename "$baseline")"
  rm -f "$baseline"
fi
# --dr: no user settings; --test-threshold is an integer there: 0 asks for the exact image (the
# project's threshold, 0.05 of vtkImageDifference's thresholded error, lies below 1).
PV_PLUGIN_PATH="$plugin_dir" "$paraview" --dr --test-script="$events" \
  --test-baseline="$baseline" --test-directory="$output_dir" --test-threshold=0 --exit
if [ "$missing" -eq 1 ]; then
  echo "no baseline; the rendered image is $baseline" >&2
  exit 1
fi

#!/usr/bin/env bash
# The README's first command: installs/builds (scripts/setup.sh), then segments MRPT's sample
# Velodyne VLP-16 scan (mrpt-common's datasets/test_velodyne_VLP16.rawlog) and writes into
# ./travel-out/:
#   test_velodyne_VLP16_travel.rawlog  the input plus Velodyne1_SCAN_{ground,nonground,outlier}
#   test_velodyne_VLP16_000000.png     bird's-eye view (ground green, non-ground red, outlier blue)
#   test_velodyne_VLP16_000000.ply     the same colours in 3-D (CloudCompare, MeshLab)
#   test_velodyne_VLP16.csv            per-frame counts and timings
set -euo pipefail

ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT_DIR"
OUT_DIR="$ROOT_DIR/travel-out"
NAME=test_velodyne_VLP16

# Only what the demo runs: the app and the plugin module for RawLogViewer (the test command
# builds the rest).
"$ROOT_DIR/scripts/setup.sh" --demo --target travel-rawlog --target travel_mrpt_plugin

dataset=""
for dir in /usr/share/mrpt/datasets /usr/local/share/mrpt/datasets; do
  if [[ -f "$dir/$NAME.rawlog" ]]; then dataset="$dir/$NAME.rawlog"; break; fi
done
if [[ -z "$dataset" ]]; then
  dataset="$(dpkg -L mrpt-common 2>/dev/null | grep "/$NAME.rawlog\$" | head -n 1 || true)"
fi
[[ -n "$dataset" && -f "$dataset" ]] || {
  echo "[run-demo] error: $NAME.rawlog not found (install mrpt-common)" >&2
  exit 1
}

mkdir -p "$OUT_DIR"
# The sensor preset only: the floor height (2.24 m here) is estimated from the scan
# (sensor_height: auto) and printed; the seed search then reaches the first ground ring.
cmd=(build/apps/travel-rawlog
  -i "$dataset"
  -o "travel-out/${NAME}_travel.rawlog"
  --png "travel-out/$NAME"
  --csv "travel-out/$NAME.csv"
  --preset vlp16 --set sensor_height=auto)
echo "[run-demo] running: ${cmd[*]}"
"${cmd[@]}"

echo "[run-demo] outputs in $OUT_DIR:"
ls -1 "$OUT_DIR" | sed "s|^|  travel-out/|"
echo "[run-demo] view: travel-out/${NAME}_000000.png; 3-D: travel-out/${NAME}_000000.ply;"
echo "[run-demo] rawlog in colour (package mrpt-apps): RawLogViewer -l $ROOT_DIR/build/mrpt_plugin/libtravel_mrpt_plugin.so travel-out/${NAME}_travel.rawlog"

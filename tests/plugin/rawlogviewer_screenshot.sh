#!/bin/sh
# Run inside a virtual X server (xvfb-run): open RawLogViewer with the plugin on RAWLOG, hide the
# "Tip of the day" dialog, enlarge the main window and screenshot the screen to OUT.png.
# Needs xdotool, xwd and netpbm (xwdtopnm, pnmtopng).
#   rawlogviewer_screenshot.sh RAWLOGVIEWER PLUGIN OUT.png RAWLOG
# (Selecting a tree entry by a synthetic click did not work under Xvfb without a window manager;
# the README's picture of the coloured 3-D view was taken by hand.)
set -eu
viewer=$1 plugin=$2 out=$3 rawlog=$4
"$viewer" -l "$plugin" "$rawlog" >/dev/null 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
sleep 6
for w in $(xdotool search --onlyvisible --name "Tip of the Day" 2>/dev/null || true); do
    xdotool windowunmap "$w" || true
done
for w in $(xdotool search --onlyvisible --name "RawlogViewer" 2>/dev/null || true); do
    xdotool windowsize "$w" 1600 1000 || true
done
sleep 2
xwd -root -silent | xwdtopnm 2>/dev/null | pnmtopng > "$out"
echo "screenshot: $out"

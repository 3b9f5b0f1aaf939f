#!/usr/bin/env bash
# Runs one UI test executable: on the current display if there is one, else under a virtual X
# server (xvfb-run), with the xcb platform (Qt's offscreen platform cannot host a QOpenGLWidget).
set -euo pipefail
export QT_QPA_PLATFORM=xcb
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"

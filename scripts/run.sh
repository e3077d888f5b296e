#!/usr/bin/env bash
# First README command: set up, build, and launch the app on the default scene.
# With no display it renders the default scene headlessly into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release
exec build/release/app/airlight "$@"

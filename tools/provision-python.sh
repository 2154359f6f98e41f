#!/usr/bin/env bash
# Creates the project's Python venv (.venv) with the pinned GDScript linter and formatter.
source "$(dirname "$0")/common.sh"

requirements="$PROJECT_ROOT/tools/requirements.txt"
venv="$PROJECT_ROOT/.venv"
stamp="$venv/.requirements-$(sha256sum "$requirements" | cut -c1-12)"
[ -f "$stamp" ] && exit 0
log "creating the Python tools venv in $venv"
rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/pip" install -q --disable-pip-version-check -r "$requirements"
touch "$venv/.gdignore" "$stamp"
